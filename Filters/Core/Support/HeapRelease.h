// SPDX-License-Identifier: GPL-3.0-or-later
// Gives the heap's wholly free pages back to the system where a stage has
// just freed its largest transient data.
#ifndef medialaxis_HeapRelease_h
#define medialaxis_HeapRelease_h

#include <cstddef>
#include <cstdlib> // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace medialaxis
{
/// The programs keep freed memory in their heaps (HeapTuning.h: reusing it
/// is faster than asking the system again), and each thread has a heap of
/// its own that the others do not reuse, so the pages one step freed stayed
/// resident beside what the next step allocated. Called where a step has
/// just freed its largest transient data (the Delaunay triangulation, the
/// per-cell arrays, the restricted Voronoi diagram's blocks), it keeps the
/// process's peak near what lives at once: 364 -> 292 MB on a
/// 268,686-triangle surface at 50,000 samples. Pages given back come back
/// zeroed, by page faults, when the heap grows again: on a small heap that
/// cost more than the memory is worth (0.80 -> 0.90 s for 10,000 samples,
/// peak 82 -> 77 MB), so heaps below 256 MB are left as they are. Changes no
/// result. No effect outside glibc.
inline void ReleaseFreeHeapPages()
{
#if defined(__GLIBC__)
  constexpr std::size_t smallHeap = std::size_t(256) << 20;
  if (mallinfo2().arena >= smallHeap)
  {
    malloc_trim(0);
  }
#endif
}
}

#endif
