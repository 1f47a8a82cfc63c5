#pragma once
/// The ParaView time series `case.pvd` (ARCHITECTURE.md "A case directory"): one DataSet entry per
/// written particle set and time, rewritten atomically after each write so ParaView can open the case
/// while the solver runs.

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// The one part that may be static: the walls sampleParticles writes once into 0/boundary.vtp (and those of each
/// subdomain of a parallel run, "boundary.processor<N>").
inline constexpr const char* kStaticPart = "boundary";

class PvdSeries {
public:
  struct Entry {
    double time;      ///< simulation time [s], the pvd "timestep"
    std::string part; ///< particle set name, e.g. "fluid"; each name gets its own pvd part index
    std::string file; ///< path relative to the .pvd, e.g. "0.1/fluid.vtp"
  };

  /// Appends an entry; an existing entry with the same time and part is replaced (a rewrite of a time).
  void add(double time, const std::string& part, const std::string& file);

  const std::vector<Entry>& entries() const { return entries_; }
  bool empty() const { return entries_.empty(); }

  /// Drops the entries later than `time` (restart from `time`: what followed will be recomputed).
  void removeTimesAfter(double time);
  /// Drops the entries of exactly this time value (purgeWrite).
  void removeTime(double time);
  /// Drops the entries whose file lies in the time directory `timeName` (e.g. "0.1"; purgeWrite).
  void removeTime(const std::string& timeName);

  /// Drops the entries of exactly this time value whose file (relative to `baseDir`, the directory of the .pvd)
  /// does not exist: after a time directory is rewritten, the surfaces fluidSurface had added to it are gone.
  void removeMissingFiles(double time, const std::filesystem::path& baseDir);

  /// Writes the collection atomically (writeFileAtomically): per time (in order of first appearance) one
  /// `<DataSet timestep=".." group="" part="k" name="<part>" file=".."/>` per part, times with 17 significant
  /// digits, part indices 0, 1, ... in order of first appearance of each part name. The static set (the part
  /// kStaticPart with a single file, at the series' first time: the boundary sampleParticles writes once into 0/)
  /// is listed at every time with that file: ParaView's reader shows only the files of the current time, so the
  /// set stays visible and keeps its block index and name. Any other part is listed only at the times it has a
  /// file, so a surface that fluidSurface made for some times (also only for the first) never shows at others.
  /// Throws OutputError.
  void write(const std::filesystem::path& path) const;

  /// Reads a collection written by write() (or by ParaView): the DataSet elements' timestep and file
  /// attributes; the part name is the file's stem ("0.1/fluid.vtp" -> "fluid"). A file listed again for
  /// the same part (write()'s repetition of a static set) is read once, at its first time. Throws InputError
  /// ("path:line: ...") for a missing file, a file that is not a collection or an unreadable DataSet.
  static PvdSeries read(const std::filesystem::path& path);

private:
  std::vector<Entry> entries_;
};

} // namespace poro
