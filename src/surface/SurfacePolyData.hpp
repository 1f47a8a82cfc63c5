#pragma once
/// TriangleSurface as VTK PolyData. A VTK-facing header: only the libraries that link VTK themselves include it
/// (surface, to write .vtp files, and render, to draw); every other header of this folder is VTK-free.

#include "surface/TriangleSurface.hpp"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace poro {

/// Points and fields as Float32 (a picture needs no more, and the files stay half as large), triangles as polys;
/// a 3-component field is also the active vectors, the first 1-component field the active scalars.
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleSurface& surface);

} // namespace poro
