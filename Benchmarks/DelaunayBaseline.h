// SPDX-License-Identifier: GPL-3.0-or-later
// A reference point for the benchmark: CGAL's Delaunay triangulation of the
// samples alone, the least that any Voronoi-based medial axis pays (the
// Voronoi stage adds the inside tests and the medial faces to it).
#ifndef medialaxis_DelaunayBaseline_h
#define medialaxis_DelaunayBaseline_h

#include "Geometry/Types.h"

#include <cstddef>
#include <vector>

namespace medialaxis
{
/// Triangulates `points` (CGAL's Delaunay_triangulation_3 with the same
/// kernel as the library) and returns its number of finite cells.
std::size_t DelaunayCellCount(const std::vector<Point3>& points);
}

#endif
