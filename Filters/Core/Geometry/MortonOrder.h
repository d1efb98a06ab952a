// SPDX-License-Identifier: GPL-3.0-or-later
// Points ordered along a Morton (Z-order) curve: points close in space end up
// close in the order, so that passes over them touch neighbours one after the
// other (caches, search trees).
#ifndef medialaxis_MortonOrder_h
#define medialaxis_MortonOrder_h

#include "Geometry/Types.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace medialaxis
{
/// The indices 0..n-1 sorted by the Morton code of pointOf(i) on a 2^21 grid
/// over the points' bounding box (ties by index: deterministic).
template <typename PointOf>
std::vector<std::uint32_t> MortonOrder(std::size_t n, PointOf&& pointOf)
{
  Point3 lo{ 0.0, 0.0, 0.0 }, hi{ 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point3 p = pointOf(i);
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = i == 0 ? p[k] : std::min(lo[k], p[k]);
      hi[k] = i == 0 ? p[k] : std::max(hi[k], p[k]);
    }
  }
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300 });
  auto spread = [](std::uint64_t v) // 21 bits -> every third bit
  {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point3 p = pointOf(i);
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k)
    {
      const double u = (p[k] - lo[k]) / extent * 2097151.0;
      code |= spread(static_cast<std::uint64_t>(std::clamp(u, 0.0, 2097151.0))) << k;
    }
    keys[i] = { code, static_cast<std::uint32_t>(i) };
  }
  // Keys are distinct (the index is part of them): any sort gives this order.
  tbb::parallel_sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    order[i] = keys[i].second;
  }
  return order;
}
}

#endif
