#pragma once
/// How the process gets and returns its memory.

namespace poro::memory {

/// Large blocks (a particle set's fields, neighbour lists, per-pair arrays) are mapped from the system and go back
/// to it when freed. glibc's allocator would otherwise raise its threshold for that after the first large block
/// is freed and carve later ones out of its heap, whose freed pages stay with the process: as lists grow step by
/// step (fluid entering a porous body), the peak memory then grows by blocks no longer in use (about 50 MB of
/// 590 on the published Seep at r = 1 cm). Call once, first thing in main; does nothing on other C libraries.
void returnLargeBlocksToSystem();

} // namespace poro::memory
