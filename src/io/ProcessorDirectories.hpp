#pragma once
/// The subdomains of a decomposed case (ARCHITECTURE.md "Decomposed runs"): `processor<N>/`, N = 0, 1, ..., each laid
/// out like a case's time directories (`processor<N>/<t>/fluid.vtp`, ...), written by decomposePar and a parallel run
/// and merged back by reconstructPar.

#include "io/PvdSeries.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/RunState.hpp"
#include "sph/ParticleSystem.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// `<caseDir>/processor<n>`.
std::filesystem::path processorDirectory(const std::filesystem::path& caseDir, int n);

/// Whether `dir` is named like a subdomain: processor<N>, N in digits.
bool isProcessorDirectory(const std::filesystem::path& dir);

/// The processor directories of a case, in rank order; empty when it is not decomposed. A gap in the numbering
/// (processor0 and processor2 without processor1) is an InputError naming the missing one.
std::vector<std::filesystem::path> listProcessorDirectories(const std::filesystem::path& caseDir);

/// case.pvd of a decomposed case as its subdomains hold it: every piece of every time, part "<set>.processor<N>" (the
/// file stem and the subdomain), file "processor<N>/<t>/<set>.vtp", so ParaView opens the case without reconstructing.
PvdSeries seriesOfSubdomains(const std::vector<std::filesystem::path>& processors);

/// Time `time` of a decomposed case as one system (parallel/Decomposition.hpp mergePieces): every subdomain's
/// particles, each set sorted by id. A subdomain without the time (or with it incomplete), pieces of different runs
/// or radii and a particle in two subdomains are InputErrors that name the directory.
ParticleSystem readDecomposedParticles(const std::vector<std::filesystem::path>& processors, const std::string& time,
                                       double particleRadius, const std::vector<PorousMaterial>& materials);

/// uniform/time (and uniform/rigidBodies) of time `time`, which every subdomain must agree on.
RunState readDecomposedRunState(const std::vector<std::filesystem::path>& processors, const std::string& time);

} // namespace poro
