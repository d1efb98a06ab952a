// SPDX-License-Identifier: GPL-3.0-or-later
// Building blocks of the generated test shapes (AnalyticShapes,
// FilletedShapes): quads, planar caps and surfaces of revolution.
#ifndef medialaxis_ShapeBuilding_h
#define medialaxis_ShapeBuilding_h

#include "Mesh/PolygonMesh.h"

#include <array>
#include <vector>

namespace medialaxis
{
/// Splits quad (a, b, c, d), given counter-clockwise seen from outside, along
/// its shorter diagonal.
void AddQuad(TriangleMesh& mesh, Index a, Index b, Index c, Index d);

/// Rings of a star-shaped planar cap at height z, from its outline (ring 0,
/// whose point ids are given) inward to the centre `centre`: quads between
/// rings, a fan at the centre. `up` orients the cap's normal to +z. Label
/// -1 is appended to `labels` for every triangle added.
void AddCap(TriangleMesh& mesh, const std::vector<Index>& outline, const Point3& centre, int rings,
  bool up, std::vector<int>* labels);

/// The surface of revolution around z of `profile` (distance from the axis,
/// z), given from the top pole (0, top) to the bottom pole (0, bottom), both
/// excluded, with `around` segments per circle. With labels, triangle labels
/// follow: -1 at the poles, labelBefore[i + 1] between profile points i and
/// i + 1.
TriangleMesh Revolve(const std::vector<std::array<double, 2>>& profile, double top, double bottom,
  int around, const std::vector<int>* labelBefore = nullptr, std::vector<int>* labels = nullptr);
}

#endif
