#include "core/Memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace poro::memory {

namespace {
/// Blocks from this size on are mapped on their own. Small enough for the arrays of a set of some ten thousand
/// particles; the per-step scratch below it stays in the heap, where reusing it costs no page faults.
constexpr int kMappedBlockBytes = 1 << 20;
/// Free memory at the heap's top up to this size stays with the process.
constexpr int kKeptHeapTopBytes = 8 << 20;
} // namespace

void returnLargeBlocksToSystem() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMappedBlockBytes); // a fixed threshold: glibc no longer raises it
  // That also fixes the heap's trim threshold at its default of 128 KiB: the small arrays that grow each step
  // (pairs of a few hundred particles coming into contact) would then give the heap top back and fault it in
  // again every step. Kept small all the same: a large request is carved from the heap's top whenever the top
  // has room for it, mapping or no mapping, and the top then held blocks freed long ago (the published Seep at
  // r = 1 cm peaks 2 MiB lower with 8 MiB than with 64).
  mallopt(M_TRIM_THRESHOLD, kKeptHeapTopBytes);
  // One arena for every thread. A worker's own arena kept the blocks its tasks had freed (a grid search's chunk
  // buffers) beside the main one, unused by anything else: 6 MiB of the published Seep's peak at r = 1 cm. The
  // threads allocate a few blocks per list and step, so they seldom meet at the arena's lock.
  mallopt(M_ARENA_MAX, 1);
#endif
}

} // namespace poro::memory
