// SPDX-License-Identifier: GPL-3.0-or-later
#include "Simplification/EdgeCollapse.h"

#include "Geometry/Vec3.h"
#include "Mesh/MedialMeshQuality.h"
#include "Support/Prefetch.h"
#include "Support/SortedLists.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <iterator>
#include <memory>
#include <thread>

namespace medialaxis
{
namespace
{
// Zero area up to rounding: twice the area at most 1e-10 x the longest edge
// squared (the sine of the largest angle below 1e-10).
bool IsDegenerate(const Point3& p, const Point3& q, const Point3& r)
{
  const double longest = std::max({ Distance2(p, q), Distance2(q, r), Distance2(r, p) });
  return !(Norm(Cross(q - p, r - p)) > 1e-10 * longest);
}
}

MedialEdgeCollapse::MedialEdgeCollapse(const MedialMesh& input, const Normalisation& frame,
  const EdgeCollapseOptions& options, CollapsePolicy& policy)
  : Options(options)
  , Policy(policy)
  , UnitFrame(frame)
  , Queue(EndpointsUnchanged{ &this->Version })
{
  this->FoldGuard = options.PreventFolds;
  const std::size_t nv = input.Centers.size();
  this->Spheres.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    const Point3 c = frame.To(input.Centers[v]);
    this->Spheres[v] = { c[0], c[1], c[2], input.Radii[v] * frame.Scale };
  }
  this->VertexNeighbours.assign(nv, {});
  this->VertexFaces.assign(nv, {});
  {
    // Sized first: a few hundred thousand lists grown one push at a time
    // cost more in reallocations than the rest of the set-up.
    std::vector<std::uint32_t> links(nv, 0), faces(nv, 0);
    for (const auto& e : input.Edges)
    {
      ++links[e[0]];
      ++links[e[1]];
    }
    for (const auto& t : input.Faces)
    {
      for (Index v : t)
      {
        links[v] += 2;
        ++faces[v];
      }
    }
    for (std::size_t v = 0; v < nv; ++v)
    {
      this->VertexNeighbours[v].reserve(links[v]);
      this->VertexFaces[v].reserve(faces[v]);
    }
  }
  auto link = [this](Index a, Index b)
  {
    this->VertexNeighbours[a].push_back(b);
    this->VertexNeighbours[b].push_back(a);
  };
  for (const auto& e : input.Edges)
  {
    link(e[0], e[1]);
  }
  this->Faces = input.Faces;
  this->FaceAlive.assign(this->Faces.size(), 1);
  for (std::size_t f = 0; f < this->Faces.size(); ++f)
  {
    const auto& t = this->Faces[f];
    link(t[0], t[1]);
    link(t[1], t[2]);
    link(t[2], t[0]);
    for (Index v : t)
    {
      this->VertexFaces[v].push_back(static_cast<Index>(f));
    }
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 2048),
    [this](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t v = range.begin(); v != range.end(); ++v)
      {
        auto& n = this->VertexNeighbours[v];
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
      }
    });
  this->Version.assign(nv, 0);
  this->VertexAlive.assign(nv, 1);
  this->NumberAlive = nv;
}

double MedialEdgeCollapse::StabilityRatio(Index a, Index b) const
{
  return medialaxis::StabilityRatio(
    this->Position(a), this->Spheres[a][3], this->Position(b), this->Spheres[b][3]);
}

std::size_t MedialEdgeCollapse::MergedRingSums(
  Index a, Index b, Point3& sum, double& sumSquares) const
{
  // Both lists are sorted: merge them, shared neighbours once.
  std::size_t count = 0;
  ForEachInUnion(this->VertexNeighbours[a], this->VertexNeighbours[b],
    [&](Index u, bool)
    {
      if (u != a && u != b)
      {
        const Point3 p = this->Position(u);
        sum = sum + p;
        sumSquares += Dot(p, p);
        ++count;
      }
    });
  return count;
}

MedialEdgeCollapse::Candidate MedialEdgeCollapse::MakeCandidate(
  Index a, Index b, CollapseScratch& scratch) const
{
  if (a > b)
  {
    std::swap(a, b);
  }
  const CollapsePolicy::Evaluation e = this->Policy.Evaluate(*this, a, b, scratch);
  return { e.Cost, a, b, this->Version[a], this->Version[b], e.Target };
}

bool MedialEdgeCollapse::LinkConditionHolds(Index a, Index b, CollapseScratch& scratch) const
{
  scratch.EulerNeutral = false;
  // Dey's vertex condition: the common neighbours of a and b must be exactly
  // the apices of faces (a, b, x). With FringeCollapses (or, for spike
  // edges, EulerNeutralSpikeCollapses), where it fails the collapse is
  // still taken when it keeps the Euler characteristic: every
  // extra common neighbour x closes the loop (a, b, x), raising the
  // characteristic by one, and every face pair (a, x, y), (b, x, y) that
  // merges lowers it by one (e.g. the fins of a fringe along a fillet's
  // centre line, where (a, x, y), (b, x, y) and (a, b, x) form a disk).
  Index apices[16];
  std::size_t apexCount = 0;
  for (Index f : this->VertexFaces[a])
  {
    const auto& t = this->Faces[f];
    if (this->FaceAlive[f] && (t[0] == b || t[1] == b || t[2] == b))
    {
      const Index x = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
      if (apexCount < 16)
      {
        apices[apexCount++] = x;
      }
      else
      {
        return false; // an edge in more than 16 faces: too tangled to collapse
                      // safely
      }
    }
  }
  std::size_t extra = 0;
  ForEachShared(this->VertexNeighbours[a], this->VertexNeighbours[b],
    [&](Index x)
    { extra += std::find(apices, apices + apexCount, x) == apices + apexCount ? 1 : 0; });
  if (extra == 0)
  {
    return true;
  }
  const bool eulerNeutralAllowed = this->Options.FringeCollapses ||
    (this->Options.EulerNeutralSpikeCollapses &&
      this->StabilityRatio(a, b) < this->Options.SpikeThreshold);
  if (!eulerNeutralAllowed || this->NumberAlive <= this->Options.StrictLinkConditionVertexCount)
  {
    return false;
  }
  std::size_t merges = 0;
  for (Index f : this->VertexFaces[b])
  {
    const auto& t = this->Faces[f];
    if (!this->FaceAlive[f] || t[0] == a || t[1] == a || t[2] == a)
    {
      continue;
    }
    const int k = t[0] == b ? 0 : (t[1] == b ? 1 : 2);
    const Index x = t[(k + 1) % 3], y = t[(k + 2) % 3];
    for (Index g : this->VertexFaces[a])
    {
      const auto& u = this->Faces[g];
      if (this->FaceAlive[g] && (u[0] == x || u[1] == x || u[2] == x) &&
        (u[0] == y || u[1] == y || u[2] == y))
      {
        ++merges;
        break;
      }
    }
  }
  scratch.EulerNeutral = extra == merges;
  return scratch.EulerNeutral;
}

// Merges b into a at `target` if the result stays a valid medial mesh (the
// caller has checked the link condition).
bool MedialEdgeCollapse::Collapse(Index a, Index b, const Sphere& target, CollapseScratch& scratch)
{
  if (!this->CollapseIsValid(a, b, target, scratch))
  {
    return false;
  }
  this->ApplyCollapse(a, b, target, scratch);
  return true;
}

bool MedialEdgeCollapse::CollapseIsValid(
  Index a, Index b, const Sphere& target, CollapseScratch& scratch) const
{
  const Point3 newPosition{ target[0], target[1], target[2] };
  auto position = [this](Index v) {
    return Point3{ this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  };
  // Removing an unstable spike edge turns its needle triangles in any
  // direction: the flip test is meaningless there and only guards stable
  // parts of the medial mesh.
  const bool spike = this->StabilityRatio(a, b) < this->Options.SpikeThreshold;
  // Faces that survive: no zero area and no flip (for faces that had a
  // well-defined normal). Two faces that become one are merged. With the
  // vertex part of the link condition holding, that only happens when
  // (a, b, x, y) bound a tetrahedral bubble, which the merge removes: the
  // edge part of Dey's link condition is relaxed on purpose, since a bubble
  // in the medial axis of a solid without cavities is always spurious.
  auto& keys = scratch.FaceKeys;
  keys.clear();
  for (Index v : { a, b })
  {
    for (Index f : this->VertexFaces[v])
    {
      if (!this->FaceAlive[f])
      {
        continue;
      }
      const auto& t = this->Faces[f];
      const bool hasA = t[0] == a || t[1] == a || t[2] == a;
      const bool hasB = t[0] == b || t[1] == b || t[2] == b;
      if (hasA && hasB)
      {
        continue; // vanishes with the edge
      }
      if (v == b && hasA)
      {
        continue; // seen from a
      }
      std::array<Index, 3> after = t;
      Point3 before[3], moved[3];
      for (int k = 0; k < 3; ++k)
      {
        before[k] = position(t[k]);
        moved[k] = (t[k] == a || t[k] == b) ? newPosition : before[k];
        if (after[k] == b)
        {
          after[k] = a;
        }
      }
      const Point3 n0 = Cross(before[1] - before[0], before[2] - before[0]);
      const Point3 n1 = Cross(moved[1] - moved[0], moved[2] - moved[0]);
      const double l0 = std::max({ Distance2(before[0], before[1]), Distance2(before[1], before[2]),
        Distance2(before[2], before[0]) });
      if (IsDegenerate(moved[0], moved[1], moved[2]))
      {
        return false; // would be degenerate
      }
      // (A fold repair turns triangles over on purpose: the folds it
      // counts are the test then.)
      if (!spike && !scratch.FewerFolds && Norm(n0) > 1e-6 * l0 && Dot(n0, n1) <= 0.0)
      {
        return false; // would flip
      }
      std::sort(after.begin(), after.end());
      keys.emplace_back(after, f);
    }
  }
  std::sort(keys.begin(), keys.end());
  auto& mergedAway = scratch.MergedAway;
  mergedAway.clear();
  for (std::size_t i = 1; i < keys.size(); ++i)
  {
    if (keys[i].first == keys[i - 1].first)
    {
      mergedAway.push_back(keys[i].second);
    }
  }

  if (((this->FoldGuard && (this->Options.FoldTestOnSpikes || !spike)) || scratch.FewerFolds) &&
    this->CreatesFold(a, b, newPosition, scratch))
  {
    return false;
  }
  return true;
}

void MedialEdgeCollapse::ApplyCollapse(
  Index a, Index b, const Sphere& target, CollapseScratch& scratch)
{
  const auto& mergedAway = scratch.MergedAway;
  for (Index f : mergedAway)
  {
    this->FaceAlive[f] = 0;
  }
  // An Euler-neutral collapse's merges pair up with the loops it closes:
  // they close no bubble.
  (scratch.EulerNeutral ? scratch.EulerNeutralMerges : scratch.MergedFaces) += mergedAway.size();
  for (Index f : this->VertexFaces[b])
  {
    if (!this->FaceAlive[f])
    {
      continue;
    }
    auto& t = this->Faces[f];
    if (t[0] == a || t[1] == a || t[2] == a)
    {
      this->FaceAlive[f] = 0;
      continue;
    }
    for (Index& v : t)
    {
      v = v == b ? a : v;
    }
    this->VertexFaces[a].push_back(f);
  }
  auto& faces = this->VertexFaces[a];
  faces.erase(
    std::remove_if(faces.begin(), faces.end(), [this](Index f) { return !this->FaceAlive[f]; }),
    faces.end());
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  for (Index u : this->VertexNeighbours[b])
  {
    auto& n = this->VertexNeighbours[u];
    n.erase(std::lower_bound(n.begin(), n.end(), b));
    if (u != a)
    {
      n.insert(std::lower_bound(n.begin(), n.end(), a), a);
      n.erase(std::unique(n.begin(), n.end()), n.end());
    }
  }
  auto& merged = scratch.MergedNeighbours;
  merged.clear();
  std::set_union(this->VertexNeighbours[a].begin(), this->VertexNeighbours[a].end(),
    this->VertexNeighbours[b].begin(), this->VertexNeighbours[b].end(), std::back_inserter(merged));
  merged.erase(
    std::remove_if(merged.begin(), merged.end(), [a, b](Index u) { return u == a || u == b; }),
    merged.end());
  this->VertexNeighbours[a].swap(merged); // the old list becomes the next scratch
  std::vector<Index>().swap(this->VertexNeighbours[b]);
  std::vector<Index>().swap(this->VertexFaces[b]);

  this->Spheres[a] = target;
  this->VertexAlive[b] = 0; // NumberAlive is counted down after the batch
  ++this->Version[a];
  ++this->Version[b];
  this->Policy.Merged(*this, a, b, scratch);
}

namespace
{
// Calls fold(u, v, x, y) for every edge (u, v) between exactly two of the
// faces listed in `incidences` as (min, max, apex, flag), sorted, whose faces
// (u, v, x) and (v, u, y) fold onto each other and have a flag set.
template <typename Position, typename Fold>
void ForEachFold(
  const std::vector<std::array<Index, 4>>& incidences, const Position& position, const Fold& fold)
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
    if (j - i == 2 && (p[3] || q[3]) &&
      IsFold(position(p[0]), position(p[1]), position(p[2]), position(q[2])))
    {
      fold(p[0], p[1], p[2], q[2]);
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
  ForEachFold(incidences, position, [&folds](Index, Index, Index, Index) { ++folds; });
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
    [&folds](Index u, Index v, Index x, Index y) {
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
      if (faces == 2 &&
        IsFold(newPosition, position(u), position(std::min(x, y)), position(std::max(x, y))))
      {
        ++folds;
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
    if (count == 1 && IsFold(position(u), position(v), newPosition, position(y)))
    {
      ++folds;
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

// When the optimal sphere would break validity: the policy's fallback
// spheres, best first.
bool MedialEdgeCollapse::CollapseAtFallback(Index a, Index b, CollapseScratch& scratch)
{
  for (const Sphere& s : this->Policy.FallbackSpheres(*this, a, b))
  {
    if (this->Collapse(a, b, s, scratch))
    {
      return true;
    }
  }
  return false;
}

// Whether moving v to `target` keeps its faces non-degenerate and folds no
// more of them than before.
bool MedialEdgeCollapse::MoveKeepsValid(
  Index v, const Point3& target, CollapseScratch& scratch) const
{
  auto& faces = scratch.FaceKeys;
  faces.clear();
  for (Index f : this->VertexFaces[v])
  {
    if (!this->FaceAlive[f])
    {
      continue; // the lists of vertices off a collapsed edge keep its dead faces
    }
    Point3 p[3];
    for (int k = 0; k < 3; ++k)
    {
      const Index u = this->Faces[f][k];
      p[k] = u == v ? target : this->Position(u);
    }
    if (IsDegenerate(p[0], p[1], p[2]))
    {
      return false;
    }
    std::array<Index, 3> sorted = this->Faces[f];
    std::sort(sorted.begin(), sorted.end());
    faces.emplace_back(sorted, f);
  }
  std::sort(faces.begin(), faces.end());
  return this->FoldsAroundMerged(v, -1, target, scratch) <=
    this->FoldsAroundMerged(v, -1, this->Position(v), scratch);
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

void MedialEdgeCollapse::PushAllEdges()
{
  std::vector<std::array<Index, 2>> edges;
  for (std::size_t v = 0; v < this->Spheres.size(); ++v)
  {
    if (!this->VertexAlive[v])
    {
      continue;
    }
    for (Index u : this->VertexNeighbours[v])
    {
      if (static_cast<Index>(v) < u)
      {
        edges.push_back({ static_cast<Index>(v), u });
      }
    }
  }
  // Evaluations are independent: in parallel, each into its own slot.
  std::vector<Candidate> candidates(edges.size());
  tbb::enumerable_thread_specific<CollapseScratch> scratches;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, edges.size(), 512),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      auto& scratch = scratches.local();
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        candidates[k] = this->MakeCandidate(edges[k][0], edges[k][1], scratch);
      }
    });
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                     [](const Candidate& c) { return !(c.Cost < HUGE_VAL); }),
    candidates.end());
  this->Queue.PushAll(std::move(candidates));
}

namespace
{
// Most candidates passed over while a batch fills: each goes back to the
// queue, so looking far costs more than the larger batches gain.
constexpr std::size_t LookAhead = 16;
}

// How many collapses may be taken at once: one near a vertex count where
// the rules change (the topology guard, the strict link condition), so that
// every collapse of a batch sees the rules of the sequential order.
std::size_t MedialEdgeCollapse::BatchLimit(std::size_t target) const
{
  const std::size_t alive = this->NumberAlive;
  std::size_t limit = std::min(
    std::max<std::size_t>(this->Options.MaximumBatch, 1), alive > target ? alive - target : 1);
  auto crosses = [alive, limit](std::size_t threshold)
  { return alive > threshold && alive - threshold <= limit; };
  if ((!this->Relaxed && crosses(this->Options.TopologyGuardVertexCount)) ||
    crosses(this->Options.StrictLinkConditionVertexCount))
  {
    limit = 1;
  }
  return std::max<std::size_t>(limit, 1);
}

// The vertices within two edges of a or b: the rings of their neighbours,
// each neighbour once (both lists are sorted; a and b are among them).
void MedialEdgeCollapse::GatherRegion(Index a, Index b, std::vector<Index>& region) const
{
  // Sized first, then copied by a plain loop: the rings are a few entries
  // each, for which vector::insert's bookkeeping cost more than the copy.
  std::size_t size = 0;
  ForEachInUnion(this->VertexNeighbours[a], this->VertexNeighbours[b],
    [&](Index u, bool)
    {
      Prefetch(this->VertexNeighbours[u].data());
      size += this->VertexNeighbours[u].size();
    });
  region.resize(size);
  Index* out = region.data();
  ForEachInUnion(this->VertexNeighbours[a], this->VertexNeighbours[b],
    [&](Index u, bool)
    {
      for (Index v : this->VertexNeighbours[u])
      {
        *out++ = v;
      }
    });
}

// Claims a candidate's region (GatherRegion) for the batch under way; false
// when one of its vertices is claimed already (claiming them all anyway, so
// that no costlier candidate near this one joins the batch either). Members
// of a batch are then at least five edges apart: a collapse writes within
// one edge of its endpoints and reads within three (the fold tests around
// vertices its policy moves), so no member reads what another writes, and
// the batch's result is that of any order.
bool MedialEdgeCollapse::ClaimRegion(const std::vector<Index>& region)
{
  // One pass: a vertex stamped since the batch began, by another claim, is
  // taken already.
  const std::uint32_t claim = ++this->ClaimStamp;
  bool free = true;
  for (Index v : region)
  {
    std::uint32_t& stamp = this->RegionStamp[v];
    free = free && (stamp < this->BatchStart || stamp == claim);
    stamp = claim;
  }
  return free;
}

bool MedialEdgeCollapse::LookFurther(std::size_t count, bool gather)
{
  const std::size_t first = this->Looked.size();
  Candidate taken;
  while (this->Looked.size() - first < count && this->TakeNext(taken))
  {
    this->Looked.push_back(taken);
  }
  const std::size_t end = this->Looked.size();
  if (!gather || end == first)
  {
    return end > first;
  }
  // Gathering the regions chases pointers through the neighbour lists, the
  // dearest part of choosing a batch: done for all at once, in parallel.
  if (this->Regions.size() < end)
  {
    this->Regions.resize(end);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first, end, 8),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        // The next candidates' neighbour lists, requested ahead in two steps:
        // the lists' headers two candidates ahead, their entries one ahead.
        if (k + 2 < r.end())
        {
          Prefetch(&this->VertexNeighbours[this->Looked[k + 2].A]);
          Prefetch(&this->VertexNeighbours[this->Looked[k + 2].B]);
        }
        if (k + 1 < r.end())
        {
          Prefetch(this->VertexNeighbours[this->Looked[k + 1].A].data());
          Prefetch(this->VertexNeighbours[this->Looked[k + 1].B].data());
        }
        this->GatherRegion(this->Looked[k].A, this->Looked[k].B, this->Regions[k]);
      }
    });
  return true;
}

// Collapses a batch member (or rejects it) and re-evaluates the edges of the
// merged vertex: all within its claimed region.
void MedialEdgeCollapse::CollapseTaken(BatchItem& item, CollapseScratch& scratch)
{
  this->CollapseOnly(item, scratch);
  this->EvaluateMergedEdges(item, scratch);
}

// Requests the records of the given faces and whether each is alive.
void MedialEdgeCollapse::PrefetchFaces(const std::vector<Index>& faces) const
{
  for (Index f : faces)
  {
    Prefetch(&this->Faces[f]);
    Prefetch(&this->FaceAlive[f]);
  }
}

// Requests what the checks and the collapse of (a, b) read first: the faces
// and neighbours of a and b, their spheres and the policy's data, so that
// these scattered cache misses overlap. No effect on results.
void MedialEdgeCollapse::PrefetchCollapse(Index a, Index b) const
{
  for (Index v : { a, b })
  {
    Prefetch(this->VertexFaces[v].data());
    Prefetch(this->VertexNeighbours[v].data());
    this->Policy.Prefetch(v);
  }
  for (Index v : { a, b })
  {
    this->PrefetchFaces(this->VertexFaces[v]);
    for (Index u : this->VertexNeighbours[v])
    {
      Prefetch(&this->Spheres[u]);
      Prefetch(this->VertexFaces[u].data());
    }
  }
}

// CollapseTaken without the re-evaluation; with `checked`, the link
// condition and the target placement's validity as found earlier.
void MedialEdgeCollapse::CollapseOnly(
  BatchItem& item, CollapseScratch& scratch, const CollapseCheck* checked)
{
  const Candidate& c = item.Taken;
  this->PrefetchCollapse(c.A, c.B);
  scratch.EulerNeutral = false;
  scratch.FoldsBeforeA = scratch.FoldsBeforeB = -1;
  scratch.MergedFaces = scratch.EulerNeutralMerges = 0;
  item.Pushes.clear();
  // The link condition depends on the connectivity alone: checked once,
  // not for every placement tried.
  const bool guarded =
    this->NumberAlive <= this->Options.TopologyGuardVertexCount && !this->Relaxed;
  bool linkHolds = true;
  if (guarded && checked)
  {
    linkHolds = checked->LinkHolds;
    scratch.EulerNeutral = checked->EulerNeutral;
  }
  else if (guarded)
  {
    linkHolds = this->LinkConditionHolds(c.A, c.B, scratch);
  }
  if (!linkHolds)
  {
    item.Collapsed = false;
  }
  else if (checked ? checked->Valid : this->CollapseIsValid(c.A, c.B, c.Target, scratch))
  {
    this->ApplyCollapse(c.A, c.B, c.Target, scratch);
    item.Collapsed = true;
  }
  else
  {
    item.Collapsed = this->CollapseAtFallback(c.A, c.B, scratch);
  }
  this->NoteCollapse(item, scratch);
}

// What a collapse did, for the counts.
void MedialEdgeCollapse::NoteCollapse(BatchItem& item, const CollapseScratch& scratch) const
{
  if (item.Collapsed)
  {
    item.EulerNeutral = scratch.EulerNeutral;
    item.MergedFaces = scratch.MergedFaces;
    item.EulerNeutralMerges = scratch.EulerNeutralMerges;
  }
}

// After a collapse: the policy's follow-up, then the merged vertex's edges.
void MedialEdgeCollapse::EvaluateMergedEdges(BatchItem& item, CollapseScratch& scratch)
{
  if (!item.Collapsed)
  {
    return;
  }
  const Index a = item.Taken.A;
  this->Policy.AfterCollapse(*this, a, scratch);
  // The neighbours' data lie scattered through memory: requested for all of
  // them first, so that the evaluations below do not wait for each in turn.
  for (Index u : this->VertexNeighbours[a])
  {
    Prefetch(this->VertexNeighbours[u].data());
    Prefetch(&this->Spheres[u]);
    this->Policy.Prefetch(u);
  }
  for (Index u : this->VertexNeighbours[a])
  {
    for (Index v : this->VertexNeighbours[u])
    {
      Prefetch(&this->Spheres[v]);
    }
  }
  for (Index u : this->VertexNeighbours[a])
  {
    const Candidate next = this->MakeCandidate(a, u, scratch);
    if (next.Cost < HUGE_VAL)
    {
      item.Pushes.push_back(next);
    }
  }
}

// Counts a batch member's collapse (or rejection) and queues the edges it
// re-evaluated; true when it collapsed.
bool MedialEdgeCollapse::Finish(const BatchItem& item)
{
  if (!item.Collapsed)
  {
    ++this->Counts.RejectedCollapses; // not retried until its neighbourhood changes
    return false;
  }
  --this->NumberAlive;
  ++this->Counts.Collapses;
  this->Counts.EulerNeutralCollapses += item.EulerNeutral ? 1 : 0;
  this->Counts.RelaxedCollapses += this->Relaxed ? 1 : 0;
  this->Counts.FoldingAllowedCollapses += this->FoldsAllowedAtLast ? 1 : 0;
  this->Counts.MergedFaces += item.MergedFaces;
  this->Counts.EulerNeutralMerges += item.EulerNeutralMerges;
  for (const Candidate& next : item.Pushes)
  {
    this->Queue.Push(next);
  }
  return true;
}

// The next current candidate, taken off the queue, unless the queue is dry or
// its cheapest costs more than the limit.
bool MedialEdgeCollapse::TakeNext(Candidate& out)
{
  this->AboveCostLimit = false;
  const Candidate* top = this->Queue.TopCurrent();
  if (top == nullptr)
  {
    return false;
  }
  if (top->Cost > this->Options.MaximumCost)
  {
    this->AboveCostLimit = true;
    return false;
  }
  out = *top;
  this->Queue.PopTop();
  return true;
}

namespace
{
// A second thread that runs one posted job at a time, handed over by
// spinning on atomics. Written by hand: a job here takes about 10 us, and
// waking a TBB worker for each (parallel_invoke) cost as much as it saved.
class SpinningHelper
{
public:
  SpinningHelper()
    : Thread([this] { this->Loop(); })
  {
  }
  ~SpinningHelper()
  {
    this->Stop.store(true, std::memory_order_release);
    this->Thread.join();
  }
  SpinningHelper(const SpinningHelper&) = delete;
  SpinningHelper& operator=(const SpinningHelper&) = delete;

  /// Runs `job` on the helper; Wait() before posting another or touching
  /// what it uses.
  void Post(const std::function<void()>* job)
  {
    this->Job = job;
    this->Posted.fetch_add(1, std::memory_order_release);
  }
  void Wait() const
  {
    const std::uint64_t posted = this->Posted.load(std::memory_order_relaxed);
    for (unsigned spins = 0; this->Done.load(std::memory_order_acquire) != posted; ++spins)
    {
      if (spins > 1000)
      {
        std::this_thread::yield();
      }
    }
  }

private:
  void Loop()
  {
    std::uint64_t seen = 0;
    unsigned spins = 0;
    while (!this->Stop.load(std::memory_order_acquire))
    {
      const std::uint64_t posted = this->Posted.load(std::memory_order_acquire);
      if (posted == seen)
      {
        // Idle: between jobs the other thread spends a few microseconds;
        // past that, give the core away.
        if (++spins > 4000)
        {
          std::this_thread::yield();
        }
        continue;
      }
      spins = 0;
      (*this->Job)();
      seen = posted;
      this->Done.store(posted, std::memory_order_release);
    }
  }

  const std::function<void()>* Job = nullptr;
  std::atomic<std::uint64_t> Posted{ 0 }, Done{ 0 };
  std::atomic<bool> Stop{ false };
  std::thread Thread;
};
}

// CollapseUntil one candidate at a time, in exactly the sequential greedy
// order, with two threads: while one collapses the current candidate, the
// other runs the validity checks of the next one in the queue when their
// regions are disjoint (GatherRegion: neither writes what the other reads);
// then both re-evaluate the merged vertex's edges. The checked candidate is
// the next one in the sequential order unless an edge the collapse
// re-evaluated is cheaper (about 4% of the time on CAD meshes); then it goes
// back to the queue and its checks are dropped. The checks depend on the
// vertex count only through the link condition: whether it guards is
// decided when the candidate's turn comes, and checks made on the other side
// of the strict link condition's threshold are redone.
bool MedialEdgeCollapse::CollapseInOrder(
  std::size_t target, const std::function<bool(std::size_t)>& progress)
{
  struct Checked
  {
    bool Done = false;
    bool Strict = false; // the link condition was strict (by the vertex count)
    CollapseCheck Found;
  };
  auto strict = [this]
  { return this->NumberAlive <= this->Options.StrictLinkConditionVertexCount; };
  if (this->RegionStamp.size() != this->Spheres.size())
  {
    this->RegionStamp.assign(this->Spheres.size(), 0);
    this->ClaimStamp = 0;
  }
  this->Batch.resize(1);
  BatchItem& item = this->Batch[0];
  CollapseScratch scratches[2];
  std::vector<Index> regions[2];
  int current = 0; // the scratch (and checks) of the current candidate
  Checked checks[2];
  Candidate next;
  bool haveCurrent = false;
  std::size_t sinceReport = 0;
  // The checks of the next candidate, for the helper.
  auto checkNext = [&]
  {
    CollapseScratch& scratch = scratches[1 - current];
    Checked& check = checks[1 - current];
    scratch.FoldsBeforeA = scratch.FoldsBeforeB = -1;
    scratch.MergedFaces = scratch.EulerNeutralMerges = 0;
    check.Strict = strict();
    check.Found.LinkHolds = this->LinkConditionHolds(next.A, next.B, scratch);
    check.Found.EulerNeutral = scratch.EulerNeutral;
    check.Found.Valid = this->CollapseIsValid(next.A, next.B, next.Target, scratch);
    check.Done = true;
  };
  // Evaluations of the merged vertex's edges, taken one at a time by
  // either thread (results by index, so the order of pushes is fixed).
  struct Evaluations
  {
    std::atomic<int> State{ 0 }; // 1: Vertex and Count are set
    std::atomic<std::size_t> Next{ 0 };
    Index Vertex = -1;
    std::size_t Count = 0;
  };
  Evaluations shared;
  std::vector<Candidate> evaluated;
  auto evaluate = [&](CollapseScratch& scratch)
  {
    for (std::size_t k; (k = shared.Next.fetch_add(1, std::memory_order_relaxed)) < shared.Count;)
    {
      evaluated[k] =
        this->MakeCandidate(shared.Vertex, this->VertexNeighbours[shared.Vertex][k], scratch);
    }
  };
  CollapseScratch helperScratch;
  bool checkAhead = false;
  const std::function<void()> helperJob = [&]
  {
    if (checkAhead)
    {
      checkNext();
    }
    while (shared.State.load(std::memory_order_acquire) == 0)
    {
    }
    evaluate(helperScratch);
  };
  // The helper only with a second thread to run it on; declared after what
  // its jobs use, so that it stops first.
  std::unique_ptr<SpinningHelper> helper;
  if (tbb::this_task_arena::max_concurrency() > 1)
  {
    helper = std::make_unique<SpinningHelper>();
  }
  // Leaving with a job posted (an exception on this thread): release the
  // job if it still waits for the evaluations, and let it finish.
  bool posted = false;
  struct Settle
  {
    std::unique_ptr<SpinningHelper>& Helper;
    Evaluations& Shared;
    const bool& Posted;
    ~Settle()
    {
      if (this->Posted)
      {
        if (this->Shared.State.load(std::memory_order_relaxed) == 0)
        {
          this->Shared.Count = 0;
          this->Shared.State.store(1, std::memory_order_release);
        }
        this->Helper->Wait();
      }
    }
  } settle{ helper, shared, posted };
  while (this->NumberAlive > target)
  {
    if (!haveCurrent && !this->TakeNext(item.Taken))
    {
      if (this->AboveCostLimit)
      {
        this->Queue.Clear();
      }
      break;
    }
    if (this->ClaimStamp > std::numeric_limits<std::uint32_t>::max() - 4)
    {
      std::fill(this->RegionStamp.begin(), this->RegionStamp.end(), 0);
      this->ClaimStamp = 0;
    }
    haveCurrent = false;
    const bool haveNext = this->Options.CheckAhead && this->TakeNext(next);
    // Disjoint regions: claim the current one's, then try the next one's.
    bool overlap = true;
    if (haveNext)
    {
      this->BatchStart = this->ClaimStamp + 1;
      this->GatherRegion(item.Taken.A, item.Taken.B, regions[0]);
      this->ClaimRegion(regions[0]);
      this->GatherRegion(next.A, next.B, regions[1]);
      overlap = !this->ClaimRegion(regions[1]);
    }
    // Checks made on the other side of the strict link condition's
    // threshold are redone.
    const Checked& check = checks[current];
    const bool useCheck = check.Done && check.Strict == strict();
    checks[1 - current].Done = false;
    checkAhead = haveNext && !overlap && helper;
    shared.State.store(0, std::memory_order_relaxed);
    if (helper)
    {
      helper->Post(&helperJob);
      posted = true;
    }
    this->CollapseOnly(item, scratches[current], useCheck ? &check.Found : nullptr);
    // The merged vertex's edges: the policy's follow-up, then the
    // evaluations, shared with the helper once it is done checking.
    std::size_t count = 0;
    if (item.Collapsed)
    {
      this->Policy.AfterCollapse(*this, item.Taken.A, scratches[current]);
      count = this->VertexNeighbours[item.Taken.A].size();
      evaluated.resize(count);
    }
    shared.Vertex = item.Taken.A;
    shared.Count = count;
    shared.Next.store(0, std::memory_order_relaxed);
    shared.State.store(1, std::memory_order_release);
    evaluate(scratches[current]);
    if (helper)
    {
      helper->Wait();
      posted = false;
    }
    for (std::size_t k = 0; k < count; ++k)
    {
      if (evaluated[k].Cost < HUGE_VAL)
      {
        item.Pushes.push_back(evaluated[k]);
      }
    }
    checks[current].Done = false;
    ++this->Counts.Batches;
    sinceReport += this->Finish(item) ? 1 : 0;
    // The next one (unless the collapse made it stale, when its regions
    // overlapped) is next in the sequential order too when no re-evaluated
    // edge comes before it.
    if (haveNext && EndpointsUnchanged{ &this->Version }(next))
    {
      const bool first = std::none_of(item.Pushes.begin(), item.Pushes.end(),
        [&](const Candidate& p) { return CandidateQueue::Before(p, next); });
      if (first && this->NumberAlive > target)
      {
        item.Taken = next;
        haveCurrent = true;
        current = 1 - current;
      }
      else
      {
        this->Queue.Push(next);
      }
    }
    if (sinceReport >= 256)
    {
      sinceReport = 0;
      if (!progress(this->NumberAlive))
      {
        return false;
      }
    }
  }
  if (haveCurrent)
  {
    this->Queue.Push(item.Taken);
  }
  return true;
}

// Collapses the cheapest valid edges until `target` vertices remain, the
// queue runs dry or the cost limit is reached. Returns false on abort.
bool MedialEdgeCollapse::CollapseUntil(
  std::size_t target, const std::function<bool(std::size_t)>& progress)
{
  if (this->Options.MaximumBatch <= 1)
  {
    return this->CollapseInOrder(target, progress);
  }
  if (this->RegionStamp.size() != this->Spheres.size())
  {
    this->RegionStamp.assign(this->Spheres.size(), 0);
    this->ClaimStamp = 0;
  }
  this->Batch.resize(std::max<std::size_t>(this->Options.MaximumBatch, 1));
  tbb::enumerable_thread_specific<CollapseScratch> scratches;
  std::size_t sinceReport = 0;
  while (this->NumberAlive > target)
  {
    // The batch: the cheapest candidates whose regions are disjoint from
    // those of every cheaper one looked at. Those passed over (their region
    // meets a cheaper one's) go back to the queue.
    const std::size_t limit = this->BatchLimit(target);
    if (this->ClaimStamp > std::numeric_limits<std::uint32_t>::max() - 2 * (limit + LookAhead))
    {
      std::fill(this->RegionStamp.begin(), this->RegionStamp.end(), 0);
      this->ClaimStamp = 0;
    }
    this->BatchStart = this->ClaimStamp + 1;
    std::size_t taken = 0, next = 0;
    this->Looked.clear();
    this->PassedOver.clear();
    this->AboveCostLimit = false;
    while (taken < limit && this->PassedOver.size() < LookAhead)
    {
      // More candidates, as many as the last batch looked at (the rest go
      // back to the queue).
      if (next == this->Looked.size() &&
        (this->AboveCostLimit ||
          !this->LookFurther(limit == 1
              ? 1
              : std::min(std::max<std::size_t>(this->LookedLastTime, 8), limit + LookAhead - next),
            limit > 1)))
      {
        break;
      }
      // (The first candidate of a batch always finds its region free; one
      // taken alone need not claim it at all.)
      if (limit == 1 || this->ClaimRegion(this->Regions[next]))
      {
        this->Batch[taken++].Taken = this->Looked[next];
      }
      else
      {
        this->PassedOver.push_back(this->Looked[next]);
      }
      ++next;
    }
    this->LookedLastTime = next;
    for (std::size_t k = next; k < this->Looked.size(); ++k)
    {
      this->Queue.Push(this->Looked[k]);
    }
    for (const Candidate& c : this->PassedOver)
    {
      this->Queue.Push(c);
    }
    if (taken == 0)
    {
      if (this->AboveCostLimit)
      {
        this->Queue.Clear();
      }
      break;
    }
    ++this->Counts.Batches;
    if (taken == 1)
    {
      this->CollapseTaken(this->Batch[0], this->Scratch);
    }
    else
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, taken, 1),
        [&](const tbb::blocked_range<std::size_t>& r)
        {
          auto& scratch = scratches.local();
          for (std::size_t k = r.begin(); k != r.end(); ++k)
          {
            this->CollapseTaken(this->Batch[k], scratch);
          }
        });
    }
    for (std::size_t k = 0; k < taken; ++k)
    {
      sinceReport += this->Finish(this->Batch[k]) ? 1 : 0;
    }
    if (sinceReport >= 256)
    {
      sinceReport = 0;
      if (!progress(this->NumberAlive))
      {
        return false;
      }
    }
  }
  return true;
}

EdgeCollapseCounts MedialEdgeCollapse::Run()
{
  const auto start = std::chrono::steady_clock::now();
  const std::size_t nv = this->Spheres.size();
  auto report = [this](double f) { return !this->Options.Progress || this->Options.Progress(f); };

  const std::vector<Index> urgent = this->Policy.Prepare(*this);
  this->PushAllEdges();
  for (Index v : urgent)
  {
    for (Index u : this->VertexNeighbours[v])
    {
      Candidate c = this->MakeCandidate(v, u, this->Scratch);
      c.Cost = -1.0; // before any other collapse
      this->Queue.Push(c);
    }
  }
  this->Counts.QueueInitialisationSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!report(0.1))
  {
    this->Counts.Aborted = true;
    return this->Counts;
  }

  const std::size_t target = std::max<std::size_t>(1, this->Options.TargetNumberOfVertices);
  const double toRemove = static_cast<double>(nv > target ? nv - target : 1);
  auto progress = [&](std::size_t alive)
  { return report(0.1 + 0.85 * std::min(1.0, static_cast<double>(nv - alive) / toRemove)); };
  // Forced snaps fold triangles that the urgent collapses around them do not
  // always unfold, and no other collapse will (each may only keep or lower
  // the folds around it). Short of the target by one vertex per forced snap
  // at most, collapses chosen to remove them (CollapseFolds) come first,
  // then the rest down to the target.
  const std::size_t reserve = this->Options.PreventFolds
    ? std::min(urgent.size(), this->NumberAlive - std::min(this->NumberAlive, target))
    : 0;
  if (!this->CollapseUntil(target + reserve, progress))
  {
    this->Counts.Aborted = true;
    return this->Counts;
  }
  if (reserve > 0)
  {
    this->CollapseFolds(target);
    if (!this->CollapseUntil(target, progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
  }
  // Stalled because every remaining collapse would fold triangles onto each
  // other: where a tube's thin sheets must shrink to a curve, the last
  // strips of sliver triangles cannot collapse otherwise. Go on without the
  // fold guard and count those collapses.
  if (this->NumberAlive > target && this->FoldGuard)
  {
    this->FoldGuard = false;
    this->FoldsAllowedAtLast = true;
    this->PushAllEdges();
    if (!this->CollapseUntil(target, progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
  }
  // Stalled below the topology guard (no collapse keeps the link condition,
  // as in a contractible but non-collapsible "foam" of sheets): unless the
  // guard is strict, reach the target anyway and count those collapses.
  if (this->NumberAlive > target && this->NumberAlive <= this->Options.TopologyGuardVertexCount &&
    !this->Options.StrictTopologyGuard)
  {
    this->Relaxed = true;
    this->PushAllEdges();
    if (!this->CollapseUntil(target, progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
  }
  report(1.0);
  return this->Counts;
}

MedialMesh MedialEdgeCollapse::Output(std::vector<Index>& outputToInput) const
{
  MedialMesh out;
  outputToInput.clear();
  std::vector<Index> newId(this->Spheres.size(), -1);
  for (std::size_t v = 0; v < this->Spheres.size(); ++v)
  {
    if (!this->VertexAlive[v])
    {
      continue;
    }
    newId[v] = static_cast<Index>(out.Centers.size());
    outputToInput.push_back(static_cast<Index>(v));
    const Sphere& s = this->Spheres[v];
    out.Centers.push_back(this->UnitFrame.From({ s[0], s[1], s[2] }));
    out.Radii.push_back(s[3] / this->UnitFrame.Scale);
  }
  for (std::size_t f = 0; f < this->Faces.size(); ++f)
  {
    if (this->FaceAlive[f])
    {
      const auto& t = this->Faces[f];
      out.Faces.push_back({ newId[t[0]], newId[t[1]], newId[t[2]] });
    }
  }
  for (std::size_t v = 0; v < this->Spheres.size(); ++v)
  {
    if (!this->VertexAlive[v])
    {
      continue;
    }
    for (Index u : this->VertexNeighbours[v])
    {
      if (static_cast<Index>(v) < u)
      {
        out.Edges.push_back({ newId[v], newId[u] });
      }
    }
  }
  return out;
}
}
