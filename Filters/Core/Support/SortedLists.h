// SPDX-License-Identifier: GPL-3.0-or-later
// Walks over sorted id lists (neighbour lists, Atlases).
#ifndef medialaxis_SortedLists_h
#define medialaxis_SortedLists_h

#include <cstddef>

namespace medialaxis
{
/// Calls `shared(x)` for every value in both sorted, duplicate-free lists,
/// in increasing order (std::set_intersection without an output buffer).
template <typename List, typename Function>
void ForEachShared(const List& a, const List& b, Function&& shared)
{
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size())
  {
    if (a[i] < b[j])
    {
      ++i;
    }
    else if (b[j] < a[i])
    {
      ++j;
    }
    else
    {
      shared(a[i]);
      ++i;
      ++j;
    }
  }
}

/// Calls `each(x, inBoth)` for every value in either sorted, duplicate-free
/// list, once, in increasing order (std::set_union without an output buffer).
template <typename List, typename Function>
void ForEachInUnion(const List& a, const List& b, Function&& each)
{
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size())
  {
    if (j == b.size() || (i < a.size() && a[i] < b[j]))
    {
      each(a[i++], false);
    }
    else if (i == a.size() || b[j] < a[i])
    {
      each(b[j++], false);
    }
    else
    {
      each(a[i], true);
      ++i;
      ++j;
    }
  }
}
}

#endif
