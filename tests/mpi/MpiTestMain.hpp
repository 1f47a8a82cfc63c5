#pragma once
#include "parallel/mpi/Communicator.hpp"

namespace poro::test {
/// The communicator of the MPI test executable (MpiTestMain.cpp).
const Communicator& mpiTestCommunicator();
} // namespace poro::test
