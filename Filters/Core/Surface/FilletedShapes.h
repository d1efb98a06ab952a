// SPDX-License-Identifier: GPL-3.0-or-later
// Generated CAD-like parts whose fillet faces are known exactly, each
// triangle labelled with the fillet it lies on: the ground truths of the
// fillet detector's and the envelope fit's tests.
#ifndef medialaxis_FilletedShapes_h
#define medialaxis_FilletedShapes_h

#include "Mesh/PolygonMesh.h"

#include <array>
#include <vector>

namespace medialaxis
{
/// A generated part whose fillet faces are known exactly: FilletId[t] is the
/// fillet triangle t lies on, -1 for triangles on no fillet.
struct LabelledTriangleMesh
{
  TriangleMesh Mesh;
  std::vector<int> FilletId;
};

/// Prism along z over the rectangle sides[0] x sides[1] (centred at the
/// origin, height sides[2]) with flat, sharp-edged caps. Its four vertical
/// edges, numbered counter-clockwise from the (+x, +y) one, are rounded:
/// edge k has radius bottomRadii[k] at the bottom cap varying linearly to
/// topRadii[k] at the top (both 0: a sharp edge; different: a
/// variable-radius fillet, the exact envelope of a ball rolling between the
/// two faces whose radius varies linearly with its centre's height). FilletId
/// k labels edge k's fillet. `resolution` is the number of segments along each
/// arc; the flat parts get about 2 * resolution segments along the longest side.
LabelledTriangleMesh MakeFilletedPrism(const Point3& sides,
  const std::array<double, 4>& bottomRadii, const std::array<double, 4>& topRadii, int resolution);

/// Cylinder along z (centred at the origin) whose top and bottom rims are
/// rounded with the given fillet radii (0: a sharp rim). FilletId 0 labels
/// the top fillet, 1 the bottom one. `resolution` is the number of segments
/// along each rim's quarter-circle arc; the circles around the axis get
/// 16 * resolution segments.
LabelledTriangleMesh MakeRoundedCylinder(
  double radius, double height, double topFilletRadius, double bottomFilletRadius, int resolution);
}

#endif
