// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/CoincidentPoints.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <tuple>
#include <unordered_map>

namespace medialaxis
{
namespace
{
struct CellKey
{
  std::int64_t I, J, K;
  bool operator==(const CellKey& o) const { return I == o.I && J == o.J && K == o.K; }
};
struct CellKeyHash
{
  std::size_t operator()(const CellKey& k) const
  {
    std::uint64_t h = static_cast<std::uint64_t>(k.I) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(k.J) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(k.K) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};
}

std::vector<Index> MergeCoincidentPoints(
  const std::vector<Point3>& points, const std::vector<char>& used, double tolerance)
{
  std::vector<Index> representative(points.size(), -1);
  if (tolerance > 0.0)
  {
    // The used points sorted by (cell, index), each cell's run found through
    // an open-addressing table (no allocation per point or cell).
    struct CellPoint
    {
      CellKey Cell;
      Index Point;
    };
    std::vector<CellPoint> sorted;
    sorted.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      if (used[i])
      {
        const Point3& p = points[i];
        sorted.push_back({ { static_cast<std::int64_t>(std::floor(p[0] / tolerance)),
                             static_cast<std::int64_t>(std::floor(p[1] / tolerance)),
                             static_cast<std::int64_t>(std::floor(p[2] / tolerance)) },
          static_cast<Index>(i) });
      }
    }
    std::sort(sorted.begin(), sorted.end(),
      [](const CellPoint& x, const CellPoint& y)
      {
        return std::tie(x.Cell.I, x.Cell.J, x.Cell.K, x.Point) <
          std::tie(y.Cell.I, y.Cell.J, y.Cell.K, y.Point);
      });
    std::vector<std::size_t> runBegin;
    for (std::size_t k = 0; k < sorted.size(); ++k)
    {
      if (k == 0 || !(sorted[k].Cell == sorted[k - 1].Cell))
      {
        runBegin.push_back(k);
      }
    }
    const std::size_t runs = runBegin.size();
    runBegin.push_back(sorted.size());
    std::size_t capacity = 16;
    while (capacity < 2 * runs + 1)
    {
      capacity *= 2;
    }
    std::vector<std::int64_t> slot(capacity, -1);
    const CellKeyHash hash;
    for (std::size_t r = 0; r < runs; ++r)
    {
      std::size_t h = hash(sorted[runBegin[r]].Cell) & (capacity - 1);
      while (slot[h] >= 0)
      {
        h = (h + 1) & (capacity - 1);
      }
      slot[h] = static_cast<std::int64_t>(r);
    }
    auto findRun = [&](const CellKey& key) -> std::int64_t
    {
      for (std::size_t h = hash(key) & (capacity - 1); slot[h] >= 0; h = (h + 1) & (capacity - 1))
      {
        if (sorted[runBegin[slot[h]]].Cell == key)
        {
          return slot[h];
        }
      }
      return -1;
    };

    const double tol2 = tolerance * tolerance;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      if (!used[i])
      {
        continue;
      }
      const Point3& p = points[i];
      const CellKey key{ static_cast<std::int64_t>(std::floor(p[0] / tolerance)),
        static_cast<std::int64_t>(std::floor(p[1] / tolerance)),
        static_cast<std::int64_t>(std::floor(p[2] / tolerance)) };
      // The smallest earlier representative within the tolerance, in the
      // first of the 27 cells around p that holds one.
      Index found = -1;
      for (int dx = -1; dx <= 1 && found < 0; ++dx)
      {
        for (int dy = -1; dy <= 1 && found < 0; ++dy)
        {
          for (int dz = -1; dz <= 1 && found < 0; ++dz)
          {
            const std::int64_t run = findRun({ key.I + dx, key.J + dy, key.K + dz });
            if (run < 0)
            {
              continue;
            }
            for (std::size_t k = runBegin[run]; k < runBegin[run + 1]; ++k)
            {
              const Index j = sorted[k].Point;
              if (j >= static_cast<Index>(i))
              {
                break;
              }
              const Point3 d = (points[j] - p);
              if (representative[j] == j && Dot(d, d) <= tol2)
              {
                found = j;
                break;
              }
            }
          }
        }
      }
      representative[i] = found >= 0 ? found : static_cast<Index>(i);
    }
    return representative;
  }

  struct ExactHash
  {
    std::size_t operator()(const Point3& p) const
    {
      std::size_t h = 0;
      for (double c : p)
      {
        h = h * 1000003u ^ std::hash<double>()(c == 0.0 ? 0.0 : c); // -0 == +0
      }
      return h;
    }
  };
  std::unordered_map<Point3, Index, ExactHash> seen;
  seen.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (used[i])
    {
      representative[i] = seen.emplace(points[i], static_cast<Index>(i)).first->second;
    }
  }
  return representative;
}
}
