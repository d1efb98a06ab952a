// SPDX-License-Identifier: GPL-3.0-or-later
// Runs parallel work on a chosen number of threads. Results of the library's
// parallel code never depend on this number; it only bounds CPU use.
#ifndef medialaxis_Parallel_h
#define medialaxis_Parallel_h

#include <tbb/task_arena.h>

namespace medialaxis
{
/// threads <= 0 runs `f` where it is called: on every core, or on as many as
/// an enclosing RunWithThreads allows (a stage's own "all cores" must not
/// escape the limit of the pipeline that runs it).
template <typename Function>
auto RunWithThreads(int threads, Function&& f) -> decltype(f())
{
  if (threads <= 0)
  {
    return f();
  }
  tbb::task_arena arena(threads);
  return arena.execute(f);
}
}

#endif
