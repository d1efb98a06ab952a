// SPDX-License-Identifier: GPL-3.0-or-later
// Clean polylines from a noisy set of medial edges that trace curves (e.g.
// fillet centre lines): snapped to a fraction of the ball radius, small
// cycles opened, short spurs pruned, small gaps bridged, then chained and
// split at junctions and sharp turns.
//
// Written by hand: the graph is small (edges along curves), and the
// cleaning rules are scaled by the ball radius at each vertex, which no
// general graph library offers.
#ifndef medialaxis_CentreLineGraph_h
#define medialaxis_CentreLineGraph_h

#include "Mesh/MedialMesh.h"

#include <array>
#include <vector>

namespace medialaxis
{
struct CentreLine
{
  std::vector<Index> Vertices; // a closed line does not repeat its first vertex
  bool Closed = false;
};

struct CentreLineGraphOptions
{
  /// Vertices closer than this many ball radii are snapped together first
  /// (fins side by side along one line become one path).
  double SnapRadii = 0.25;
  /// Cycles shorter than this many ball radii are noise (fins side by side).
  double SmallCycleRadii = 4.0;
  /// Branches from a free end to a junction shorter than this many radii
  /// are spurs.
  double SpurRadii = 2.0;
  /// Free ends are joined to a vertex up to this many radii away, in the
  /// direction the line was heading (within GapAngle radians), or to one
  /// closer than TouchRadii in any direction (ends side by side).
  double GapRadii = 3.0;
  double TouchRadii = 0.5;
  double GapAngle = 0.7853981633974483; // 45 degrees
  /// Lines are split where they turn by more than this (radians), measured
  /// over at least one ball radius on each side.
  double SplitAngle = 0.8726646259971648; // 50 degrees
};

/// `edges` index `centres` and `radii`. Deterministic (independent of the
/// order of equal-length edges only through their index order).
std::vector<CentreLine> TraceCentreLines(const std::vector<std::array<Index, 2>>& edges,
  const std::vector<Point3>& centres, const std::vector<double>& radii,
  const CentreLineGraphOptions& options = CentreLineGraphOptions());
}

#endif
