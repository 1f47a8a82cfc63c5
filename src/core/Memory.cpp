#include "core/Memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace poro::memory {

namespace {
/// Blocks from this size on are mapped on their own. Small enough for the arrays of a set of some ten thousand
/// particles; the per-step scratch below it stays in the heap, where reusing it costs no page faults.
constexpr int kMappedBlockBytes = 1 << 20;
} // namespace

void returnLargeBlocksToSystem() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMappedBlockBytes); // a fixed threshold: glibc no longer raises it
#endif
}

} // namespace poro::memory
