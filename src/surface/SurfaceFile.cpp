#include "surface/SurfaceFile.hpp"

#include "core/Error.hpp"
#include "io/AtomicFile.hpp"
#include "surface/VtkConversion.hpp"

#include <vtkErrorCode.h>
#include <vtkNew.h>
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

} // namespace poro
