// SPDX-License-Identifier: GPL-3.0-or-later
// Merging coincident points of a triangle soup (step 2 of PrepareSurface).
#ifndef medialaxis_CoincidentPoints_h
#define medialaxis_CoincidentPoints_h

#include "Geometry/Types.h"

#include <vector>

namespace medialaxis
{
/// Maps every used point to the first earlier used point within `tolerance`
/// (a grid of cell size `tolerance`, the first of the 27 cells around the
/// point that holds one; exactly equal coordinates when `tolerance` is 0),
/// or to itself; -1 for unused points. Written by hand because it must be
/// deterministic in input order.
std::vector<Index> MergeCoincidentPoints(
  const std::vector<Point3>& points, const std::vector<char>& used, double tolerance);
}

#endif
