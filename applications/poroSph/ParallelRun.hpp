#pragma once
/// poroSph -parallel: one rank of a decomposed case (ARCHITECTURE.md "Decomposed runs"), started by mpirun.

#include "core/Arguments.hpp"

namespace poro {

/// Runs this rank's subdomain processor<rank>/ to endTime and returns the exit code. argc/argv go to MPI first.
int runParallel(const Arguments& args, int& argc, char**& argv);

} // namespace poro
