#pragma once
/// Time directories of a case (ARCHITECTURE.md "A case directory"): `<t>/fluid.vtp`, `<t>/porous.vtp` (all
/// porous sets in one file, io/PorousSets.hpp), `<t>/boundary.vtp`, `<t>/uniform/time` (time, step index,
/// the coming step's deltaT) and `<t>/uniform/sampling` (what the particles were sampled from, io/SamplingRecord.hpp),
/// written under a temporary name and renamed when complete; `case.pvd` rewritten atomically after each write;
/// boundary sets are static and live in `0/` only.

#include "io/OutputSettings.hpp"
#include "io/PvdSeries.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/Solver.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace poro {

/// Surfaces that utilities/fluidSurface adds to a time directory (and to case.pvd, named by their stem). They are
/// derived from the particles, so readParticles skips them and a restart is unaffected by them.
/// The boundary set of rigid bodies' particles (phase: rigid), written to rigid.vtp at every time: the bodies move,
/// while static walls stay in 0/boundary.vtp.
inline constexpr const char* kRigidSetName = "rigid";
inline constexpr const char* kFluidSurfaceFile = "fluidSurface.vtp";
inline constexpr const char* kPorousSurfaceFile = "porousSurface.vtp";

/// The names of a case's particle sets in ParticleSystem order (METHOD.md §1): fluid, the porous materials in
/// constant/porosityProperties order, the walls ("boundary") and the rigid bodies.
std::vector<std::string> particleSetOrder(const std::vector<PorousMaterial>& materials);

/// The directory name of a time value: shortest decimal that reads back within 1e-10 relative ("0.1", "2.5").
std::string timeName(double time);

struct TimeDirectoryEntry {
  std::string name;
  double time;
};

/// Complete time directories (those with uniform/time) of a case, by increasing time.
std::vector<TimeDirectoryEntry> listTimeDirectories(const std::filesystem::path& caseDir);

/// Reads `<dir>/uniform/time` (time, step, deltaT and, since it is recorded, particleRadius); a time that differs
/// from the directory's name is an InputError.
RunState readRunState(const std::filesystem::path& timeDir);

/// postProcessing/rigidBodies/<name>.csv of `caseDir`: one row per write of each body of `state`; rows at or after
/// its time (a run again from an earlier time) are dropped first, so the file holds one trajectory. TimeWriter calls
/// it; rank 0 of a parallel run also does for the case itself.
void appendRigidBodyRows(const std::filesystem::path& caseDir, const RunState& state);

/// Loads every particle set of a time directory: `fluid.vtp`, `porous.vtp` and `boundary.vtp` (or
/// `0/boundary.vtp` when the directory has no boundary of its own), in ParticleSystem order. `fluid` and
/// `boundary` name the fluid and wall sets; porous.vtp is split by its materialId into one set per material
/// of `materials` (constant/porosityProperties order), named after the material (splitPorousSet). The surfaces
/// above are skipped; any other .vtp file in the directory, a missing fluid.vtp and a porous.vtp the materials cannot
/// split are InputErrors, and so are a file without the array 'id' or with two particles of the same id, a
/// `particleRadius` other than the one uniform/time records, when the case has a readable system/particleDict, a
/// missing file of a phase its regions sample (a deleted boundary.vtp or porous.vtp), and a materialId that names
/// another material than the one uniform/sampling records it was sampled as (checkSampledMaterials).
/// `everyMaterial`: a set for every material, empty where porous.vtp has none of it (a rank of a decomposed case).
ParticleSystem readParticles(const std::filesystem::path& caseDir, const std::string& timeName, double particleRadius,
                             const std::vector<PorousMaterial>& materials, bool everyMaterial = false);

/// case.pvd as the time directories say, for a case that has lost it: every complete time directory (by time) with
/// its particle files (fluid.vtp, porous.vtp, boundary.vtp, in that order) and the surfaces fluidSurface added.
PvdSeries seriesOfTimeDirectories(const std::filesystem::path& caseDir);

/// Cleans up after a run killed while writing: removes `.<t>.tmp` (unfinished time directories) and the
/// `.case.pvd.tmp.<pid>` of processes that no longer run, and puts back `.<t>.old` (a time directory being
/// replaced) where `<t>` is missing or incomplete. poroSph does this before it looks for its start time.
void recoverInterruptedWrites(const std::filesystem::path& caseDir);

/// Writes `<caseDir>/<t>/` atomically: the particle files (static walls only `withBoundaries`, rigid.vtp always),
/// uniform/time (and uniform/rigidBodies) and, unless `samplingRecord` is empty, uniform/sampling. case.pvd is left
/// as it is. Returns the part names of the files written (case.pvd's "fluid", "porous", ...), in ParticleSystem order.
std::vector<std::string> writeTimeDirectory(const std::filesystem::path& caseDir, const ParticleSystem& particles,
                                            const RunState& state, bool binary, const std::string& samplingRecord,
                                            bool withBoundaries);

/// The text of `<timeDir>/uniform/sampling` as it is (io/SamplingRecord.hpp), "" when the directory has none.
std::string readSamplingRecordText(const std::filesystem::path& timeDir);

/// Writes the solver's state as a time directory and keeps case.pvd in step.
class TimeWriter {
public:
  /// Starts the series at the time directory `startName` (entries after it are dropped from case.pvd).
  TimeWriter(std::filesystem::path caseDir, const OutputSettings& settings, const std::string& startName);

  /// Writes `<t>/` for the dynamic sets (fluid.vtp, porous.vtp) and rigid bodies (rigid.vtp), with moving walls or at
  /// step 0 also boundary.vtp, and uniform/time (and uniform/sampling when the start time directory has it),
  /// atomically, then case.pvd (one part per file: "fluid", "porous", "boundary", "rigid") and purgeWrite. When `<t>/`
  /// existed (a run again from 0 rewrites 0/), case.pvd's entries of t whose files the rewrite removed
  /// (fluidSurface.vtp, porousSurface.vtp) are dropped.
  void write(const ParticleSystem& particles, const RunState& state);
  /// Walls move (prescribed motion): every time directory gets boundary.vtp, which a restart reads back.
  void setMovingWalls(bool moving) { movingWalls_ = moving; }
  /// A file `uniform/<name>` with `text` in every time directory written from now on (a parallel run's partition);
  /// a second call for the same name replaces its text.
  void setUniformFile(const std::string& name, const std::string& text) { uniformFiles_[name] = text; }
  /// New writeFormat / purgeWrite from a re-read system/controlDict; the next write uses them.
  void setSettings(const OutputSettings& settings) { settings_ = settings; }

  /// Writes a complete time directory including boundary sets (sampleParticles writes 0/ with this), and
  /// uniform/sampling when `samplingRecord` is not empty (io/SamplingRecord.hpp).
  static void writeAll(const std::filesystem::path& caseDir, const ParticleSystem& particles, const RunState& state,
                       bool binary, const std::string& samplingRecord = "");

private:
  void purge();
  std::filesystem::path caseDir_;
  OutputSettings settings_;
  PvdSeries series_;
  bool movingWalls_ = false;
  std::string samplingRecord_; ///< uniform/sampling of the start time directory, copied into every one written
  std::map<std::string, std::string> uniformFiles_; ///< setUniformFile
};

} // namespace poro
