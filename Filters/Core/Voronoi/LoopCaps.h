// SPDX-License-Identifier: GPL-3.0-or-later
// Caps over loops of a medial complex for the topology repair
// (MedialTopologyRepair.cxx): where to put the fans of triangles that close a
// spurious loop, so that they stay inside the surface.
#ifndef medialaxis_LoopCaps_h
#define medialaxis_LoopCaps_h

#include "Mesh/MedialMesh.h"
#include "Voronoi/MedialTopologyRepair.h"

#include <vector>

namespace medialaxis
{
namespace repair
{
/// A cap over a loop: a fan from each hub over its part of the loop. One fan
/// over the whole loop, or fans over the parts that chords (segments between
/// two loop vertices, new edges of the complex) split it into; either way a
/// disk spanning the loop.
struct LoopCap
{
  std::vector<Point3> Hubs;
  std::vector<std::vector<Index>> Fans; // closed chains of loop vertices
};

/// A cap over `loop` that stays inside the surface, as far as segment tests
/// tell: a fan from a hub that sees every loop vertex without crossing the
/// surface (the centroid, or failing that a point a third, two thirds or 95%
/// of the way from it to a loop vertex), or, where no point sees the whole
/// loop (a loop bent round a concave part), the loop split in two by a chord
/// inside the surface and each half capped the same way, `depth` times at
/// most, and 64 hub searches at most. Fans of a split cap must also see
/// the middle of each of their edges. Where no flat fan fits (a loop round a
/// pocket of outside space, a dent whose tip stops short of the far side),
/// a cup over the whole loop: its hub a vertex of the complex near the
/// loop, or a point inside the surface on a ray from the centroid (in a wall
/// thinner than the sampling, past the pocket's tip). False if no cap is
/// found.
bool FindCap(const MedialMesh& mesh, const std::vector<Index>& loop,
  const TopologyRepairQueries& queries, LoopCap& cap, int depth = 3);
}
}

#endif
