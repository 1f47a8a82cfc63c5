#include "surface/IsoSurface.hpp"

#include "core/Parallel.hpp"
#include "surface/VtkConversion.hpp"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkWindowedSincPolyDataFilter.h>

namespace poro {

TriangleSurface contour(const ScalarGrid& grid, double iso, int smoothingIterations) {
  TriangleSurface surface;
  if (grid.points() == 0) return surface;
  const vtkSmartPointer<vtkImageData> image = toImageData(grid);

  vtkSMPTools::Initialize(parallel::threads());
  vtkNew<vtkFlyingEdges3D> flyingEdges;
  flyingEdges->SetInputData(image);
  flyingEdges->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "c");
  flyingEdges->SetValue(0, iso);
  flyingEdges->ComputeNormalsOff();
  flyingEdges->ComputeGradientsOff();
  flyingEdges->ComputeScalarsOff();
  flyingEdges->Update();
  vtkPolyData* mesh = flyingEdges->GetOutput();
  vtkNew<vtkWindowedSincPolyDataFilter> smoother;
  if (smoothingIterations > 0 && mesh->GetNumberOfPolys() > 0) {
    smoother->SetInputData(mesh);
    smoother->SetNumberOfIterations(smoothingIterations);
    smoother->SetPassBand(0.1);
    smoother->NormalizeCoordinatesOn(); // the pass band then does not depend on the size of the scene
    smoother->BoundarySmoothingOff();
    smoother->FeatureEdgeSmoothingOff();
    smoother->NonManifoldSmoothingOn();
    smoother->Update();
    mesh = smoother->GetOutput();
  }

  const vtkIdType n = mesh->GetNumberOfPoints();
  surface.points.resize(static_cast<std::size_t>(n));
  for (vtkIdType p = 0; p < n; ++p) {
    double x[3];
    mesh->GetPoint(p, x);
    surface.points[static_cast<std::size_t>(p)] = Vec3(x[0], x[1], x[2]);
  }
  vtkCellArray* polys = mesh->GetPolys();
  surface.triangles.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
    if (size == 3) surface.triangles.push_back({static_cast<Index>(ids[0]), static_cast<Index>(ids[1]),
                                                static_cast<Index>(ids[2])});
  // The case table's winding is fixed, so one test settles the orientation of every component.
  if (surface.enclosedVolume() < 0.0) surface.flip();
  return surface;
}

} // namespace poro
