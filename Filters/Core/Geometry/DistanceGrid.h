// SPDX-License-Identifier: GPL-3.0-or-later
// A signed distance sampled on a regular grid, exact only in a narrow band
// around its zero level set: what a closed surface is contoured from (the
// union of a medial mesh's primitives, the union of generalized
// primitives).
#ifndef medialaxis_DistanceGrid_h
#define medialaxis_DistanceGrid_h

#include "Geometry/BoxTree.h"
#include "Geometry/Types.h"

#include <array>
#include <functional>
#include <vector>

namespace medialaxis
{
/// F on a regular grid, x fastest. The grid extends two spacings beyond the
/// given bounds so that the zero level set is closed.
struct DistanceGrid
{
  Point3 Origin{ 0, 0, 0 };
  double Spacing = 0.0;
  std::array<int, 3> Dimensions{ 0, 0, 0 };
  /// Exact F within one block (see below) of the zero level set; elsewhere
  /// a value of the right sign whose magnitude exceeds one spacing.
  std::vector<float> Values;
  std::size_t ExactPoints = 0;
  bool Aborted = false;
};

/// Samples `signedDistance` (negative inside) over `bounds`, which must
/// contain its zero level set, with the given spacing. Blocks of
/// blockSide^3 points are filled from their centre's value when it proves
/// that none of their points lies within a spacing of the level set (small
/// blocks: a thinner band, more centres evaluated), so |F(x)| must never
/// exceed the distance from x to the level set (a distance or a lower bound
/// of it with the right sign). Parallel and deterministic. Returns an empty
/// grid for empty bounds or a spacing that is not positive.
DistanceGrid SampleNarrowBand(const Box& bounds, double spacing,
  const std::function<double(const Point3&)>& signedDistance,
  const std::function<bool(double)>& progress = nullptr, int blockSide = 8);

/// F made cheaper for the points within `radius` of `centre` (a block's),
/// e.g. by deciding once which parts of a union are too far to matter.
using LocalDistance =
  std::function<std::function<double(const Point3&)>(const Point3& centre, double radius)>;

/// SampleNarrowBand with F localized per block: `local(centre, radius)` is
/// called once per block and evaluated at its centre and, when the block is
/// near the level set, at each of its points.
DistanceGrid SampleNarrowBandLocal(const Box& bounds, double spacing, const LocalDistance& local,
  const std::function<bool(double)>& progress = nullptr, int blockSide = 8);
}

#endif
