// SPDX-License-Identifier: GPL-3.0-or-later
// The surface points a final fit of the medial mesh (EnvelopeFit.h) pulls the
// envelope through: the sites, and the corners where three cells of their
// restricted Voronoi diagram meet. The corners are the surface points
// farthest from every site, where an envelope built from the sites falls
// shortest, so they carry the largest distances at three times the cost of
// the sites alone (every polygon vertex would be ten times).
#ifndef medialaxis_FitPoints_h
#define medialaxis_FitPoints_h

#include "Fitting/EnvelopeFit.h"
#include "Voronoi/RestrictedVoronoi.h"

#include <vector>

namespace medialaxis
{
struct FitPointsOptions
{
  /// Fit through the corners too (else the sites alone).
  bool Corners = true;
  /// Give every distinct polygon vertex as the surface for the test of balls
  /// reaching out of it (else the fit points serve): exact along the
  /// surface's sharp edges, where CAD parts' balls poke out, but a k-d tree
  /// of several points per surface triangle.
  bool DenseSurface = false;
};

/// Sites (weight: half their cell's area) and the corners shared by three
/// cells inside one surface triangle (weight: a quarter of the mean area of
/// the three cells: a cell has six corners on average, each shared by three
/// cells, so its corners get the other half of its area). `rvd` is the
/// diagram of `sites`. Without Corners, or without PolygonTriangle, only
/// the sites are given, each with its cell's area. The weights add up to the
/// area. With DenseSurface, Surface holds the sites and every distinct
/// polygon vertex of the diagram (they include the points of the surface's
/// edges and corners).
FitTarget FitPoints(const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const FitPointsOptions& options = FitPointsOptions());
}

#endif
