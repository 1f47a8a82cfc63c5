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
constexpr int kKeptHeapTopBytes = 64 << 20;
} // namespace

void returnLargeBlocksToSystem() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMappedBlockBytes); // a fixed threshold: glibc no longer raises it
  // That also fixes the heap's trim threshold at its default of 128 KiB: the small arrays that grow each step
  // (pairs of a few hundred particles coming into contact) would then give the heap top back and fault it in
  // again every step. The heap holds only blocks below 1 MiB, so keeping its top costs little.
  mallopt(M_TRIM_THRESHOLD, kKeptHeapTopBytes);
#endif
}

} // namespace poro::memory
