#pragma once
/// The subdomains of a decomposed case (ARCHITECTURE.md "Decomposed runs"): `processor<N>/`, N = 0, 1, ..., each laid
/// out like a case's time directories (`processor<N>/<t>/fluid.vtp`, ...), written by decomposePar and a parallel run
/// and merged back by reconstructPar.

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// `<caseDir>/processor<n>`.
std::filesystem::path processorDirectory(const std::filesystem::path& caseDir, int n);

/// The processor directories of a case, in rank order; empty when it is not decomposed. A gap in the numbering
/// (processor0 and processor2 without processor1) is an InputError naming the missing one.
std::vector<std::filesystem::path> listProcessorDirectories(const std::filesystem::path& caseDir);

} // namespace poro
