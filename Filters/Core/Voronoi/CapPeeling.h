// SPDX-License-Identifier: GPL-3.0-or-later
// Peeling a medial complex for the topology repair (MedialTopologyRepair.cxx):
// removing, until none is left, every triangle with an edge on no other live
// triangle. FaceIncidence holds the incidences the peeling walks follow;
// CapPeeler tells whether a cap over a loop of the complex would close a void.
#ifndef medialaxis_CapPeeling_h
#define medialaxis_CapPeeling_h

#include "Mesh/MedialMesh.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace medialaxis
{
namespace repair
{
using EdgeKey = std::array<Index, 2>;

inline EdgeKey Key(Index a, Index b)
{
  return a < b ? EdgeKey{ a, b } : EdgeKey{ b, a };
}

// Which edges each triangle has and which triangles each edge is on, for
// the peeling walks of the topology repair.
struct FaceIncidence
{
  explicit FaceIncidence(const MedialMesh& mesh);

  /// The index of edge (a, b) in Edges, which must hold it.
  std::size_t Id(Index a, Index b) const
  {
    const EdgeKey key = Key(a, b);
    auto first = this->Edges.begin() + static_cast<std::ptrdiff_t>(this->FirstEdge[key[0]]);
    auto last = this->Edges.begin() + static_cast<std::ptrdiff_t>(this->FirstEdge[key[0] + 1]);
    return static_cast<std::size_t>(std::lower_bound(first, last, key) - this->Edges.begin());
  }

  std::vector<EdgeKey> Edges; // sorted
  std::vector<std::array<std::size_t, 3>> FaceEdges;
  std::vector<int> FaceCount;     // triangles on each edge
  std::vector<std::size_t> Start; // edge -> faces, compressed rows
  std::vector<Index> EdgeFaces;
  std::vector<std::size_t> FirstEdge; // vertex -> its run of Edges (as the smaller vertex)
};

// Whether a cap would close a void: peeling (removing, until none is left,
// every triangle with an edge on no other live triangle) leaves exactly the
// triangles of the complex's closed surfaces and of what they pin down, so a
// cap that survives it closes one. The complex's incidences are built once;
// caps made since (AddCap) join each peel as fans of their own, and each
// candidate cap is peeled with them from scratch, as peeling is not
// incremental.
class CapPeeler
{
public:
  explicit CapPeeler(const MedialMesh& mesh)
    : Incidence(mesh)
  {
  }

  /// A cap made over `loop` (a fan from a new vertex): later peels include
  /// it, as a rebuilt peeler would.
  void AddCap(const std::vector<Index>& loop) { this->Caps.push_back(loop); }

  /// True when the fan from a new vertex over the closed `loop` (of edges
  /// of the complex) would survive peeling.
  bool CapClosesVoid(const std::vector<Index>& loop) const;

private:
  // The quick answer for most loops that are not holes: the loop bounds a
  // small patch of triangles (joined across edges on exactly two, the loop's
  // edges each on one of them), a flap whose rim it is or a disk cut out of
  // a sheet, which with the cap makes a closed surface. False when unsure.
  bool BoundsSmallPatch(const std::vector<Index>& loop) const;

  FaceIncidence Incidence;
  std::vector<std::vector<Index>> Caps; // made since the incidences were built
};
}
}

#endif
