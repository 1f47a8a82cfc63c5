#pragma once
/// Writing a TriangleSurface as VTK XML PolyData (.vtp), the format of the time directories (ParaView opens it), and
/// reading it back (tests measure what fluidSurface wrote).

#include "surface/TriangleSurface.hpp"

#include <filesystem>

namespace poro {

/// Writes `surface` (Float32 points and point fields, triangles as polys; binary, zlib-compressed) atomically:
/// to a temporary sibling, renamed over `file` when complete. Throws OutputError naming the file.
void writeSurface(const TriangleSurface& surface, const std::filesystem::path& file);

/// Reads a .vtp of triangles (as writeSurface writes it): points, triangles and every point-data array as a field.
/// Throws InputError naming the file when it cannot be read or holds cells other than triangles.
TriangleSurface readSurface(const std::filesystem::path& file);

} // namespace poro
