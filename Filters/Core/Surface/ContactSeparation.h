// SPDX-License-Identifier: GPL-3.0-or-later
// Pulls apart a small contact where a surface passes through itself by a
// vertex poking through a wall: the tip of a dent that pierces the far side
// of a thin part, so that the air in the dent meets the air beyond the wall
// through a hole far smaller than any sampling could see. The solid bounded
// by such a surface has one handle more than its mesh has (the hole), and no
// medial axis of the mesh's genus exists; moving the tip back behind the wall
// restores the solid the mesh describes.
#ifndef medialaxis_ContactSeparation_h
#define medialaxis_ContactSeparation_h

#include "Mesh/PolygonMesh.h"
#include "Surface/SelfIntersection.h"

#include <string>
#include <vector>

namespace medialaxis
{
struct ContactSeparation
{
  std::vector<Point3> Points; // the input's, the piercing vertices moved
  std::size_t MovedVertices = 0;
  double LargestMove = 0.0;
  /// Empty on success; otherwise why the contact cannot be pulled apart.
  std::string Error;
};

/// For each crossing (triangles far apart on the surface), a vertex of one
/// triangle that lies in front of the other (on its outside, by the outward
/// orientation `outward` gives: +1 or -1 per triangle), over it (projecting
/// into it) while its own triangle reaches behind it, is moved straight back
/// to `gap` behind the other triangle's plane. Contacts of another kind (a
/// part pressed into another, edges crossing) are not handled: Error says
/// so, as it does when a move would exceed half the shortest edge at the
/// vertex. The caller checks that the moved surface no longer crosses itself.
ContactSeparation SeparatePiercingVertices(const std::vector<Point3>& points,
  const std::vector<Triangle>& triangles, const std::vector<signed char>& outward,
  const std::vector<TriangleCrossing>& crossings, double gap);
}

#endif
