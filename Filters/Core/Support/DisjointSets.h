// SPDX-License-Identifier: GPL-3.0-or-later
// Union-find with path halving; the smaller id becomes the root, so results
// do not depend on the order of unions.
#ifndef medialaxis_DisjointSets_h
#define medialaxis_DisjointSets_h

#include "Geometry/Types.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace medialaxis
{
struct DisjointSets
{
  std::vector<Index> Parent;
  explicit DisjointSets(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), Index(0));
  }
  Index Find(Index x)
  {
    while (this->Parent[x] != x)
    {
      this->Parent[x] = this->Parent[this->Parent[x]];
      x = this->Parent[x];
    }
    return x;
  }
  void Union(Index a, Index b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a != b)
    {
      this->Parent[std::max(a, b)] = std::min(a, b);
    }
  }
};
}

#endif
