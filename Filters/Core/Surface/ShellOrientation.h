// SPDX-License-Identifier: GPL-3.0-or-later
// How a surface's triangles join (steps 5 to 7 of the surface preparation):
// the edges paired into manifold adjacencies, the vertices whose corners form
// several fans, and one consistent orientation per connected shell.
#ifndef medialaxis_ShellOrientation_h
#define medialaxis_ShellOrientation_h

#include "Mesh/PolygonMesh.h"

#include <cstddef>
#include <vector>

namespace medialaxis
{
/// Two triangles that share an edge no other triangle uses.
struct EdgeAdjacency
{
  Index A, B;      // the two triangles
  Index U, V;      // the edge's vertices, U < V
  bool Consistent; // traversed in opposite directions
};

struct EdgePairing
{
  std::vector<EdgeAdjacency> Adjacencies; // one per manifold edge, by (U, V)
  std::size_t BoundaryEdges = 0;          // edges with one triangle
  std::size_t NonManifoldEdges = 0;       // edges with more than two triangles
};

/// Every edge of the triangles with the triangles that use it.
EdgePairing PairTriangleEdges(const std::vector<Triangle>& triangles);

/// The vertices (indices below `pointCount`) whose corners, joined across the
/// manifold edges, form more than one fan.
std::size_t CountNonManifoldVertices(const std::vector<Triangle>& triangles,
  const std::vector<EdgeAdjacency>& adjacencies, std::size_t pointCount);

struct ShellOrientation
{
  std::vector<Index> Component;            // per triangle, its shell
  std::vector<std::vector<Index>> Members; // per shell, its triangles
  std::vector<char> Flip;                  // per triangle, reversed to agree
  std::size_t Flipped = 0;                 // triangles with Flip set
  std::size_t NonOrientable = 0;           // adjacencies no flip can satisfy
};

/// The connected shells over the adjacencies (breadth-first from the lowest
/// triangle), each with the flips that make its orientation consistent;
/// of the two consistent choices, the one flipping fewer triangles.
ShellOrientation OrientShells(
  std::size_t triangleCount, const std::vector<EdgeAdjacency>& adjacencies);
}

#endif
