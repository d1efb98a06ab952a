// SPDX-License-Identifier: GPL-3.0-or-later
// The tidying of the mid-surface's triangles (MidSurface.h): one orientation
// per orientable piece, and the folds that the fins of the discrete medial
// axis leave on a wall's plane untangled, or their tips found where they
// stay; with the triangle helpers ExtractMidSurface shares (AreaNormal,
// EdgeFaces).
#ifndef medialaxis_MidSurfaceFolds_h
#define medialaxis_MidSurfaceFolds_h

#include "Geometry/Vec3.h"
#include "Structure/WallProbe.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace medialaxis
{
// Twice the area of triangle t, along its normal.
inline Point3 AreaNormal(const std::vector<Point3>& points, const std::array<Index, 3>& t)
{
  return Cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
}

using EdgeFaceMap = std::map<std::array<Index, 2>, std::vector<Index>>;

// The faces on each edge (a, b), a < b.
EdgeFaceMap EdgeFaces(const std::vector<std::array<Index, 3>>& faces);

// Flips faces so that faces across edges of exactly two agree (one
// orientation per orientable piece).
void OrientConsistently(std::vector<std::array<Index, 3>>& faces);

// Folds: where the discrete medial axis had a fin on a wall, its triangles
// land upside down on the wall's plane. The points of folded triangles
// (neighbours across an edge of two that face opposite ways) move towards
// the mean of their neighbours within their wall's plane (along the
// planes' common line at a junction), a round at a time, until nothing is
// folded or `rounds` are spent. Returns the folded edges left, and marks the
// points moved.
std::size_t UntangleFolds(std::vector<Point3>& points,
  const std::vector<std::array<Index, 3>>& faces, const std::vector<PlaneSet>& planes, int rounds,
  std::vector<std::uint8_t>& moved);

// Of each pair of triangles across an edge of two that face opposite ways,
// the smaller (a fin's tip).
std::vector<Index> FoldedTips(
  const std::vector<Point3>& points, const std::vector<std::array<Index, 3>>& faces);
}

#endif
