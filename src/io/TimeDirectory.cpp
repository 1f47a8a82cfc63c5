#include "io/TimeDirectory.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "io/AtomicFile.hpp"
#include "io/ParticleVtk.hpp"
#include "io/PorousSets.hpp"
#include "io/ProcessorDirectories.hpp"
#include "io/SamplingRecord.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <utility>

#include <unistd.h>

namespace poro {

namespace fs = std::filesystem;

namespace {

const char* const kPvdName = "case.pvd";

bool isTimeName(const std::string& name, double& value) {
  if (name.empty() || !(std::isdigit(static_cast<unsigned char>(name[0])))) return false;
  char* end = nullptr;
  value = std::strtod(name.c_str(), &end);
  return end && *end == '\0' && std::isfinite(value);
}

/// The particle files of a time directory: fluid.vtp, porous.vtp (every porous material), boundary.vtp (walls) and
/// rigid.vtp (rigid bodies).
bool isParticleFile(const fs::path& file) {
  const std::string stem = file.stem().string();
  return file.extension() == ".vtp" &&
         (stem == "fluid" || stem == kPorousSetName || stem == "boundary" || stem == kRigidSetName);
}

SetKind kindOfFile(const fs::path& file) {
  const std::string stem = file.stem().string();
  if (stem == "fluid") return SetKind::Fluid;
  if (stem == "boundary" || stem == kRigidSetName) return SetKind::Boundary;
  return SetKind::Porous;
}

/// ParticleSystem order (METHOD.md §1): fluid, porous, walls, rigid bodies - the same for every run and restart.
int rankOfFile(const fs::path& file) {
  return 2 * static_cast<int>(kindOfFile(file)) + (file.stem().string() == kRigidSetName ? 1 : 0);
}

std::string formatExact(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

/// The files a time directory gets, in ParticleSystem order: (part name = file stem, contents). Porous sets
/// share one file.
std::vector<std::pair<std::string, ParticleFile>> filesOf(const ParticleSystem& particles, bool withBoundaries) {
  std::vector<std::pair<std::string, ParticleFile>> files;
  bool porousListed = false;
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleSet& set = particles[s];
    if (set.kind() == SetKind::Boundary && !withBoundaries && set.name() != kRigidSetName) continue;
    if (set.kind() != SetKind::Porous) {
      files.emplace_back(set.name(), particleFileOf(set));
    } else if (!porousListed) {
      porousListed = true;
      files.emplace_back(kPorousSetName, porousFile(particles));
    }
  }
  return files;
}

/// Writes the particle files into `dir` and returns their part names (case.pvd), in ParticleSystem order.
std::vector<std::string> writeSets(const fs::path& dir, const ParticleSystem& particles, bool withBoundaries,
                                   bool binary) {
  std::vector<std::string> parts;
  for (const auto& [part, contents] : filesOf(particles, withBoundaries)) {
    writeParticleFile(contents, dir / (part + ".vtp"), binary);
    parts.push_back(part);
  }
  fs::create_directories(dir / "uniform");
  return parts;
}

void writeRunState(const fs::path& dir, const RunState& state, double particleRadius) {
  std::ostringstream out;
  out << "# Run state of this time directory (restart: startFrom latestTime).\n"
      << "time: " << formatExact(state.time) << "\nstep: " << state.step
      << "\ndeltaT: " << formatExact(state.nextDeltaT) << "  # the step size of the coming step [s]\n"
      << "lastDeltaT: " << formatExact(state.lastDeltaT) << "  # the step size of the step before [s]\n";
  // The radius the particles were sampled with, so that an edited particleDict cannot silently mismatch them.
  if (particleRadius > 0.0)
    out << "particleRadius: " << formatExact(particleRadius) << "  # [m], must equal system/particleDict's\n";
  writeFileAtomically(dir / "uniform" / "time", out.str());
  if (state.rigidBodies.empty()) return;
  // Every number exactly (formatExact), so a restart continues the bodies bit for bit.
  const auto vec = [](const Vec3& v) {
    return "[" + formatExact(v.x()) + ", " + formatExact(v.y()) + ", " + formatExact(v.z()) + "]";
  };
  std::ostringstream bodies;
  bodies << "# Rigid bodies of this time directory (physics/RigidBody.hpp): centre of mass [m], rotation from the\n"
         << "# sampled orientation (rows), velocity [m/s], angular momentum and velocity, world frame.\n"
         << "bodies:\n";
  for (const RigidBodyState& b : state.rigidBodies) {
    bodies << "  - name: " << b.name << "\n    centre: " << vec(b.centre) << "\n    rotation: [";
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) bodies << formatExact(b.rotation(r, c)) << (r == 2 && c == 2 ? "]\n" : ", ");
    bodies << "    velocity: " << vec(b.velocity) << "\n    angularMomentum: " << vec(b.angularMomentum)
           << "\n    angularVelocity: " << vec(b.angularVelocity) << "\n";
  }
  writeFileAtomically(dir / "uniform" / "rigidBodies", bodies.str());
}

RigidBodyState readRigidBody(const Dictionary& d) {
  RigidBodyState b;
  b.name = d.getString("name");
  b.centre = d.getVec3("centre");
  if (!d.has("rotation")) d.fail("rotation", "expected the body's rotation matrix, 9 numbers row by row");
  const std::vector<double> r = d.getReals("rotation", 9, {});
  for (int i = 0; i < 9; ++i) b.rotation(i / 3, i % 3) = r[static_cast<std::size_t>(i)];
  b.velocity = d.getVec3("velocity");
  b.angularMomentum = d.getVec3("angularMomentum");
  b.angularVelocity = d.getVec3("angularVelocity");
  d.checkUnknownKeys();
  return b;
}

/// uniform/sampling (io/SamplingRecord.hpp), unless there is no record to write.
void writeSamplingRecord(const fs::path& dir, const std::string& record) {
  if (!record.empty()) writeFileAtomically(dir / "uniform" / kSamplingRecordName, record);
}

const char* fileOfPhase(const std::string& phase) {
  return phase == "fluid"    ? "fluid.vtp"
         : phase == "porous" ? "porous.vtp"
         : phase == "rigid"  ? "rigid.vtp"
                             : "boundary.vtp";
}

/// The case's system/particleDict when it can be read, for cross-checks against the particle files (without it,
/// e.g. in unit tests, the checks are skipped; sampleParticles and readCase report a broken one themselves).
std::optional<Dictionary> readParticleDict(const fs::path& caseDir) {
  // A subdomain (processorN/) has no system/ of its own: its case's is the one above it.
  const fs::path system = isProcessorDirectory(caseDir) ? caseDir.parent_path() / "system" : caseDir / "system";
  const fs::path path = system / "particleDict";
  if (!fs::exists(path)) return std::nullopt;
  try {
    return Dictionary::read(path.string());
  } catch (const InputError&) {
    return std::nullopt;
  }
}

/// particleDict's particleRadius must be the one the particles were sampled with (uniform/time records it):
/// spacing, mass and kernel support follow from it, and a mismatch would run without any complaint.
void checkRadius(const fs::path& dir, const std::optional<Dictionary>& particleDict, double particleRadius) {
  const fs::path timeFile = dir / "uniform" / "time";
  if (!fs::exists(timeFile)) return;
  const Dictionary runState = Dictionary::read(timeFile.string());
  if (!runState.has("particleRadius")) return; // written before the radius was recorded
  const double sampled = runState.getReal("particleRadius", Range::positive());
  if (std::abs(sampled - particleRadius) <= 1e-12 * sampled) return;
  std::ostringstream msg;
  msg << particleRadius << " differs from " << sampled << ", the radius the particles of " << dir.string()
      << " were sampled with (" << runState.where("particleRadius")
      << "); set particleRadius back, or run sampleParticles again (it rewrites 0/) and start from 0";
  if (particleDict && particleDict->has("particleRadius")) particleDict->fail("particleRadius", msg.str());
  throw InputError(dir.string() + ": particleRadius " + msg.str());
}

/// Every phase system/particleDict samples must have its file: a deleted boundary.vtp would otherwise run the
/// fluid without walls, a deleted porous.vtp without its porous body.
void checkPhasesPresent(const fs::path& caseDir, const fs::path& dir, const std::optional<Dictionary>& particleDict) {
  if (!particleDict || !particleDict->has("regions")) return;
  std::vector<Dictionary> regions;
  try {
    regions = particleDict->getDictList("regions");
  } catch (const InputError&) {
    return; // sampleParticles reports it
  }
  for (const Dictionary& region : regions) {
    if (!region.has("phase") || !region.has("name")) continue;
    std::string phase, name;
    try {
      phase = region.getString("phase");
      name = region.getString("name");
    } catch (const InputError&) {
      continue;
    }
    if (phase != "fluid" && phase != "porous" && phase != "boundary" && phase != "rigid") continue;
    const std::string file = fileOfPhase(phase);
    if (fs::exists(dir / file) || (phase == "boundary" && fs::exists(caseDir / "0" / file))) continue;
    if (phase == "boundary" && dir.filename() != "0") { // a restart: walls that stand still live in 0/ only
      const fs::path zero = caseDir / "0";
      throw InputError(
          (fs::is_directory(zero) ? (zero / file).string() + ": no such file" : zero.string() + ": no such directory") +
          ", but " + region.where("phase") + " samples boundary region '" + name +
          "'. Walls that do not move are written once, to 0/boundary.vtp, not to later time directories such as " +
          dir.filename().string() + "/, so without it the run would have no walls. " +
          (isProcessorDirectory(caseDir)
               ? std::string("Reconstruct the case (reconstructPar) and decompose it again (decomposePar -force), "
                             "or restore ") +
                     zero.string() + "/"
               : "Restore 0/, or run sampleParticles again with the same system/particleDict (it rewrites 0/ and "
                 "case.pvd) and start again from " +
                     dir.filename().string()));
    }
    throw InputError((dir / file).string() + ": no such file, but " + region.where("phase") + " samples " + phase +
                     " region '" + name + "'" +
                     (dir.filename() == "0" ? "; run sampleParticles again (it writes 0/)"
                                            : "; the time directory is incomplete: start from another one"));
  }
}

/// Persistent ids are what restarts, the rest state and post-processing identify particles by (METHOD.md §4.1):
/// the file must hold them and no two particles of one file may share one.
void checkIds(const fs::path& file, const std::vector<std::string>& arrays, const std::vector<std::int64_t>& ids) {
  if (!ids.empty() && std::find(arrays.begin(), arrays.end(), field::id) == arrays.end())
    throw InputError(file.string() + ": no point-data array '" + field::id +
                     "' (Int64, the persistent particle ids, unique within the file); sampleParticles writes it");
  std::vector<std::pair<std::int64_t, std::size_t>> sorted(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) sorted[i] = {ids[i], i};
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k].first == sorted[k - 1].first)
      throw InputError(file.string() + ": array '" + field::id + "': particles " +
                       std::to_string(sorted[k - 1].second) + " and " + std::to_string(sorted[k].second) +
                       " have the same id " + std::to_string(sorted[k].first) + "; ids must be unique within the file");
}

/// Writes into `.<name>.tmp` and renames it to `<name>` once every file is complete.
template <class Fill>
void writeDirectoryAtomically(const fs::path& caseDir, const std::string& name, const Fill& fill) {
  const fs::path target = caseDir / name;
  const fs::path temporary = caseDir / ("." + name + ".tmp");
  std::error_code ec;
  fs::remove_all(temporary, ec);
  fs::create_directories(temporary / "uniform", ec);
  if (ec) throw OutputError(temporary.string() + ": cannot create directory: " + ec.message());
  try {
    fill(temporary);
    renameAtomically(temporary, target); // an existing `target` stays complete until the new one replaces it
  } catch (...) { // a full disk: give the space of the partial directory back; earlier times stay as they are
    fs::remove_all(temporary, ec);
    throw;
  }
}

/// `.<time>.tmp` (a directory being written) and `.<time>.old` (one being replaced, renameAtomically) of a time:
/// the time's name, or "" for any other entry.
std::string timeOfTemporary(const std::string& entry, const std::string& suffix) {
  double value = 0.0;
  if (entry.size() <= suffix.size() + 1 || entry.front() != '.' ||
      entry.compare(entry.size() - suffix.size(), suffix.size(), suffix) != 0)
    return "";
  const std::string name = entry.substr(1, entry.size() - suffix.size() - 1);
  return isTimeName(name, value) ? name : "";
}

/// `.case.pvd.tmp.<pid>` of a process that no longer runs (AtomicFile's temporarySibling of case.pvd).
bool isStalePvdTemporary(const std::string& entry) {
  const std::string prefix = std::string(".") + kPvdName + ".tmp.";
  if (entry.rfind(prefix, 0) != 0) return false;
  const std::string pid = entry.substr(prefix.size());
  if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) return false;
  const long owner = std::strtol(pid.c_str(), nullptr, 10);
  return owner != static_cast<long>(::getpid()) && ::kill(static_cast<pid_t>(owner), 0) != 0 && errno == ESRCH;
}

/// qw, qx, qy, qz of a row of postProcessing/rigidBodies/<name>.csv (columns 5-8), if it has them.
std::optional<Eigen::Quaterniond> quaternionOfRow(const std::string& row) {
  double values[8];
  const char* at = row.c_str();
  for (double& value : values) {
    char* end = nullptr;
    value = std::strtod(at, &end);
    if (end == at) return std::nullopt;
    at = *end == ',' ? end + 1 : end;
  }
  return Eigen::Quaterniond(values[4], values[5], values[6], values[7]);
}

} // namespace

void appendRigidBodyRows(const fs::path& caseDir, const RunState& state) {
  if (state.rigidBodies.empty()) return;
  const fs::path dir = caseDir / "postProcessing" / "rigidBodies";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir.string() + ": cannot create directory: " + ec.message());
  const char* header = "time,cx,cy,cz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";
  for (const RigidBodyState& b : state.rigidBodies) {
    const fs::path file = dir / (b.name + ".csv");
    std::string kept = std::string(header) + "\n", previous;
    if (std::ifstream in{file}) {
      std::string line;
      std::getline(in, line);
      while (std::getline(in, line))
        if (!line.empty() && std::strtod(line.c_str(), nullptr) < state.time - 1e-12) {
          kept += line + "\n";
          previous = line;
        }
    }
    Eigen::Quaterniond q{Eigen::Matrix3d(b.rotation)};
    // q and -q are the same rotation: the sign nearest the row before keeps the columns continuous for plots.
    if (const auto p = quaternionOfRow(previous); p && p->dot(q) < 0.0) q.coeffs() = -q.coeffs();
    std::ostringstream row;
    row << std::setprecision(10) << state.time;
    for (double value :
         {b.centre.x(), b.centre.y(), b.centre.z(), q.w(), q.x(), q.y(), q.z(), b.velocity.x(), b.velocity.y(),
          b.velocity.z(), b.angularVelocity.x(), b.angularVelocity.y(), b.angularVelocity.z()})
      row << ',' << value;
    writeFileAtomically(file, kept + row.str() + "\n");
  }
}

std::vector<std::string> particleSetOrder(const std::vector<PorousMaterial>& materials) {
  std::vector<std::string> names{"fluid"};
  for (const PorousMaterial& m : materials) names.push_back(m.name);
  names.push_back("boundary");
  names.push_back(kRigidSetName);
  return names;
}

std::string timeName(double time) {
  char buffer[40];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, time);
    const double back = std::strtod(buffer, nullptr);
    if (std::abs(back - time) <= 1e-10 * std::max(1.0, std::abs(time))) break;
  }
  return buffer;
}

std::vector<TimeDirectoryEntry> listTimeDirectories(const fs::path& caseDir) {
  std::vector<TimeDirectoryEntry> result;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
    double value = 0.0;
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && isTimeName(name, value) && fs::exists(entry.path() / "uniform" / "time"))
      result.push_back({name, value});
  }
  std::sort(result.begin(), result.end(), [](const auto& a, const auto& b) { return a.time < b.time; });
  return result;
}

RunState readRunState(const fs::path& timeDir) {
  const Dictionary dict = Dictionary::read((timeDir / "uniform" / "time").string());
  RunState state;
  state.time = dict.getReal("time", Range::nonNegative());
  state.step = dict.getInt("step", Range::nonNegative());
  state.nextDeltaT = dict.getReal("deltaT", Range::nonNegative());          // 0: take controlDict deltaT
  state.lastDeltaT = dict.getReal("lastDeltaT", 0.0, Range::nonNegative()); // 0: none (also older directories)
  dict.getReal("particleRadius", 0.0, Range::positive()); // checked against particleDict by readParticles
  dict.checkUnknownKeys();
  const fs::path bodies = timeDir / "uniform" / "rigidBodies";
  if (fs::exists(bodies))
    for (const Dictionary& body : Dictionary::read(bodies.string()).getDictList("bodies"))
      state.rigidBodies.push_back(readRigidBody(body));
  // The directory name is what startTime, latestTime and case.pvd go by; a run must not start elsewhere.
  double named = 0.0;
  const std::string name = timeDir.filename().string();
  if (isTimeName(name, named) && std::abs(named - state.time) > 1e-10 * std::max(1.0, std::abs(named)))
    dict.fail("time", "the time " + formatExact(state.time) + " differs from the directory name " + name +
                          "; the directory of time t must be named t");
  return state;
}

PvdSeries seriesOfTimeDirectories(const fs::path& caseDir) {
  PvdSeries series;
  const std::string porous = std::string(kPorousSetName) + ".vtp";
  for (const TimeDirectoryEntry& time : listTimeDirectories(caseDir))
    for (const std::string& file :
         {std::string("fluid.vtp"), porous, std::string("boundary.vtp"), std::string(kRigidSetName) + ".vtp",
          std::string(kFluidSurfaceFile), std::string(kPorousSurfaceFile)})
      if (fs::exists(caseDir / time.name / file))
        series.add(time.time, fs::path(file).stem().string(), time.name + "/" + file);
  return series;
}

ParticleSystem readParticles(const fs::path& caseDir, const std::string& name, double particleRadius,
                             const std::vector<PorousMaterial>& materials, bool everyMaterial) {
  const fs::path dir = caseDir / name;
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": time directory not found");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".vtp") continue;
    const std::string file = entry.path().filename().string();
    if (file == kFluidSurfaceFile || file == kPorousSurfaceFile) continue; // derived, not particles
    // Anything else would be silently left out of the run (e.g. a porous set of an older layout, sand.vtp).
    if (!isParticleFile(entry.path()))
      throw InputError(entry.path().string() +
                       ": not a particle file of a time directory; expected fluid.vtp, porous.vtp (all porous "
                       "materials), boundary.vtp and rigid.vtp only; move the file elsewhere");
    files.push_back(entry.path());
  }
  if (!fs::exists(dir / "boundary.vtp") && fs::exists(caseDir / "0" / "boundary.vtp"))
    files.push_back(caseDir / "0" / "boundary.vtp");
  // Fluid first, then porous sets in material order, walls, rigid bodies last (ParticleSystem order, METHOD.md §1).
  std::sort(files.begin(), files.end(),
            [&](const fs::path& a, const fs::path& b) { return rankOfFile(a) < rankOfFile(b); });
  const std::optional<Dictionary> particleDict = readParticleDict(caseDir);
  checkRadius(dir, particleDict, particleRadius);
  checkPhasesPresent(caseDir, dir, particleDict);
  checkSampledMaterials(caseDir, dir, materials);
  ParticleSystem particles(particleRadius);
  for (const fs::path& file : files) {
    const std::size_t first = particles.size();
    if (kindOfFile(file) == SetKind::Porous) {
      ParticleSet merged(kPorousSetName, SetKind::Porous);
      const auto arrays = readParticleSet(merged, file);
      const std::vector<std::int64_t> ids = merged.integer(field::id);
      splitPorousSet(std::move(merged), materials, particles, file,
                     everyMaterial); // first: its materialId message is clearer
      checkIds(file, arrays, ids);
    } else {
      ParticleSet& set = particles.add(file.stem().string(), kindOfFile(file));
      checkIds(file, readParticleSet(set, file), set.integer(field::id));
    }
    for (std::size_t s = first; s < particles.size(); ++s) particles[s].source = file.string();
  }
  if (!particles.find("fluid"))
    throw InputError(dir.string() + ": no fluid.vtp; run sampleParticles first (it writes 0/)");
  return particles;
}

TimeWriter::TimeWriter(fs::path caseDir, const OutputSettings& settings, const std::string& startName)
    : caseDir_(std::move(caseDir)), settings_(settings) {
  const fs::path pvd = caseDir_ / kPvdName;
  const double start = std::strtod(startName.c_str(), nullptr);
  if (fs::exists(pvd)) {
    try {
      series_ = PvdSeries::read(pvd);
    } catch (const InputError& e) {
      log::warning(std::string(e.what()) + "; rebuilding case.pvd");
      series_ = PvdSeries();
    }
  }
  series_.removeTimesAfter(start);
  recoverInterruptedWrites(caseDir_);
  // The record of what the particles were sampled from goes with them into every time directory (a restart from
  // any of them is checked, io/SamplingRecord.hpp); copied as it is.
  samplingRecord_ = readSamplingRecordText(caseDir_ / startName);
  for (const auto& entry : fs::directory_iterator(caseDir_ / startName))
    if (isParticleFile(entry.path()))
      series_.add(start, entry.path().stem().string(), startName + "/" + entry.path().filename().string());
  if (startName != "0" && fs::exists(caseDir_ / "0" / "boundary.vtp")) series_.add(0.0, "boundary", "0/boundary.vtp");
  series_.write(pvd);
}

void TimeWriter::write(const ParticleSystem& particles, const RunState& state) {
  const std::string name = timeName(state.time);
  std::vector<std::string> parts;
  // Static walls live in the start directory 0/ only, so rewriting 0/ (step 0) writes them too; rigid.vtp is
  // written every time. Where there is no 0/ to read them from (a subdomain decomposed from a later time) every
  // time directory holds them, so that a restart from any of them has its walls.
  const bool withBoundaries = movingWalls_ || state.step == 0 || !fs::exists(caseDir_ / "0" / "boundary.vtp");
  writeDirectoryAtomically(caseDir_, name, [&](const fs::path& dir) {
    parts = writeSets(dir, particles, withBoundaries, settings_.binary);
    writeRunState(dir, state, particles.particleRadius());
    writeSamplingRecord(dir, samplingRecord_);
    for (const auto& [file, text] : uniformFiles_) writeFileAtomically(dir / "uniform" / file, text);
  });
  appendRigidBodyRows(caseDir_, state);
  // A rewritten directory (a run again from 0 replaces 0/) has lost the surfaces fluidSurface added to the old one.
  series_.removeMissingFiles(state.time, caseDir_);
  for (const std::string& part : parts) series_.add(state.time, part, name + "/" + part + ".vtp");
  if (settings_.purgeWrite > 0) purge();
  series_.write(caseDir_ / kPvdName);
}

void recoverInterruptedWrites(const fs::path& caseDir) {
  std::vector<fs::path> unfinished, replaced, stale;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && !timeOfTemporary(name, ".tmp").empty())
      unfinished.push_back(entry.path());
    else if (entry.is_directory() && !timeOfTemporary(name, ".old").empty())
      replaced.push_back(entry.path());
    else if (entry.is_regular_file() && isStalePvdTemporary(name))
      stale.push_back(entry.path());
  }
  for (const auto& path : unfinished) {
    fs::remove_all(path, ec);
    log::warning(path.string() + ": removed an unfinished time directory (a run was killed while writing it)");
  }
  for (const auto& path : replaced) { // a run killed while replacing the time directory (renameAtomically)
    const fs::path time = caseDir / timeOfTemporary(path.filename().string(), ".old");
    if (fs::exists(time / "uniform" / "time")) {
      fs::remove_all(path, ec);
      continue;
    }
    fs::remove_all(time, ec);
    fs::rename(path, time, ec);
    log::warning(time.string() + ": restored from " + path.filename().string() +
                 " (a run was killed while replacing this time directory)");
  }
  for (const auto& path : stale) fs::remove(path, ec); // left by a run killed while rewriting case.pvd
}

void TimeWriter::purge() {
  auto times = listTimeDirectories(caseDir_);
  times.erase(std::remove_if(times.begin(), times.end(), [](const auto& t) { return t.name == "0"; }), times.end());
  const std::size_t keep = static_cast<std::size_t>(settings_.purgeWrite);
  for (std::size_t i = 0; i + keep < times.size(); ++i) {
    std::error_code ec;
    fs::remove_all(caseDir_ / times[i].name, ec);
    series_.removeTime(times[i].name);
  }
}

std::vector<std::string> writeTimeDirectory(const fs::path& caseDir, const ParticleSystem& particles,
                                            const RunState& state, bool binary, const std::string& samplingRecord,
                                            bool withBoundaries) {
  std::vector<std::string> parts;
  writeDirectoryAtomically(caseDir, timeName(state.time), [&](const fs::path& dir) {
    parts = writeSets(dir, particles, withBoundaries, binary);
    writeRunState(dir, state, particles.particleRadius());
    writeSamplingRecord(dir, samplingRecord);
  });
  return parts;
}

std::string readSamplingRecordText(const fs::path& timeDir) {
  std::string text;
  if (std::ifstream record{timeDir / "uniform" / kSamplingRecordName})
    text.assign(std::istreambuf_iterator<char>(record), std::istreambuf_iterator<char>());
  return text;
}

void TimeWriter::writeAll(const fs::path& caseDir, const ParticleSystem& particles, const RunState& state, bool binary,
                          const std::string& samplingRecord) {
  const std::vector<std::string> parts = writeTimeDirectory(caseDir, particles, state, binary, samplingRecord, true);
  const std::string name = timeName(state.time);
  PvdSeries series;
  for (const std::string& part : parts) series.add(state.time, part, name + "/" + part + ".vtp");
  series.write(caseDir / kPvdName);
}

} // namespace poro
