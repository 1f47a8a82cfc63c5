#pragma once
/// How the process gets and returns its memory.

#include <cstddef>
#include <vector>

namespace poro::memory {

/// Large blocks (a particle set's fields, neighbour lists, per-pair arrays) are mapped from the system and go back
/// to it when freed. glibc's allocator would otherwise raise its threshold for that after the first large block
/// is freed and carve later ones out of its heap, whose freed pages stay with the process: as lists grow step by
/// step (fluid entering a porous body), the peak memory then grows by blocks no longer in use (about 50 MB of
/// 590 on the published Seep at r = 1 cm). The heap keeps little free memory at its top, and every thread
/// allocates from the one heap (Memory.cpp says why). Call once, first thing in main, before any thread starts;
/// does nothing on other C libraries.
void returnLargeBlocksToSystem();

/// Empties an array (a std::vector, a ReallocVector) and gives its block back (clear() keeps it).
template <class Array> void freeAll(Array& array) { Array().swap(array); }

/// Resizes an array whose old contents are not needed (it is refilled) to n entries. Past its capacity it
/// allocates n plus 1/32, copying nothing: per-pair arrays grow by a little most steps while fluid enters a
/// body, and std::vector's doubling would keep up to twice their size; an exact fit would reallocate every step.
/// The old block is freed before the new one is taken, so the two are never held at once.
template <class T> void resizeForRefill(std::vector<T>& array, std::size_t n) {
  if (n > array.capacity()) {
    freeAll(array);
    array.reserve(n + n / 32);
  }
  array.resize(n);
}

} // namespace poro::memory
