#include "render/ClipCap.hpp"

#include "surface/VtkConversion.hpp"

#include <vtkCellArray.h>
#include <vtkClipPolyData.h>
#include <vtkCutter.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkTriangleFilter.h>

namespace poro {

TriangleSurface clipCap(const ScalarGrid& grid, double iso, const ClipSettings& clip) {
  TriangleSurface cap;
  if (grid.points() == 0) return cap;
  const vtkSmartPointer<vtkImageData> image = toImageData(grid);
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(clip.origin.x(), clip.origin.y(), clip.origin.z());
  plane->SetNormal(clip.normal.x(), clip.normal.y(), clip.normal.z());
  vtkNew<vtkCutter> cutter;
  cutter->SetInputData(image);
  cutter->SetCutFunction(plane);
  vtkNew<vtkClipPolyData> inside; // keeps c >= iso
  inside->SetInputConnection(cutter->GetOutputPort());
  inside->SetValue(iso);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(inside->GetOutputPort());
  triangles->Update();
  vtkPolyData* poly = triangles->GetOutput();
  cap.points.resize(static_cast<std::size_t>(poly->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < poly->GetNumberOfPoints(); ++p) poly->GetPoint(p, cap.points[static_cast<std::size_t>(p)].data());
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
    if (size == 3) cap.triangles.push_back({static_cast<Index>(ids[0]), static_cast<Index>(ids[1]), static_cast<Index>(ids[2])});
  return cap;
}

} // namespace poro
