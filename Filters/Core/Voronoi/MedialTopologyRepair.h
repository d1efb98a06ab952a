// SPDX-License-Identifier: GPL-3.0-or-later
// Gives the initial medial complex the topology of the solid it came from.
// A solid's medial axis is a deformation retract of it: one connected piece
// per solid, as many independent loops as the solid has handles (its
// surface's genus) and no enclosed void. The Voronoi complex of a sparse
// sampling can miss that where Delaunay cells are classified outside: a piece
// cut off in a thin part, a chain of Voronoi edges closing a loop round a
// pocket of outside cells, a hole in a sheet. The repair counts the excess
// and removes exactly that much, the smallest defects first.
#ifndef medialaxis_MedialTopologyRepair_h
#define medialaxis_MedialTopologyRepair_h

#include "Mesh/PolygonMesh.h"
#include "Voronoi/VoronoiMedialAxis.h"

#include <functional>

namespace medialaxis
{
/// Connected pieces and total genus of a closed triangle surface.
struct SurfaceTopology
{
  std::size_t Components = 0;
  long long Genus = 0;
};
SurfaceTopology ComputeSurfaceTopology(const TriangleMesh& surface);

/// Surface queries the repair needs (the caller owns the spatial search).
struct TopologyRepairQueries
{
  std::function<bool(const Point3&)> Inside;
  std::function<double(const Point3&)> Distance;
  /// True when the segment from a to b meets the surface.
  std::function<bool(const Point3&, const Point3&)> Crosses;
  /// A lower bound on the distance from a vertex of the complex being
  /// repaired to the surface (0 when unknown): a segment shorter than the
  /// bounds at its ends added cannot meet the surface, and skips Crosses.
  /// Optional.
  std::function<double(Index)> DistanceLowerBound;
};

struct TopologyRepairCounts
{
  std::size_t EdgesAcrossSurface = 0; // medial edges leaving the solid, removed
  std::size_t JoinedPieces = 0;       // pieces joined to another by a new edge
  std::size_t CutLoops = 0;           // face-less edges removed to open a loop
  std::size_t FilledHoles = 0;        // loops capped by a fan of triangles
  /// Handles of the surface with no loop of the complex round them: the
  /// sampling missed a part (a thin handle) and only more samples there
  /// bring it back.
  std::size_t MissingLoops = 0;
};

/// Repairs `result` in place so that it has at most `expected.Components`
/// pieces and `expected.Genus` independent loops, as far as it can:
/// 0. medial edges that leave the solid (bridges across a gap between two
///    parts) are removed with their faces, and scraps left on their own;
/// 1. pieces beyond the expected count are joined, closest pairs of
///    vertices first, by edges that stay inside the surface;
/// 2. while there are too many loops, the face-less edge on the shortest
///    loop is removed (a loop round a handle is long, a spurious one short);
/// 3. then the shortest boundary loops of the sheets, and after them the
///    shortest loops of what the complex collapses to (round a tube, say),
///    are capped by a fan from their centroid (or a point between it and a
///    loop vertex), or, where no point sees the whole loop (a loop bent
///    round a concave part), by fans over the parts that chords inside the
///    surface split it into (LoopCaps.h), where the cap is inside the surface
///    and closes a loop rather than a void (its triangles do not survive
///    peeling).
/// New vertices' Atlas is the union of their neighbours'; cap triangles get
/// the site pair {-1, -1}. Deterministic.
TopologyRepairCounts RepairMedialTopology(VoronoiMedialAxisResult& result,
  const SurfaceTopology& expected, const TopologyRepairQueries& queries);
}

#endif
