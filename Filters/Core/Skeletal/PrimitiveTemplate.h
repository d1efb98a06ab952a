// SPDX-License-Identifier: GPL-3.0-or-later
// Templates of the generalized enveloping primitives of the Medial Skeletal
// Diagram (paper 004, section 5.2): a mesh of the boundary of a small
// neighbourhood of one skeletal element, each vertex j a point p_j of the
// element and a unit direction d_j in which p_j is the element's closest
// point. A fitted primitive moves vertex j to p_j + r_j d_j.
#ifndef medialaxis_PrimitiveTemplate_h
#define medialaxis_PrimitiveTemplate_h

#include "Geometry/Vec3.h"
#include "Mesh/PolygonMesh.h"

#include <array>
#include <vector>

namespace medialaxis
{
/// The kind of skeletal element a template belongs to.
enum class SkeletalElement : int
{
  Vertex = 0,
  Edge = 1,
  Triangle = 2
};

struct PrimitiveTemplate
{
  SkeletalElement Element = SkeletalElement::Vertex;
  std::vector<Point3> Base;      // p_j, on the element
  std::vector<Point3> Direction; // d_j, unit
  std::vector<Triangle> Triangles;
};

/// A vertex element at `centre`: the unit sphere of directions, an
/// icosahedron subdivided `subdivisions` times (10 * 4^s + 2 vertices: 642
/// at 3, 2,562 at 4).
PrimitiveTemplate MakeVertexTemplate(const Point3& centre, int subdivisions);

/// An edge element from a to b: the circles of directions perpendicular to
/// it at rings spaced at most `spacing` apart along it (at least the two
/// ends), `around` directions each, and a hemisphere of directions beyond
/// each end (`around` / 4 latitude rings and a pole). Throws
/// std::invalid_argument for a degenerate edge or fewer than 8 directions around.
PrimitiveTemplate MakeEdgeTemplate(const Point3& a, const Point3& b, int around, double spacing);

/// A triangle element abc (normal n = (b - a) x (c - a), normalised): +n and
/// -n over the triangle (two triangular faces, subdivided so that no edge
/// is longer than `spacing`), a half circle of directions from +n to -n
/// beyond each edge (half-cylinder walls), and at each corner the spherical
/// wedge of directions between the two edges' (its angle is the corner's
/// exterior angle). `around` sets the angular resolution as for the edge
/// template. Throws std::invalid_argument for a degenerate triangle.
PrimitiveTemplate MakeTriangleTemplate(
  const Point3& a, const Point3& b, const Point3& c, int around, double spacing);

/// The template of an element of the given kind from its corners (the
/// first one, two or three), with the resolutions above.
PrimitiveTemplate MakeElementTemplate(SkeletalElement element, const std::array<Point3, 3>& corners,
  int vertexSubdivisions, int around, double spacing);

/// The radius of the template's vertices at which they become the
/// primitive's surface: Base + radius * Direction.
std::vector<Point3> PrimitivePoints(
  const PrimitiveTemplate& shape, const std::vector<double>& radius);
}

#endif
