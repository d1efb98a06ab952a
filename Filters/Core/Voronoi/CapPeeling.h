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
#include <utility>
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

/// The index of edge (a, b) in the sorted `edges`, which must hold it.
inline std::size_t EdgeId(const std::vector<EdgeKey>& edges, Index a, Index b)
{
  return static_cast<std::size_t>(
    std::lower_bound(edges.begin(), edges.end(), Key(a, b)) - edges.begin());
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
// cap that survives it closes one.
//
// Peeling ends in the same place whatever the order, so the complex is
// peeled once, remembering for each removed triangle when it went and the
// edge that was free then (its witness). A cap can only hold back the
// triangles whose removal depends, through witnesses, on an edge of its
// loop; a query peels those and the cap's fan again, on top of what
// survived the first peeling, instead of the whole complex. Caps made
// (AddCap) join the complex as fans from a new vertex.
class CapPeeler
{
public:
  explicit CapPeeler(const MedialMesh& mesh);

  /// True when the fan from a new vertex over the closed `loop` (of edges
  /// of the complex) would survive peeling.
  bool CapClosesVoid(const std::vector<Index>& loop) const;

  /// A cap made over `loop` (a fan from a new vertex): later queries
  /// include it, as a peeler built on the capped complex would.
  void AddCap(const std::vector<Index>& loop);

  /// The complex's edges and incidences.
  const FaceIncidence& Complex() const { return this->Incidence; }

  /// Whether peeling removed every triangle of the complex (caps included).
  bool PeelsAway() const;

  /// Per edge of the complex, 1 unless it was the witness of a removed
  /// triangle: with the peeling, an elementary collapse of the complex,
  /// whose edges left are a graph when it peels away.
  std::vector<char> EdgesLeft() const;

private:
  static constexpr std::size_t Survived = static_cast<std::size_t>(-1);

  // The quick answer for most loops that are not holes: the loop bounds a
  // small patch of triangles (joined across edges on exactly two, the loop's
  // edges each on one of them), a flap whose rim it is or a disk cut out of
  // a sheet, which with the cap makes a closed surface. False when unsure.
  bool BoundsSmallPatch(const std::vector<Index>& loop) const;

  // The peeling again of the triangles that depend on the loop's edges,
  // with the fan over it added; how they went (or that they survived) in
  // `order`, removal order, and `survivors`. True when a fan face survived.
  bool PeelWithFan(const std::vector<Index>& loop, std::vector<std::size_t>& order,
    std::vector<std::size_t>& survivors, std::vector<std::size_t>& witnesses) const;

  const std::array<std::size_t, 3>& EdgesOf(std::size_t face) const;
  template <typename F>
  void ForEachFaceOn(std::size_t edge, F&& visit) const;

  FaceIncidence Incidence;
  // Fans of the caps made: faces nf + i, spokes (edges) ne + j.
  std::vector<std::array<std::size_t, 3>> FanEdges;
  std::vector<std::pair<std::size_t, std::size_t>> FansOnEdge; // sorted (edge, fan face)
  std::vector<std::array<std::size_t, 2>> SpokeFaces;
  // The peeling: per triangle, its place in the removal order (Survived
  // for the triangles left) and its witness; per edge, the survivors on it.
  std::vector<std::size_t> RemovedAt;
  std::vector<std::size_t> Witness;
  std::vector<int> SurvivorsOn;
  std::size_t Removals = 0;
};
}
}

#endif
