#pragma once
/// The contour c = iso of a ScalarGrid's colour channel as a closed triangle mesh, by flying edges (Schroeder et
/// al. 2015, VTK's vtkFlyingEdges3D: marching cubes in four passes, parallel). VTK stays in IsoSurface.cpp.

#include "surface/ScalarGrid.hpp"
#include "surface/TriangleSurface.hpp"

namespace poro {

/// The contour of the grid at `iso`, its triangles facing outward (away from c > iso). Closed and manifold when
/// c < iso on the grid's border (as
/// colourField makes it). `smoothingIterations` > 0 then smooths the mesh with a windowed sinc filter (Taubin
/// et al. 1996, vtkWindowedSincPolyDataFilter: a low-pass filter that neither shrinks the surface nor changes its
/// connectivity, so it stays closed), which removes the grid- and particle-scale ripple. Uses
/// parallel::threads() threads. An empty grid gives an empty surface.
TriangleSurface contour(const ScalarGrid& grid, double iso, int smoothingIterations = 0);

} // namespace poro
