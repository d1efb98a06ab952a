// SPDX-License-Identifier: GPL-3.0-or-later
// Folds (two triangles folded onto each other across an edge): counted
// before and after a collapse, and repaired by collapsing them away.
#include "Simplification/EdgeCollapse.h"

#include "Mesh/MedialMeshQuality.h"

#include <algorithm>

namespace medialaxis
{
std::size_t MedialEdgeCollapse::FoldWeight(
  const Point3& u, const Point3& v, const Point3& x, const Point3& y) const
{
  // IsFold at both angles, from one pair of normals.
  const Point3 e = v - u;
  const Point3 n1 = Cross(e, x - u);
  const Point3 n2 = Cross(y - v, e);
  const double dot = Dot(n1, n2), scale = Norm(n1) * Norm(n2);
  if (dot < -FoldCosine * scale)
  {
    return FoldCountWeight;
  }
  return dot < -this->GuardCosine * scale ? 1 : 0;
}

namespace
{
// Calls fold(u, v, x, y, w) for every edge (u, v) between exactly two of the
// faces listed in `incidences` as (min, max, apex, flag), sorted, whose faces
// (u, v, x) and (v, u, y) have a flag set and a weight w = weight(u, v, x, y)
// above 0 (they fold onto each other, or pleat).
template <typename Position, typename Weight, typename Fold>
void ForEachFold(const std::vector<std::array<Index, 4>>& incidences, const Position& position,
  const Weight& weight, const Fold& fold)
{
  for (std::size_t i = 0; i < incidences.size();)
  {
    std::size_t j = i + 1;
    while (j < incidences.size() && incidences[j][0] == incidences[i][0] &&
      incidences[j][1] == incidences[i][1])
    {
      ++j;
    }
    const auto &p = incidences[i], &q = incidences[i + 1];
    const std::size_t w = j - i == 2 && (p[3] || q[3])
      ? weight(position(p[0]), position(p[1]), position(p[2]), position(q[2]))
      : 0;
    if (w > 0)
    {
      fold(p[0], p[1], p[2], q[2], w);
    }
    i = j;
  }
}

void AddIncidences(
  std::vector<std::array<Index, 4>>& incidences, const std::array<Index, 3>& t, Index flag)
{
  for (int k = 0; k < 3; ++k)
  {
    const Index u = t[k], v = t[(k + 1) % 3];
    incidences.push_back({ std::min(u, v), std::max(u, v), t[(k + 2) % 3], flag });
  }
}
}

// Folded manifold edges among the edges of the `centre` faces, with the
// faces across them taken from `centre` and scratch.Outer; vertex `moved` sits
// at `movedTo`.
std::size_t MedialEdgeCollapse::CountFolds(const std::vector<std::array<Index, 3>>& centre,
  Index moved, const Point3& movedTo, CollapseScratch& scratch) const
{
  auto position = [&](Index v)
  {
    return v == moved ? movedTo
                      : Point3{ this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  };
  auto& incidences = scratch.EdgeIncidences;
  incidences.clear();
  for (const auto& t : centre)
  {
    AddIncidences(incidences, t, 1);
  }
  for (const auto& t : scratch.Outer)
  {
    AddIncidences(incidences, t, 0);
  }
  std::sort(incidences.begin(), incidences.end());
  std::size_t folds = 0;
  ForEachFold(
    incidences, position,
    [this](const Point3& u, const Point3& v, const Point3& x, const Point3& y)
    { return this->FoldWeight(u, v, x, y); },
    [&folds](Index, Index, Index, Index, std::size_t w) { folds += w; });
  return folds;
}

// Every folded edge (u, v, x, y) of the mesh, as in CountFolds.
std::vector<std::array<Index, 4>> MedialEdgeCollapse::FindFolds(CollapseScratch& scratch) const
{
  auto& incidences = scratch.EdgeIncidences;
  incidences.clear();
  for (std::size_t f = 0; f < this->Faces.size(); ++f)
  {
    if (this->FaceAlive[f])
    {
      AddIncidences(incidences, this->Faces[f], 1);
    }
  }
  std::sort(incidences.begin(), incidences.end());
  std::vector<std::array<Index, 4>> folds;
  ForEachFold(
    incidences, [this](Index v) { return this->Position(v); },
    [](const Point3& u, const Point3& v, const Point3& x, const Point3& y)
    { return IsFold(u, v, x, y) ? 1 : 0; },
    [&folds](Index u, Index v, Index x, Index y, std::size_t) {
      folds.push_back({ u, v, x, y });
    });
  return folds;
}

// Folded edges around a after merging b into it at `newPosition`, from the
// collapse's face keys. Every face around a is then (a, u, v): spokes (a, u)
// lie between two such faces, ring edges (u, v) between one and the faces
// across that do not move. A fast path for the common case (no fold): no
// sorting, and the pre-collapse state is looked at only when needed.
std::size_t MedialEdgeCollapse::FoldsAroundMerged(
  Index a, Index b, const Point3& newPosition, CollapseScratch& scratch) const
{
  auto position = [this](Index v) {
    return Point3{ this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  };
  auto& ring = scratch.RingPairs;
  ring.clear();
  const auto& keys = scratch.FaceKeys;
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    if (i > 0 && keys[i].first == keys[i - 1].first)
    {
      continue; // merged away
    }
    const auto& t = keys[i].first;
    ring.push_back(t[0] == a ? std::array<Index, 2>{ t[1], t[2] }
        : t[1] == a          ? std::array<Index, 2>{ t[0], t[2] }
                             : std::array<Index, 2>{ t[0], t[1] });
  }
  // Spoke (a, u) between exactly two faces (a, u, x) and (a, u, y), x < y.
  // A dozen faces at most, mostly: pairwise scans beat sorting the spokes.
  std::size_t folds = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    for (int end = 0; end < 2; ++end)
    {
      const Index u = ring[i][end];
      bool seen = false; // each spoke once, at the first face it is in
      for (std::size_t k = 0; k < i && !seen; ++k)
      {
        seen = ring[k][0] == u || ring[k][1] == u;
      }
      if (seen)
      {
        continue;
      }
      const Index x = ring[i][1 - end];
      Index y = -1;
      std::size_t faces = 1;
      for (std::size_t k = i + 1; k < ring.size() && faces <= 2; ++k)
      {
        if (ring[k][0] == u || ring[k][1] == u)
        {
          y = ring[k][0] == u ? ring[k][1] : ring[k][0];
          ++faces;
        }
      }
      if (faces == 2)
      {
        folds += this->FoldWeight(
          newPosition, position(u), position(std::min(x, y)), position(std::max(x, y)));
      }
    }
  }
  // The faces scanned below are scattered through memory: requested all at
  // once first, so that their cache misses overlap instead of queueing up
  // behind the scan's data-dependent branches.
  for (const auto& edge : ring)
  {
    const auto& u = this->VertexFaces[edge[0]];
    const auto& v = this->VertexFaces[edge[1]];
    this->PrefetchFaces(u.size() <= v.size() ? u : v);
  }
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    // Ring edge (u, v) between (a, u, v) and the faces across it.
    const Index u = ring[i][0], v = ring[i][1];
    // Scan the shorter face list of the two; stop at a second face (the
    // edge is then non-manifold and cannot fold).
    const auto& candidates = this->VertexFaces[u].size() <= this->VertexFaces[v].size()
      ? this->VertexFaces[u]
      : this->VertexFaces[v];
    std::size_t count = 0;
    Index y = -1;
    for (Index f : candidates)
    {
      if (!this->FaceAlive[f])
      {
        continue;
      }
      const auto& o = this->Faces[f];
      const bool hasU = o[0] == u || o[1] == u || o[2] == u;
      const bool hasV = o[0] == v || o[1] == v || o[2] == v;
      const bool hasAB = o[0] == a || o[1] == a || o[2] == a || o[0] == b || o[1] == b || o[2] == b;
      if (hasU && hasV && !hasAB)
      {
        y = o[0] != u && o[0] != v ? o[0] : (o[1] != u && o[1] != v ? o[1] : o[2]);
        if (++count > 1)
        {
          break;
        }
      }
    }
    if (count == 1)
    {
      folds += this->FoldWeight(position(u), position(v), newPosition, position(y));
    }
  }
  return folds;
}

// Whether merging b into a at `newPosition` folds two triangles onto each
// other that were not folded before. (A face's own normal may turn by less
// than the flip test allows and still fold over its neighbour; and the
// flip test is skipped on spike edges.)
bool MedialEdgeCollapse::CreatesFold(
  Index a, Index b, const Point3& newPosition, CollapseScratch& scratch) const
{
  const std::size_t foldsAfter = this->FoldsAroundMerged(a, b, newPosition, scratch);
  if (foldsAfter == 0 && !scratch.FewerFolds)
  {
    return false;
  }
  // Rare: were there as many folds before (in a medial mesh given as input)?
  // That does not depend on the placement: counted once per edge.
  auto tooMany = [&scratch](std::size_t after)
  { return scratch.FewerFolds ? after >= scratch.FoldsBefore : after > scratch.FoldsBefore; };
  if (scratch.FoldsBeforeA == a && scratch.FoldsBeforeB == b)
  {
    return tooMany(foldsAfter);
  }
  auto has = [](const std::array<Index, 3>& t, Index v)
  { return t[0] == v || t[1] == v || t[2] == v; };
  auto& before = scratch.CentreBefore;
  before.clear();
  for (Index v : { a, b })
  {
    for (Index f : this->VertexFaces[v])
    {
      const auto& t = this->Faces[f];
      if (this->FaceAlive[f] && !(v == b && has(t, a)))
      {
        before.push_back(t);
      }
    }
  }
  // The faces across the ring edges (those without a or b).
  auto& outer = scratch.Outer;
  outer.clear();
  for (const auto& t : before)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index u = t[k], v = t[(k + 1) % 3];
      if (u == a || u == b || v == a || v == b)
      {
        continue;
      }
      for (Index f : this->VertexFaces[u])
      {
        const auto& o = this->Faces[f];
        if (this->FaceAlive[f] && has(o, v) && !has(o, a) && !has(o, b))
        {
          std::array<Index, 3> sorted = o;
          std::sort(sorted.begin(), sorted.end());
          outer.push_back(sorted);
        }
      }
    }
  }
  std::sort(outer.begin(), outer.end());
  outer.erase(std::unique(outer.begin(), outer.end()), outer.end());
  scratch.FoldsBefore = this->CountFolds(before, -1, newPosition, scratch);
  scratch.FoldsBeforeA = a;
  scratch.FoldsBeforeB = b;
  return tooMany(foldsAfter);
}

// Folds left after the urgent collapses around forced snaps (see Prepare):
// every collapse may only keep or lower the folds around it, so nothing
// else removes them. Collapses an edge of each folded pair of triangles, the
// cheapest that leaves fewer folds around it (none above MaximumCost), while
// vertices above `target` remain (Run keeps some in reserve for this).
void MedialEdgeCollapse::CollapseFolds(std::size_t target)
{
  CollapseScratch& scratch = this->Scratch;
  scratch.FewerFolds = true;
  std::vector<BatchItem> tries;
  for (int pass = 0; pass < 8 && this->NumberAlive > target; ++pass)
  {
    bool collapsed = false;
    for (const auto& fold : this->FindFolds(scratch))
    {
      if (this->NumberAlive <= target)
      {
        break;
      }
      if (!std::all_of(fold.begin(), fold.end(), [this](Index v) { return this->Alive(v); }))
      {
        continue; // merged away by a repair of an earlier fold
      }
      // The edges at the four vertices of the triangles (u, v, x) and
      // (v, u, y), each once, cheapest first.
      tries.clear();
      for (Index w : fold)
      {
        for (Index n : this->VertexNeighbours[w])
        {
          const bool seen = std::any_of(tries.begin(), tries.end(),
            [&](const BatchItem& t)
            { return t.Taken.A == std::min(w, n) && t.Taken.B == std::max(w, n); });
          if (!seen)
          {
            BatchItem item;
            item.Taken = this->MakeCandidate(std::min(w, n), std::max(w, n), scratch);
            if (item.Taken.Cost < HUGE_VAL && item.Taken.Cost <= this->Options.MaximumCost)
            {
              tries.push_back(std::move(item));
            }
          }
        }
      }
      std::stable_sort(tries.begin(), tries.end(),
        [](const BatchItem& p, const BatchItem& q) { return p.Taken.Cost < q.Taken.Cost; });
      for (BatchItem& item : tries)
      {
        this->CollapseTaken(item, scratch);
        if (this->Finish(item))
        {
          ++this->Counts.FoldRepairCollapses;
          collapsed = true;
          break;
        }
      }
    }
    if (!collapsed)
    {
      break;
    }
  }
  scratch.FewerFolds = false;
}
}
