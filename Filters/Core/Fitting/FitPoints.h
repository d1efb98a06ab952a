// SPDX-License-Identifier: GPL-3.0-or-later
// The surface points a final fit of the medial mesh (EnvelopeFit.h) pulls the
// envelope through: the sites, and the corners where three cells of their
// restricted Voronoi diagram meet. The corners are the surface points
// farthest from every site, where an envelope built from the sites falls
// shortest, so they carry the largest distances at three times the cost of
// the sites alone (every polygon vertex would be ten times).
#ifndef medialaxis_FitPoints_h
#define medialaxis_FitPoints_h

#include "Voronoi/RestrictedVoronoi.h"

#include <vector>

namespace medialaxis
{
struct WeightedPoints
{
  std::vector<Point3> Points;
  /// The surface area each point stands for; they add up to the area.
  std::vector<double> Weights;
};

/// Sites (weight: half their cell's area) and the corners shared by three
/// cells inside one surface triangle (weight: a quarter of the mean area of
/// the three cells: a cell has six corners on average, each shared by three
/// cells, so its corners get the other half of its area). `rvd` is the
/// diagram of `sites`. Without `corners`, or without PolygonTriangle, only
/// the sites are given, each with its cell's area.
WeightedPoints FitPoints(
  const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites, bool corners = true);
}

#endif
