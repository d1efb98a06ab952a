// SPDX-License-Identifier: GPL-3.0-or-later
// Tunes glibc's heap for the command-line programs. The pipeline allocates
// and frees hundreds of megabytes in large blocks; by default glibc maps
// every block above a sliding threshold afresh and unmaps it when freed, so
// the kernel faults the memory in (and zeroes it) again and again, 4 KB at a
// time. On virtual machines where a page fault is dear that was a third of
// the run (bunny, 10,000 samples to 1,000 spheres: 0.67 s against 0.44 s).
// The settings below keep blocks of up to 32 MB in the heap, keep freed
// memory for reuse, grow the heap 64 MB at a time and back it with
// transparent huge pages. glibc reads them only at start-up (environment
// variable GLIBC_TUNABLES, glibc 2.35 on), so the program starts itself
// again once with them. Embedding applications (ParaView, pvpython, VTK
// programs) get the same by starting with HeapTunables() in GLIBC_TUNABLES.
// Not kept: one heap for all threads (arena_max=1) lowered igea's peak at
// 50,000 samples on two threads from 362 to 294-300 MB, but made the bunny
// at 200,000 samples 20% slower: the parallel stages allocate enough to
// contend for a single heap.
#ifndef MedialAxis_HeapTuning_h
#define MedialAxis_HeapTuning_h

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#if defined(__linux__)
#include <unistd.h>
#endif

namespace medialaxis
{
/// The glibc tunables the programs run with (huge pages only where the
/// kernel offers them to madvise).
inline std::string HeapTunables()
{
  std::string tunables = "glibc.malloc.mmap_threshold=33554432"
                         ":glibc.malloc.trim_threshold=4294967296"
                         ":glibc.malloc.top_pad=67108864";
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  const std::string modes{ std::istreambuf_iterator<char>(mode), std::istreambuf_iterator<char>() };
  if (modes.find("[always]") != std::string::npos || modes.find("[madvise]") != std::string::npos)
  {
    tunables += ":glibc.malloc.hugetlb=1";
  }
  return tunables;
}

/// True when the process runs with heap tunables (ours or the user's).
inline bool HeapTuned()
{
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return tunables != nullptr && std::strstr(tunables, "glibc.malloc.") != nullptr;
}

/// Starts the program again with HeapTunables() added to GLIBC_TUNABLES,
/// unless the process has heap tunables already (the user's win), runs
/// under valgrind or AddressSanitizer (their own allocators), or
/// MEDIALAXIS_TUNE_HEAP=0. Call first thing in main, before any output;
/// returns when nothing is to do or the restart failed (the program then
/// runs with the default heap).
inline void TuneHeap(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) &&                  \
  (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35))
  const char* wanted = std::getenv("MEDIALAXIS_TUNE_HEAP");
  // Not under valgrind either: the restarted program would leave it.
  const char* preload = std::getenv("LD_PRELOAD");
  if ((wanted != nullptr && std::strcmp(wanted, "0") == 0) || HeapTuned() ||
    (preload != nullptr && std::strstr(preload, "vgpreload") != nullptr))
  {
    return;
  }
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof(self) - 1);
  if (length <= 0)
  {
    return;
  }
  self[length] = '\0';
  const char* before = std::getenv("GLIBC_TUNABLES");
  const std::string previous = before != nullptr ? before : "";
  const std::string value = previous.empty() ? HeapTunables() : previous + ":" + HeapTunables();
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0)
  {
    execv(self, argv);
    // Still here: the restart failed; the environment says so no longer.
    if (before != nullptr)
    {
      setenv("GLIBC_TUNABLES", previous.c_str(), 1);
    }
    else
    {
      unsetenv("GLIBC_TUNABLES");
    }
  }
#else
  (void)argv;
#endif
}
}

#endif
