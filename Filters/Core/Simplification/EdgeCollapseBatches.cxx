// SPDX-License-Identifier: GPL-3.0-or-later
// Parallel batches: the cheapest candidates whose regions are disjoint,
// collapsed at once with the same result at any thread count.
#include "Simplification/EdgeCollapse.h"

#include "Support/Prefetch.h"
#include "Support/SortedLists.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace medialaxis
{
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
}
