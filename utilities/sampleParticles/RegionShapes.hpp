#pragma once
/// The keys of particleDict regions with `shape: sphere` or `shape: surface`, read into the closed surface
/// sampleParticles samples:
///   {shape: sphere, centre: [x, y, z], radius: R}
///   {shape: surface, file: name.stl, scale: 2 or [sx, sy, sz], rotate: {axis: [0, 0, 1], angle: 90},
///    translate: [x, y, z], repair: false}
/// `file` is relative to constant/triSurface (STL, OBJ, OFF or PLY; SurfaceFile.hpp lists what is checked), and
/// the transform is applied in the order scale, rotate, translate (SurfaceTransform.hpp).

#include "geometry/ClosedShape.hpp"
#include "geometry/SurfaceTransform.hpp"

#include <filesystem>
#include <memory>

namespace poro {
class Dictionary;

/// Reads centre and radius (> 0).
std::shared_ptr<const ClosedShape> readSphere(const Dictionary& region);

/// Reads the transform keys: scale (a number or [sx, sy, sz], each > 0, default 1), rotate (a mapping of axis, any
/// non-zero vector, and angle in degrees; default none) and translate ([x, y, z] m, default 0).
SurfaceTransform readSurfaceTransform(const Dictionary& region);

/// A surface region's keys: which file, where it goes, whether to repair it.
struct SurfaceSource {
  std::filesystem::path path;
  SurfaceTransform transform;
  bool repair = false; ///< triangulate faces with more than three corners (otherwise an error)
};

/// Reads file, the transform keys and repair (default false). A file missing from `surfaceDirectory` is an
/// error at the `file` key that lists the files there; so is a directory of the file's name.
SurfaceSource readSurfaceKeys(const Dictionary& region, const std::filesystem::path& surfaceDirectory);

/// Reads, checks and places the surface (after the region's keys are all checked: a mesh may take a while), and
/// logs what was read and repaired.
std::shared_ptr<const ClosedShape> loadSurface(const SurfaceSource& source);

} // namespace poro
