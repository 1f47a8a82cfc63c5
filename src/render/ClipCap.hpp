#pragma once
/// Where a clip plane cuts a body open: the part of the plane inside the body (c >= iso of the colour field the
/// body's surface was contoured from), so the cut shows a face instead of a hollow shell. VTK stays in ClipCap.cpp.

#include "render/RenderSettings.hpp"
#include "surface/ScalarGrid.hpp"
#include "surface/TriangleSurface.hpp"

namespace poro {

/// The cap of `grid`'s body on `clip`'s plane as triangles (empty where the plane misses the body).
TriangleSurface clipCap(const ScalarGrid& grid, double iso, const ClipSettings& clip);

} // namespace poro
