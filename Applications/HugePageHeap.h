// SPDX-License-Identifier: GPL-3.0-or-later
// Puts the process's heap on transparent huge pages, for the command-line
// programs: the pipeline touches hundreds of megabytes of fresh memory, and
// on virtual machines where a page fault is dear, faulting it in 4 KB at a
// time costs a quarter of the run (bunny, 10,000 samples: 27,800 faults
// against 8,600). glibc (2.35 on) does it when started with
// GLIBC_TUNABLES=glibc.malloc.hugetlb=1, a setting read only at start-up:
// so the program starts itself again once with it. Embedding applications
// (ParaView, pvpython, VTK programs) get the same by setting it themselves.
#ifndef MedialAxis_HugePageHeap_h
#define MedialAxis_HugePageHeap_h

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
/// True when the heap was put on huge pages by the GLIBC_TUNABLES setting.
inline bool HugePageHeapRequested()
{
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return tunables != nullptr && std::strstr(tunables, "glibc.malloc.hugetlb=1") != nullptr;
}

/// Starts the program again with glibc's huge-page heap unless it runs with
/// it (or with any glibc.malloc.hugetlb setting of the user's), the kernel
/// has transparent huge pages turned off, or MEDIALAXIS_HUGE_PAGES=0. Call
/// first thing in main, before any output; returns when nothing is to do or
/// the restart failed (the program then runs with the default heap).
inline void UseHugePageHeap(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__) &&                                                    \
  (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35))
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const char* wanted = std::getenv("MEDIALAXIS_HUGE_PAGES");
  if ((wanted != nullptr && std::strcmp(wanted, "0") == 0) ||
    (tunables != nullptr && std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr))
  {
    return;
  }
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  const std::string modes{ std::istreambuf_iterator<char>(mode), std::istreambuf_iterator<char>() };
  if (modes.find("[always]") == std::string::npos && modes.find("[madvise]") == std::string::npos)
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
  const std::string value = tunables != nullptr && *tunables != '\0'
    ? std::string(tunables) + ":glibc.malloc.hugetlb=1"
    : std::string("glibc.malloc.hugetlb=1");
  const std::string before = tunables != nullptr ? tunables : "";
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0)
  {
    execv(self, argv);
    // Still here: the restart failed; the environment says so no longer.
    if (tunables != nullptr)
    {
      setenv("GLIBC_TUNABLES", before.c_str(), 1);
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
