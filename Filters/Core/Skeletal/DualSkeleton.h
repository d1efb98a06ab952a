// SPDX-License-Identifier: GPL-3.0-or-later
// The skeleton of a Medial Skeletal Diagram as the dual of its sites' cells
// on the medial mesh (paper 004, section 5.1): the cells are geodesic along
// the medial edges, two cells that meet along a medial edge give a skeletal
// edge, three that meet on a medial triangle a skeletal triangle. An edge
// whose straight chord leaves the surface (two sites on either side of a
// bend or a concave part) is routed inside it, along the medial path
// between its sites, as a polyline bent only where it has to be.
#ifndef medialaxis_DualSkeleton_h
#define medialaxis_DualSkeleton_h

#include "Mesh/MedialMesh.h"
#include "Mesh/TriangleLocator.h"

#include <array>
#include <cstdint>
#include <vector>

namespace medialaxis
{
/// The medial edges as a weighted graph (lengths).
struct MedialGraph
{
  std::vector<std::vector<std::pair<Index, double>>> Neighbours;
};

MedialGraph BuildMedialGraph(const MedialMesh& medial);

/// Each medial vertex's nearest site along the medial edges (by position in
/// the site list; -1 where no site is reachable), its distance and the
/// vertex before it on its shortest path from that site (-1 at sites).
struct SiteCells
{
  std::vector<int> Owner;
  std::vector<double> Distance;
  std::vector<Index> Parent;
};

/// Multi-source Dijkstra; ties go to the earlier site. Deterministic.
SiteCells NearestSites(const MedialGraph& graph, const std::vector<Index>& sites);

struct DualSkeleton
{
  /// Edges between sites (positions in the site list, smaller first), in
  /// increasing order, and each one's route: the medial vertices from its
  /// first site to its second, both included (two when it is straight).
  std::vector<std::array<Index, 2>> Edges;
  std::vector<std::vector<Index>> Routes;
  /// Triangles of sites (positions, increasing), in increasing order.
  std::vector<std::array<Index, 3>> Triangles;
};

/// The dual skeleton of `sites`, given their cells. An edge's route follows
/// the path from its first site down its cell's shortest-path tree to the
/// cheapest medial edge where the two cells meet and up the other cell's
/// tree. Where the straight chord between the sites leaves the surface
/// (`locator`, closed and outward), the route bends at vertices of that
/// path marked in `bendable` (medial vertices inside the surface), each
/// bend the farthest one along the path that the chord from the previous
/// bend reaches inside the surface; where no marked vertex is reached, at
/// the next vertex of the path (that piece then leaves the surface).
DualSkeleton BuildDualSkeleton(const MedialMesh& medial, const TriangleLocator& locator,
  const std::vector<std::uint8_t>& bendable, const std::vector<Index>& sites,
  const SiteCells& cells);
}

#endif
