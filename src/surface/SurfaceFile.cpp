#include "surface/SurfaceFile.hpp"

#include "core/Error.hpp"
#include "io/AtomicFile.hpp"
#include "surface/VtkConversion.hpp"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace poro {

void writeSurface(const TriangleSurface& surface, const std::filesystem::path& file) {
  const std::filesystem::path temporary = temporarySibling(file);
  // Create it ourselves first: a missing or read-only directory then gets the OS's reason, which VTK does not give.
  if (!std::ofstream(temporary))
    throw OutputError(file.string() + ": cannot create file (" + std::strerror(errno) + ")");
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(toPolyData(surface));
  writer->SetFileName(temporary.c_str());
  writer->SetHeaderTypeToUInt64();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(1); // half the time of the default level for 2 % more bytes
  if (!writer->Write() || writer->GetErrorCode() != vtkErrorCode::NoError) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw OutputError(file.string() + ": cannot write VTK file (" +
                      vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode()) + ")");
  }
  commitTemporaryFile(temporary, file);
}

TriangleSurface readSurface(const std::filesystem::path& file) {
  if (!std::ifstream(file))
    throw InputError(file.string() + ": cannot open (" + std::strerror(errno) + ")");
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  if (reader->GetErrorCode() != vtkErrorCode::NoError || !poly || !poly->GetPoints())
    throw InputError(file.string() + ": not a readable VTK PolyData file");
  if (poly->GetNumberOfVerts() + poly->GetNumberOfLines() + poly->GetNumberOfStrips() > 0)
    throw InputError(file.string() + ": expected triangles only, got vertices, lines or strips");
  TriangleSurface surface;
  const vtkIdType n = poly->GetNumberOfPoints();
  surface.points.resize(static_cast<std::size_t>(n));
  for (vtkIdType p = 0; p < n; ++p) poly->GetPoint(p, surface.points[static_cast<std::size_t>(p)].data());
  vtkCellArray* polys = poly->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  while (polys->GetNextCell(ids)) {
    if (ids->GetNumberOfIds() != 3)
      throw InputError(file.string() + ": expected triangles only, got a polygon of " +
                       std::to_string(ids->GetNumberOfIds()) + " points");
    surface.triangles.push_back({static_cast<Index>(ids->GetId(0)), static_cast<Index>(ids->GetId(1)),
                                 static_cast<Index>(ids->GetId(2))});
  }
  vtkPointData* data = poly->GetPointData();
  for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = data->GetArray(a);
    if (!array || !array->GetName()) continue;
    TriangleSurface::Field field{array->GetName(), array->GetNumberOfComponents(), {}};
    field.values.reserve(static_cast<std::size_t>(n * field.components));
    for (vtkIdType p = 0; p < n; ++p)
      for (int c = 0; c < field.components; ++c) field.values.push_back(array->GetComponent(p, c));
    surface.fields.push_back(std::move(field));
  }
  return surface;
}

} // namespace poro
