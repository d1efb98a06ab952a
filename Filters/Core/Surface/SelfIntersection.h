// SPDX-License-Identifier: GPL-3.0-or-later
// Exact self-intersection test of a closed triangle mesh. Kept in a
// translation unit of its own: CGAL's polygon mesh processing is heavy to
// compile and needs -frounding-math.
#ifndef medialaxis_SelfIntersection_h
#define medialaxis_SelfIntersection_h

#include "Mesh/PolygonMesh.h"

#include <vector>

namespace medialaxis
{
/// Two triangles that cross, and a box around where they meet (the common
/// part of their bounding boxes).
struct TriangleCrossing
{
  Index A, B; // indices into the triangles, A < B
  Point3 Lo, Hi;
};

/// The pairs of triangles that meet anywhere other than in the edge or vertex
/// they share (exact predicates), sorted by (A, B). `triangles` must form a
/// manifold, consistently oriented mesh over `points`; unused points are
/// ignored. About 0.3 s per 100,000 triangles; the last four answers are
/// remembered by content, so a surface tested again costs a hash.
std::vector<TriangleCrossing> FindSelfIntersections(
  const std::vector<Point3>& points, const std::vector<Triangle>& triangles);
}

#endif
