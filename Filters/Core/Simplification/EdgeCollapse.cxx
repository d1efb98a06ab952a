// SPDX-License-Identifier: GPL-3.0-or-later
// The collapse framework's driver: the mesh set up from the input, the
// queue filled, the loop run to the target (with fold repair and the guards
// lifted when collapses stall) and the output read back.
#include "Simplification/EdgeCollapse.h"

#include "Support/SortedLists.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace medialaxis
{
MedialEdgeCollapse::MedialEdgeCollapse(const MedialMesh& input, const Normalisation& frame,
  const EdgeCollapseOptions& options, CollapsePolicy& policy)
  : Options(options)
  , Policy(policy)
  , UnitFrame(frame)
  , Queue(EndpointsUnchanged{ &this->Version })
{
  this->FoldGuard = options.PreventFolds;
  this->GuardCosine = std::cos(options.FoldAngle * 3.14159265358979323846 / 180.0);
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

void MedialEdgeCollapse::PushAllEdges(bool spikesOnly)
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
      if (static_cast<Index>(v) < u &&
        (!spikesOnly ||
          this->StabilityRatio(static_cast<Index>(v), u) < this->Options.SpikeThreshold))
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
  if (this->Options.RequeueSpikes)
  {
    if (!this->CollapseWithinBounds(
          target + reserve + std::max<std::size_t>(1, target / 50), progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
    this->PushAllEdges(true);
  }
  if (!this->CollapseWithoutFins(target + reserve, progress))
  {
    this->Counts.Aborted = true;
    return this->Counts;
  }
  if (reserve > 0)
  {
    this->CollapseFolds(target);
    if (!this->CollapseWithinBounds(target, progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
  }
  // Stalled because every remaining collapse would pleat: the pleat guard
  // gives way to the fold guard (no two triangles folded onto each other),
  // also when the policy stops at stalls.
  if (this->NumberAlive > target && this->FoldGuard && this->GuardCosine < FoldCosine)
  {
    this->GuardCosine = FoldCosine;
    this->PushAllEdges();
    if (!this->CollapseWithinBounds(target, progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
  }
  // Stalled because every remaining collapse would fold triangles onto each
  // other: where a tube's thin sheets must shrink to a curve, the last
  // strips of sliver triangles cannot collapse otherwise. Go on without the
  // fold guard and count those collapses.
  if (this->NumberAlive > target && this->FoldGuard && !this->Options.StopWhenStalled)
  {
    this->FoldGuard = false;
    this->FoldsAllowedAtLast = true;
    this->PushAllEdges();
    if (!this->CollapseWithinBounds(target, progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
  }
  // Stalled below the topology guard (no collapse keeps the link condition,
  // as in a contractible but non-collapsible "foam" of sheets): unless the
  // guard is strict, reach the target anyway and count those collapses.
  if (this->NumberAlive > target && this->NumberAlive <= this->Options.TopologyGuardVertexCount &&
    !this->Options.StrictTopologyGuard && !this->Options.StopWhenStalled)
  {
    this->Relaxed = true;
    this->PushAllEdges();
    if (!this->CollapseWithinBounds(target, progress))
    {
      this->Counts.Aborted = true;
      return this->Counts;
    }
  }
  report(1.0);
  return this->Counts;
}

bool MedialEdgeCollapse::CollapseWithinBounds(
  std::size_t target, const std::function<bool(std::size_t)>& progress)
{
  for (;;)
  {
    if (!this->CollapseUntil(target, progress))
    {
      return false;
    }
    if (this->NumberAlive <= target || !this->Policy.RaiseBound())
    {
      return true;
    }
    this->PushAllEdges();
  }
}

bool MedialEdgeCollapse::CollapseWithoutFins(
  std::size_t target, const std::function<bool(std::size_t)>& progress)
{
  const double budget = this->Options.FinBudget;
  if (!(budget > 0.0))
  {
    return this->CollapseWithinBounds(target, progress);
  }
  // Fins fold into their junctions at a few checkpoints on the way, so that
  // the collapses after them spend the spheres they free elsewhere; the
  // last one a little short of the target, which is then reached exactly.
  for (double factor : { 4.0, 2.0, 1.4, 1.1 })
  {
    const auto checkpoint = static_cast<std::size_t>(factor * static_cast<double>(target));
    if (this->NumberAlive > checkpoint)
    {
      if (!this->CollapseWithinBounds(checkpoint, progress))
      {
        return false;
      }
      this->CollapseFins(budget, this->Options.FinAreaShare);
    }
  }
  return this->CollapseWithinBounds(target, progress);
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
