// SPDX-License-Identifier: GPL-3.0-or-later
// The exact unsigned distance to a triangle surface (open or closed,
// manifold or not), sampled on a regular grid.
#ifndef medialaxis_UnsignedDistanceField_h
#define medialaxis_UnsignedDistanceField_h

#include "Geometry/BoxTree.h"
#include "Mesh/PolygonMesh.h"
#include "Udf/RegularField.h"

#include <array>
#include <functional>

namespace medialaxis
{
/// A grid of `dimensions` points (at least 2 per axis) with cubic cells,
/// centred on `bounds`, leaving `padding` free cells around them along the
/// axis that needs the largest cells (fewer when the dimensions are too
/// small for that). Values are left empty; Spacing is 0 for empty bounds.
RegularField GridAroundBox(const Box& bounds, std::array<int, 3> dimensions, int padding);

/// Fills field.Values with the distance from each grid point to the nearest
/// triangle (exact, through the mesh's box tree). Parallel over z-slices and
/// deterministic. `progress(fraction)` may return true to stop early (the
/// values are then incomplete and the function returns false).
bool SampleUnsignedDistance(const TriangleMesh& surface, RegularField& field,
  const std::function<bool(double)>& progress = nullptr);
}

#endif
