#pragma once
/// Reads and validates a whole case before anything runs (ARCHITECTURE.md "Input is checked at the
/// door"): system/controlDict, system/solverDict, constant/fluidProperties, constant/porosityProperties, the
/// particle radius of system/particleDict, and the particles of the start time directory, which must have been sampled
/// from the regions system/particleDict has now (io/SamplingRecord.hpp).

#include "io/OutputSettings.hpp"
#include "physics/FluidProperties.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/Solver.hpp"
#include "physics/SolverSettings.hpp"
#include "physics/TimeControl.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

struct SimulationCase {
  TimeControl control;
  OutputSettings output;
  SolverSettings solver;
  FluidProperties fluid;
  std::vector<PorousMaterial> materials; ///< constant/porosityProperties in file order; empty without that file
  std::string startName;                 ///< the time directory the run starts from
  RunState start;
  ParticleSystem particles;
  std::vector<ObjectMotion> wallMotions;    ///< the `motion:` blocks of system/particleDict's boundary regions
  std::vector<RigidBody::Spec> rigidBodies; ///< system/particleDict's rigid regions (physics/RigidBody.hpp)
  /// The start time directory is at endTime or after it (a finished case run again): nothing to run, and
  /// `particles` is empty.
  bool endTimeReached = false;
};

/// `threads` > 0 overrides solverDict's threads (-threads on the command line). The time directories are those of
/// `timesDir` when given (a subdomain's processor<N>/ in a parallel run), else the case's own.
SimulationCase readCase(const std::filesystem::path& caseDir, int threads = 0,
                        const std::filesystem::path& timesDir = {});

/// particleRadius of system/particleDict (the one key the solver needs from it).
double readParticleRadius(const std::filesystem::path& caseDir);

/// The `motion:` blocks of system/particleDict (physics/WallMotion.hpp), validated, with the object id each
/// region's particles carry (its index in `regions`). Only boundary regions may move.
std::vector<ObjectMotion> readWallMotions(const std::filesystem::path& caseDir);

/// The rigid regions of system/particleDict (physics/RigidBody.hpp), validated, with their object ids.
std::vector<RigidBody::Spec> readRigidBodies(const std::filesystem::path& caseDir);

/// The porous materials of constant/porosityProperties, validated (PorousMaterial::readAll), in file order;
/// empty when the case has no such file (a fluid-only case).
std::vector<PorousMaterial> readPorousMaterials(const std::filesystem::path& caseDir);

} // namespace poro
