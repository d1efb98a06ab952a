// SPDX-License-Identifier: GPL-3.0-or-later
// Edge adjacency of a triangle mesh and sharp-feature classification of its
// edges by dihedral angle.
#ifndef medialaxis_TriangleAdjacency_h
#define medialaxis_TriangleAdjacency_h

#include "Mesh/PolygonMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace medialaxis
{
/// One directed use of an undirected edge by a triangle.
struct HalfEdge
{
  Index Lo, Hi; // sorted vertex ids
  Index Tri;
  bool Forward; // the triangle traverses Lo -> Hi
  // Forward last: a triangle with a repeated vertex uses one edge twice, and
  // the order of its two uses must not depend on the sorting algorithm.
  bool operator<(const HalfEdge& o) const
  {
    return Lo != o.Lo
      ? Lo < o.Lo
      : (Hi != o.Hi ? Hi < o.Hi : (Tri != o.Tri ? Tri < o.Tri : Forward < o.Forward));
  }
};

/// All half-edges, sorted so that the uses of one edge are adjacent.
std::vector<HalfEdge> SortedHalfEdges(const std::vector<Triangle>& triangles);

enum class EdgeFeature : std::uint8_t
{
  None = 0,
  Convex = 1,  // dihedral angle below pi - featureAngle (a sharp ridge)
  Concave = 2, // dihedral angle above pi + featureAngle (a sharp valley)
};

/// Per triangle and per edge k (from vertex k to vertex k + 1): the triangle
/// across it (-1 on a boundary or non-manifold edge) and its feature class.
struct TriangleAdjacency
{
  std::vector<std::array<Index, 3>> Neighbour;
  std::vector<std::array<EdgeFeature, 3>> Feature;
};

/// `featureAngle` in radians: the tolerance phi of the dihedral-angle test
/// on the triangles' own normals (Surface/FeatureNormals.h: FeatureAdjacency
/// confirms convex edges on filtered normals).
TriangleAdjacency ComputeTriangleAdjacency(const TriangleMesh& mesh, double featureAngle);

/// Unit normal of triangle t (zero for a degenerate triangle).
Point3 TriangleNormal(const TriangleMesh& mesh, Index t);

/// Flips every triangle when the volume the mesh encloses is negative, so
/// that a closed mesh faces outward.
void OrientOutward(TriangleMesh& mesh);
}

#endif
