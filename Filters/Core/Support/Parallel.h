// SPDX-License-Identifier: GPL-3.0-or-later
// Runs parallel work on a chosen number of threads. Results of the library's
// parallel code never depend on this number; it only bounds CPU use.
#ifndef medialaxis_Parallel_h
#define medialaxis_Parallel_h

#include <tbb/task_arena.h>

namespace medialaxis
{
/// threads <= 0 uses every available core.
template <typename Function>
auto RunWithThreads(int threads, Function&& f) -> decltype(f())
{
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  return arena.execute(f);
}
}

#endif
