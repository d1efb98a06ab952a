// SPDX-License-Identifier: GPL-3.0-or-later
// Triangles no later stage may see: zero-area needles and repeated vertex
// sets (steps 3 and 4 of the surface preparation).
#ifndef medialaxis_DegenerateTriangles_h
#define medialaxis_DegenerateTriangles_h

#include "Mesh/PolygonMesh.h"

#include <cstddef>
#include <vector>

namespace medialaxis
{
/// Removes zero-area "needles" (three distinct, nearly collinear vertices):
/// each is absorbed by splitting its neighbour across the needle's longest
/// edge at the middle vertex, which keeps the surface closed; needles that
/// cannot be absorbed are dropped. Returns the needles removed and adds the
/// neighbours split to `splitNeighbours`.
std::size_t RemoveNeedles(const std::vector<Point3>& points, std::vector<Triangle>& triangles,
  std::size_t& splitNeighbours);

/// Drops every triangle whose vertex set repeats an earlier triangle's (in
/// any order); returns how many were dropped. The order of the rest is kept.
std::size_t RemoveDuplicateTriangles(std::vector<Triangle>& triangles);
}

#endif
