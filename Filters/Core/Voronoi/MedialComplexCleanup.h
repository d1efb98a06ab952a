// SPDX-License-Identifier: GPL-3.0-or-later
// Topology-preserving clean-up of the initial medial complex.
#ifndef medialaxis_MedialComplexCleanup_h
#define medialaxis_MedialComplexCleanup_h

#include "Voronoi/VoronoiMedialAxis.h"

#include <vector>

namespace medialaxis
{
/// Removes the triangles flagged in `flagged` (one flag per face of
/// result.Mesh) by elementary collapses only: a flagged triangle goes when
/// one of its edges bounds no other triangle, taking that edge with it, and
/// the edges and vertices it leaves dangling are collapsed in turn. The
/// complex therefore keeps its homotopy type; flagged triangles enclosed by
/// others stay. Returns the number of triangles removed.
std::size_t CollapseFlaggedTriangles(
  VoronoiMedialAxisResult& result, const std::vector<char>& flagged);

/// Drops connected pieces with fewer than `minimumVertices` vertices:
/// isolated pockets of Delaunay cells whose circumcentres are inside while
/// all their neighbours' are outside. The largest piece always stays.
/// Returns the number of pieces dropped.
std::size_t DropSmallComponents(VoronoiMedialAxisResult& result, std::size_t minimumVertices);
}

#endif
