// SPDX-License-Identifier: GPL-3.0-or-later
// A closed surface that passes through itself, or shells that cross each
// other, resolved into the closed outer boundary of the solid they enclose.
// Kept in a translation unit of its own (CGAL's corefinement: heavy to
// compile, needs -frounding-math).
#ifndef medialaxis_SelfIntersectionRepair_h
#define medialaxis_SelfIntersectionRepair_h

#include "Mesh/PolygonMesh.h"
#include "Surface/SelfIntersection.h"

#include <string>
#include <vector>

namespace medialaxis
{
struct SelfIntersectionRepairResult
{
  /// Empty when repaired; otherwise why not.
  std::string Error;
  /// The boundary of the union of the solids the shells enclose: closed,
  /// outward where the input was.
  TriangleMesh Surface;
  /// Per triangle of Surface: the input triangle it is a piece of.
  std::vector<Index> InputTriangle;
  /// Area of the input's parts that lay inside the solid and were removed.
  double RemovedArea = 0.0;
  /// Set with Error when the crossings were resolved but what came out is
  /// not the boundary of one solid (a part turned inside out, or patches
  /// misread where neighbouring triangles fold over each other): the inside
  /// itself is in doubt, and no other repair should guess it.
  bool InsideInDoubt = false;
};

/// Refines the triangles of `mesh` along the curves where they cross
/// (exact predicates; the new points rounded to doubles), removes the parts
/// that lie inside the solid and stitches the rest into one closed surface
/// (CGAL's autorefine_and_remove_self_intersections). `mesh` must be closed,
/// manifold and every shell oriented outward (a shell's own signed volume
/// positive); its unused points are ignored. `crossings` (as
/// FindSelfIntersections gives them) are looked at first: triangles that
/// cross in a common plane, which CGAL 5.5's autorefinement does not survive
/// (it crashes in its constrained triangulation), give an Error at once.
SelfIntersectionRepairResult RepairSelfIntersections(
  const TriangleMesh& mesh, const std::vector<TriangleCrossing>& crossings = {});
}

#endif
