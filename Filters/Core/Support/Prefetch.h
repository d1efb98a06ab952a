// SPDX-License-Identifier: GPL-3.0-or-later
// Cache prefetch hints for code that reads scattered records (mesh
// neighbourhoods, per-vertex quadrics): requesting them all before use lets
// their cache misses overlap. Hints only: no effect on results.
#ifndef medialaxis_Prefetch_h
#define medialaxis_Prefetch_h

#include <cstddef>

namespace medialaxis
{
/// Requests the cache line holding `address` (any address, even null).
inline void Prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#else
  (void)address;
#endif
}

/// Requests every cache line of the object at `address`.
template <typename T>
inline void PrefetchObject(const T* address)
{
  const char* bytes = reinterpret_cast<const char*>(address);
  for (std::size_t offset = 0; offset < sizeof(T); offset += 64)
  {
    Prefetch(bytes + offset);
  }
}
}

#endif
