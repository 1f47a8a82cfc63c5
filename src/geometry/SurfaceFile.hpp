#pragma once
/// A closed surface read from a file: STL (ASCII or binary), OBJ, OFF or PLY, checked to bound a volume and
/// oriented outward (with CGAL, behind this header). Each problem is an InputError that starts with the file's
/// path and says what is wrong, how often and where one case of it is, in the file's own coordinates:
///   - an unknown extension, a file that cannot be opened or parsed, no faces, coordinates that are not finite or
///   beyond
///     +-1e100 (the volume would overflow);
///   - faces that are not triangles (triangulated instead when `repair` is true, with a note);
///   - degenerate faces (corners that coincide or lie on one line);
///   - open boundary edges (edges of one face only: the surface is not closed, so it has no inside);
///   - edges of more than two faces, or faces meeting only at a vertex (not a manifold);
///   - pairs of faces that intersect (the surface crosses itself, so its inside is ambiguous);
///   - no enclosed volume.
/// Points with identical coordinates are merged first (STL stores every corner of every face separately).
/// Orientation is repaired, as that is always safe on a closed surface: faces oriented against their neighbours,
/// and components facing into the body, are reversed, each with a note.

#include "geometry/TriangleMesh.hpp"

#include <string>
#include <vector>

namespace poro {

struct SurfaceFile {
  TriangleMesh mesh;              ///< closed, faces counter-clockwise seen from outside
  std::vector<std::string> notes; ///< one sentence per repair made, for the log

  static SurfaceFile read(const std::string& path, bool repair = false);
};

} // namespace poro
