// SPDX-License-Identifier: GPL-3.0-or-later
// The validity checks of one collapse (no degenerate, flipped, folded or
// duplicate triangles) and the collapse itself.
#include "Simplification/EdgeCollapse.h"

#include <algorithm>
#include <iterator>

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
  // A fold repair undoes what forced moves did, whatever the bound.
  return scratch.FewerFolds || this->IgnorePolicyBound ||
    this->Policy.WithinBound(*this, a, b, target, scratch);
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
}
