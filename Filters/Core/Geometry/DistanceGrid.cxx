// SPDX-License-Identifier: GPL-3.0-or-later
#include "Geometry/DistanceGrid.h"

#include "Geometry/Vec3.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace medialaxis
{
DistanceGrid SampleNarrowBand(const Box& bounds, double spacing,
  const std::function<double(const Point3&)>& signedDistance,
  const std::function<bool(double)>& progress, int blockSide)
{
  return SampleNarrowBandLocal(
    bounds, spacing, [&signedDistance](const Point3&, double) { return signedDistance; }, progress,
    blockSide);
}

DistanceGrid SampleNarrowBandLocal(const Box& bounds, double spacing, const LocalDistance& local,
  const std::function<bool(double)>& progress, int blockSide)
{
  DistanceGrid grid;
  if (bounds.IsEmpty() || !(spacing > 0.0))
  {
    return grid;
  }
  grid.Spacing = spacing;
  for (int k = 0; k < 3; ++k)
  {
    grid.Origin[k] = bounds.Lo[k] - 2.0 * spacing;
    grid.Dimensions[k] = static_cast<int>(std::ceil((bounds.Hi[k] - bounds.Lo[k]) / spacing)) + 5;
  }
  const std::array<int, 3> dims = grid.Dimensions;
  grid.Values.resize(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]);

  const int B = std::max(2, blockSide);
  const std::array<int, 3> blocks{ (dims[0] + B - 1) / B, (dims[1] + B - 1) / B,
    (dims[2] + B - 1) / B };
  const double halfDiagonal = 0.5 * std::sqrt(3.0) * (B - 1) * spacing;
  auto point = [&](int i, int j, int k)
  {
    return Point3{ grid.Origin[0] + i * spacing, grid.Origin[1] + j * spacing,
      grid.Origin[2] + k * spacing };
  };
  std::vector<std::size_t> exact(static_cast<std::size_t>(blocks[0]) * blocks[1] * blocks[2], 0);
  for (int bz = 0; bz < blocks[2]; ++bz)
  {
    tbb::parallel_for(tbb::blocked_range<int>(0, blocks[0] * blocks[1]),
      [&](const tbb::blocked_range<int>& r)
      {
        for (int b = r.begin(); b < r.end(); ++b)
        {
          const int bx = b % blocks[0], by = b / blocks[0];
          const int i0 = bx * B, j0 = by * B, k0 = bz * B;
          const int i1 = std::min(i0 + B, dims[0]), j1 = std::min(j0 + B, dims[1]),
                    k1 = std::min(k0 + B, dims[2]);
          const Point3 centre = point(i0, j0, k0) + (0.5 * (B - 1) * spacing) * Point3{ 1, 1, 1 };
          const std::function<double(const Point3&)> signedDistance = local(centre, halfDiagonal);
          const double f = signedDistance(centre);
          // Far from the level set: every point of the block has |F| > spacing.
          const bool far = std::abs(f) > halfDiagonal + 1.5 * spacing;
          const float fill = static_cast<float>(f > 0.0 ? f - halfDiagonal : f + halfDiagonal);
          std::size_t count = 0;
          for (int k = k0; k < k1; ++k)
          {
            for (int j = j0; j < j1; ++j)
            {
              for (int i = i0; i < i1; ++i)
              {
                const std::size_t id = (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i;
                if (far)
                {
                  grid.Values[id] = fill;
                  continue;
                }
                grid.Values[id] = static_cast<float>(signedDistance(point(i, j, k)));
                ++count;
              }
            }
          }
          exact[(static_cast<std::size_t>(bz) * blocks[1] + by) * blocks[0] + bx] = count;
        }
      });
    if (progress && !progress(double(bz + 1) / blocks[2]))
    {
      grid.Aborted = true;
      return grid;
    }
  }
  for (std::size_t c : exact)
  {
    grid.ExactPoints += c;
  }
  return grid;
}
}
