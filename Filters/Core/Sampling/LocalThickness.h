// SPDX-License-Identifier: GPL-3.0-or-later
// Local thickness of a closed surface: how far the solid reaches behind a
// point, measured by rays cast inwards in a narrow cone around the inward
// normal (the shape diameter function of Shapira et al., "Consistent mesh
// partitioning and skeletonisation using the shape diameter function",
// 2008). Its median over the cone is robust to a ray that slips along a
// crease or through a gap between triangles.
#ifndef medialaxis_LocalThickness_h
#define medialaxis_LocalThickness_h

#include "Mesh/PolygonMesh.h"
#include "Mesh/TriangleLocator.h"

#include <limits>
#include <vector>

namespace medialaxis
{
struct ThicknessOptions
{
  /// Rays per point: one along the inward normal, the others evenly around
  /// it at ConeAngle.
  int Rays = 5;
  double ConeAngleDegrees = 25.0;
  /// Rays end here: a ray that meets nothing nearer counts as this long.
  double MaximumThickness = std::numeric_limits<double>::infinity();
};

/// Thickness at points on the surface: points[i] lies on triangle
/// triangles[i]: the median over the rays of the depth (along the normal)
/// of the first crossing that leaves the solid. Infinity where fewer than
/// half of the rays give one (a surface that is not closed). The surface must be closed and
/// oriented outwards; the locator indexes it. Parallel; the result does not depend on the threads.
std::vector<double> EstimateLocalThickness(const TriangleMesh& surface,
  const TriangleLocator& locator, const std::vector<Point3>& points,
  const std::vector<Index>& triangles, const ThicknessOptions& options = {});
}

#endif
