// GoogleTest under mpiexec: every rank runs every test; the tests reach the ranks through mpiTestCommunicator().
// A failure on any rank makes that rank exit non-zero, and mpiexec with it.

#include "MpiTestMain.hpp"

#include <gtest/gtest.h>

namespace poro::test {
namespace {
Communicator* world = nullptr;
}
const Communicator& mpiTestCommunicator() { return *world; }
} // namespace poro::test

int main(int argc, char** argv) {
  poro::Communicator comm(argc, argv);
  poro::test::world = &comm;
  ::testing::InitGoogleTest(&argc, argv);
  if (comm.rank() != 0) { // one report, from rank 0; the others still fail the run through their exit code
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
