#pragma once
/// Particle sets as VTK XML PolyData (.vtp): what time directories hold and ParaView shows
/// (ARCHITECTURE.md "A case directory"). VTK itself stays inside ParticleVtk.cpp.

#include "sph/ParticleSet.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// Writes every field whose role includes Output (Scratch fields are skipped) as a .vtp file.
/// Points are field "x" (Float64, not repeated as point data), one vertex cell per particle so ParaView
/// renders them; Real -> 1-component Float64, Vec3 -> 3 components, Mat3 -> 9 components row-major
/// (xx xy xz yx ...), Int -> Int64. Field data "setName" and "kind" (string arrays) name the set.
/// binary=true: appended raw data compressed with zlib (its fastest level), bit-exact on read.
/// binary=false: ascii, for reading in an editor. VTK 9.1 prints doubles with the shortest digits that
/// round-trip, so every finite value reads back bit-exact except -0.0, which becomes +0.0. VTK's reader
/// cannot parse NaN or inf in ascii, so a set holding them is written binary instead (with a warning).
/// The file is written to a temporary sibling and renamed over `file`, so a crash never leaves a
/// half-written file. Throws OutputError naming the file.
void writeParticleSet(const ParticleSet& set, const std::filesystem::path& file, bool binary);

/// What one .vtp file holds: `parts` one after the other (one set, or every porous set in porous.vtp), named
/// `name` of kind `kind`, with the point arrays `fields`; a part without one of them is written as zeros there.
struct ParticleFile {
  std::string name;
  SetKind kind = SetKind::Fluid;
  std::vector<const ParticleSet*> parts;
  std::vector<ParticleSet::FieldInfo> fields;
};

/// One set's file, as writeParticleSet writes it: its fields of role Output or Restart, in its order.
ParticleFile particleFileOf(const ParticleSet& set);

/// Writes `contents` as writeParticleSet writes one set. The Real and Vec3 fields of a file of one part are
/// written from the set's own storage; other fields, and those of several parts, are copied once.
void writeParticleFile(const ParticleFile& contents, const std::filesystem::path& file, bool binary);

/// Reads a .vtp written by writeParticleSet (or any PolyData whose point arrays fit the registry) into
/// `set`: resizes it to the number of points (fields absent from the file become zero), copies the points
/// into "x" and every point-data array into the field of the same name. Unknown arrays are registered
/// with role Output: Int8..Int64/UInt* -> Int, 1/3/9-component Float32/Float64 -> Real/Vec3/Mat3 (9
/// components row-major).
/// Returns the names of the point-data arrays the file held (the points are always there as "x").
/// Throws InputError, message starting with the file path (and the line of the array's element where one
/// array is at fault), when the file is missing, empty, not VTK XML, cut short (no closing </VTKFile>) or not
/// readable PolyData (corrupt), its NumberOfPoints is negative or more than its size can hold, an ascii array
/// has more or fewer values than NumberOfPoints times its components or a value that is not a number of its
/// type, an array does not match the type of an existing field or has an unsupported type, a Restart field
/// holds NaN or inf (names the array and first particle), or the file's "kind" differs from the set's kind.
/// The size check and the ascii checks run before VTK allocates anything. The set is left unchanged when
/// validation fails.
std::vector<std::string> readParticleSet(ParticleSet& set, const std::filesystem::path& file);

} // namespace poro
