#include "surface/VtkConversion.hpp"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

namespace poro {

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleSurface& surface) {
  const auto n = static_cast<vtkIdType>(surface.points.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  for (vtkIdType p = 0; p < n; ++p) points->SetPoint(p, surface.points[static_cast<std::size_t>(p)].data());

  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(surface.triangles.size()) + 1);
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(surface.triangles.size()));
  for (std::size_t t = 0; t <= surface.triangles.size(); ++t) offsets->SetValue(static_cast<vtkIdType>(t), 3 * static_cast<vtkIdType>(t));
  for (std::size_t t = 0; t < surface.triangles.size(); ++t)
    for (std::size_t c = 0; c < 3; ++c) connectivity->SetValue(static_cast<vtkIdType>(3 * t + c), surface.triangles[t][c]);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  bool scalarsSet = false;
  for (const TriangleSurface::Field& f : surface.fields) {
    vtkNew<vtkFloatArray> values;
    values->SetName(f.name.c_str());
    values->SetNumberOfComponents(f.components);
    values->SetNumberOfTuples(n);
    for (std::size_t k = 0; k < f.values.size(); ++k) values->SetValue(static_cast<vtkIdType>(k), static_cast<float>(f.values[k]));
    poly->GetPointData()->AddArray(values);
    if (f.components == 3) poly->GetPointData()->SetActiveVectors(f.name.c_str());
    if (f.components == 1 && !scalarsSet) poly->GetPointData()->SetActiveScalars(f.name.c_str());
    scalarsSet = scalarsSet || f.components == 1;
  }
  return poly;
}

vtkSmartPointer<vtkImageData> toImageData(const ScalarGrid& grid) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetOrigin(grid.origin.x(), grid.origin.y(), grid.origin.z());
  image->SetSpacing(grid.spacing, grid.spacing, grid.spacing);
  image->SetDimensions(static_cast<int>(grid.dims[0]), static_cast<int>(grid.dims[1]), static_cast<int>(grid.dims[2]));
  vtkNew<vtkFloatArray> values;
  values->SetName("c");
  values->SetArray(const_cast<float*>(grid.values.data()), static_cast<vtkIdType>(grid.points()), 1);
  image->GetPointData()->SetScalars(values);
  return image;
}

} // namespace poro
