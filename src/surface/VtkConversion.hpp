#pragma once
/// TriangleSurface and ScalarGrid as VTK data. A VTK-facing header: only the libraries that link VTK themselves
/// include it (surface, to contour and write .vtp files, and render, to draw); every other header of this folder
/// is VTK-free.

#include "surface/ScalarGrid.hpp"
#include "surface/TriangleSurface.hpp"

#include <vtkImageData.h>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace poro {

/// Points and fields as Float32 (a picture needs no more, and the files stay half as large), triangles as polys;
/// a 3-component field is also the active vectors, the first 1-component field the active scalars.
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleSurface& surface);

/// The grid as image data whose point scalars "c" share the grid's memory (VTK never writes or frees it): the
/// grid must outlive the image.
vtkSmartPointer<vtkImageData> toImageData(const ScalarGrid& grid);

} // namespace poro
