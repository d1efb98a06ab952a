// SPDX-License-Identifier: GPL-3.0-or-later
// A curve skeleton from a medial mesh: a graph of centre lines with the
// inscribed ball's radius at every node and one loop per handle of the
// solid.
//
// The medial mesh is thinned to a graph of its homotopy type
// (MedialThinning.h), so that the graph's cycle rank is the solid's genus
// when the medial mesh has the solid's topology. Its nodes stand at the
// centroids of the medial vertices they gathered, or at the one of those
// nearest the centroid where the centroid falls outside the solid. Branches
// from a free end to a junction whose medial balls the rest of the
// skeleton's, grown by PruneScale, contain (bumps, corners and rims of the
// surface) are pruned, the nodes inside branches are smoothed (never out of
// the solid), free ends go on to the balls touching their limbs' tips
// (along the medial mesh, then straight on), and every node's radius is its
// distance to the surface.
#ifndef medialaxis_CurveSkeleton_h
#define medialaxis_CurveSkeleton_h

#include "Mesh/MedialMesh.h"
#include "Mesh/PolygonMesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace medialaxis
{
struct CurveSkeletonOptions
{
  /// A branch from a free end to a junction goes when each of its medial
  /// balls lies inside a medial ball of the rest of the skeleton grown by
  /// this factor (the scale axis of Giesen et al. on the branch): it
  /// stands for a bump, a corner or a rim of the surface smaller than
  /// (PruneScale - 1) times the radius there, not for a limb.
  double PruneScale = 1.5;
  /// Passes of Laplacian smoothing over the nodes inside branches (each
  /// moves half way to the mean of its two neighbours unless that would take
  /// it out of the solid).
  int SmoothingIterations = 10;
  /// Edges longer than this times the larger distance to the surface at
  /// their ends (and than 1% of the diagonal) are split evenly (where the
  /// new nodes lie inside), so that each node's share of the surface is
  /// local; 0 keeps the thinned nodes.
  double NodeSpacing = 1.0;
  /// Fraction in [0, 1]; returning false stops the computation.
  std::function<bool(double)> Progress;
};

enum class SkeletonNodeType : std::uint8_t
{
  End = 0,     // one edge, or none (a skeleton of one node)
  Regular = 1, // two edges
  Junction = 2 // three or more
};

struct CurveSkeleton
{
  std::vector<Point3> Nodes;
  /// Distance from each node to the surface: the radius of the largest ball
  /// centred there inside the solid.
  std::vector<double> Radii;
  std::vector<SkeletonNodeType> Types;
  std::vector<std::array<Index, 2>> Edges;
  /// Node chains from an end or junction to the next; a loop through no
  /// junction starts and ends at its lowest node. A lone node is a branch.
  std::vector<std::vector<Index>> Branches;
  /// A branch of each node (for a junction, its longest branch).
  std::vector<Index> NodeBranch;
  /// Per medial vertex: the node it was merged or pruned into.
  std::vector<Index> MedialVertexNode;
  /// Loops (edges - nodes + components) and connected pieces.
  std::size_t CycleRank = 0;
  std::size_t Components = 0;
  std::size_t PrunedBranches = 0;
  /// Triangles of the medial mesh no homotopy-preserving step removed (a
  /// void); 0 for the medial axis of a solid.
  std::size_t UncollapsedTriangles = 0;
  bool Aborted = false;
  /// Why nothing was computed: the medial mesh is not `surface`'s
  /// (CheckMedialMeshOfSurface); empty otherwise.
  std::string Problem;
};

/// The curve skeleton of the closed `surface` from its medial mesh (nothing,
/// with Problem said, for the medial mesh of another surface).
CurveSkeleton ComputeCurveSkeleton(const MedialMesh& medial, const TriangleMesh& surface,
  const CurveSkeletonOptions& options = CurveSkeletonOptions());

/// Per surface vertex, the node it belongs to: the node whose ball (its
/// radius) comes nearest to it, least |p - x| - r among the 16 nearest
/// nodes; -1 for an empty skeleton.
std::vector<Index> SegmentSurface(const CurveSkeleton& skeleton, const TriangleMesh& surface);

/// Why `medial` cannot be the medial mesh of `surface`, or empty: it must
/// have vertices, most centres inside the surface, and radii near the
/// centres' distances to it.
std::string CheckMedialMeshOfSurface(const MedialMesh& medial, const TriangleMesh& surface);
}

#endif
