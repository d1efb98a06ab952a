// SPDX-License-Identifier: GPL-3.0-or-later
// Thinning a medial mesh (a 2-complex of triangles and lines) to a graph of
// the same homotopy type, the first step of a curve skeleton.
//
// Edges of triangles are contracted, shortest first, where the link
// condition Lk(a) n Lk(b) = Lk(ab) holds (Dey, Edelsbrunner, Guha and
// Nekhayev 1999: the contraction is then a homotopy equivalence). A merged
// vertex stands at the centroid of the medial vertices it gathered, so a
// sheet shrinks towards its centre curve: its vertices first merge across
// its width, then the chain that is left is a curve along its length. Where
// no edge may be contracted and triangles remain, a triangle with a free
// edge (an edge of no other triangle) is collapsed away with that edge, also
// a homotopy equivalence, and the contractions go on. Written by hand: no
// library thins a non-manifold simplicial 2-complex under the link
// condition.
#ifndef medialaxis_MedialThinning_h
#define medialaxis_MedialThinning_h

#include "Mesh/MedialMesh.h"

#include <array>
#include <functional>
#include <vector>

namespace medialaxis
{
struct ThinnedGraph
{
  /// Per medial vertex: the graph vertex it was merged into.
  std::vector<Index> VertexOf;
  /// Per graph vertex: the centroid of its medial vertices (weighted by
  /// their balls' volumes).
  std::vector<Point3> Centroid;
  std::vector<std::array<Index, 2>> Edges; // sorted, unique
  std::size_t Contractions = 0;
  std::size_t FreeFaceCollapses = 0;
  /// Triangles left when neither step applied (a closed 2-cycle: a void),
  /// dropped with their edges kept; 0 for the medial axis of a solid.
  std::size_t UncollapsedTriangles = 0;
  bool Aborted = false;
};

/// Thins `mesh` to a graph. `progress` (fraction in [0, 1]) may stop it.
ThinnedGraph ThinMedialMesh(
  const MedialMesh& mesh, const std::function<bool(double)>& progress = nullptr);
}

#endif
