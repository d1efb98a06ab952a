// SPDX-License-Identifier: GPL-3.0-or-later
// Priority queue of edge-collapse candidates for greedy simplifiers.
#ifndef medialaxis_CollapseQueue_h
#define medialaxis_CollapseQueue_h

#include "Mesh/MedialMesh.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace medialaxis
{
/// Min-queue of collapse candidates with lazy invalidation: an entry records
/// the versions of both endpoints when it was evaluated and is stale once
/// either has changed.
///
/// Every collapse re-evaluates the merged vertex's edges, so stale entries
/// pile up, and popping through a large heap was the biggest sequential cost
/// of simplification (cache misses on every level below the first few, for
/// half a million initial edges). Hence, written by hand rather than with
/// std::priority_queue or boost::heap, as a bucketed heap:
///  - entries are kept in buckets by cost range, with bounds at quantiles of
///    the costs (a few thousand entries each); only the cheapest bucket is a
///    heap (4-ary: one cache line holds all children of a node), small
///    enough to stay in cache; the others are unordered arrays that a push
///    appends to;
///  - when the heap runs out, the next bucket is filtered of stale entries
///    and heapified; the last bucket (no upper bound: costs rise as the
///    simplification goes on) is split at new quantiles first when large;
///  - stale entries are also dropped in bulk whenever the pushes since the
///    last clean-up exceed the size it left, which keeps the queue within
///    about twice the number of live candidates at amortised O(1) per push.
/// The heap holds every entry cheaper than its bucket's upper bound, and
/// the other buckets only entries at least as dear, so its top is the
/// cheapest entry of the queue.
///
/// Order: cheapest first; equal costs by (A, B), then by versions, so the
/// pop sequence depends on the pushed entries alone, not on the layout.
///
/// `IsCurrent` tells whether an entry still describes the mesh: a functor
/// type rather than std::function, since it runs on every entry popped.
template <typename Payload, typename IsCurrent>
class CollapseQueue
{
public:
  struct Entry
  {
    double Cost;
    Index A, B;
    std::uint32_t VersionA, VersionB;
    Payload Target;
  };

  explicit CollapseQueue(IsCurrent isCurrent)
    : Current(std::move(isCurrent))
  {
    this->Clear();
  }

  /// Pushes many entries at once, into buckets at quantiles of their costs
  /// (pass an rvalue to spare a copy).
  void PushAll(std::vector<Entry> entries)
  {
    this->MoveAllTo(entries);
    const double lowest = -std::numeric_limits<double>::infinity();
    std::vector<double> bounds = QuantileBounds(entries, lowest);
    this->Stored = entries.size();
    this->Spread(std::move(entries), std::move(bounds), lowest);
    this->SizeAfterCleanUp = this->Stored;
    this->PushesSinceCleanUp = 0;
  }

  void Push(const Entry& entry)
  {
    this->Place(entry);
    ++this->Stored;
    if (++this->PushesSinceCleanUp > std::max<std::size_t>(this->SizeAfterCleanUp, 4096))
    {
      this->DropStale();
    }
  }

  /// The cheapest current entry (stale ones above it are dropped), or null
  /// when none is left; valid until the next push.
  const Entry* TopCurrent()
  {
    for (;;)
    {
      while (!this->Heap.empty())
      {
        if (this->Current(this->Heap.front()))
        {
          return &this->Heap.front();
        }
        this->PopTop();
      }
      if (!this->OpenNextBucket())
      {
        return nullptr;
      }
    }
  }

  /// Removes the cheapest entry, current or not (TopCurrent first).
  void PopTop()
  {
    this->Heap.front() = this->Heap.back();
    this->Heap.pop_back();
    --this->Stored;
    if (!this->Heap.empty())
    {
      this->SiftDown(0);
    }
  }

  void Clear()
  {
    this->Heap.clear();
    this->Buckets.assign(1, std::vector<Entry>());
    this->Bounds.clear();
    this->NextBucket = 0;
    this->HeapLimit = -std::numeric_limits<double>::infinity();
    this->Stored = this->PushesSinceCleanUp = this->SizeAfterCleanUp = 0;
  }

  /// Entries held, stale ones included.
  std::size_t Size() const { return this->Stored; }

  /// True when `p` is popped before `q`.
  static bool Before(const Entry& p, const Entry& q)
  {
    if (p.Cost != q.Cost)
    {
      return p.Cost < q.Cost;
    }
    return std::tie(p.A, p.B, p.VersionA, p.VersionB) < std::tie(q.A, q.B, q.VersionA, q.VersionB);
  }

private:
  static constexpr std::size_t Arity = 4;
  // Entries per bucket when costs are split at quantiles.
  static constexpr std::size_t BucketSize = 4096;

  void SiftUp(std::size_t i)
  {
    const Entry entry = this->Heap[i];
    while (i > 0)
    {
      const std::size_t parent = (i - 1) / Arity;
      if (!Before(entry, this->Heap[parent]))
      {
        break;
      }
      this->Heap[i] = this->Heap[parent];
      i = parent;
    }
    this->Heap[i] = entry;
  }

  void SiftDown(std::size_t i)
  {
    const Entry entry = this->Heap[i];
    const std::size_t n = this->Heap.size();
    for (;;)
    {
      const std::size_t first = Arity * i + 1;
      if (first >= n)
      {
        break;
      }
      std::size_t best = first;
      for (std::size_t c = first + 1; c < std::min(first + Arity, n); ++c)
      {
        best = Before(this->Heap[c], this->Heap[best]) ? c : best;
      }
      if (!Before(this->Heap[best], entry))
      {
        break;
      }
      this->Heap[i] = this->Heap[best];
      i = best;
    }
    this->Heap[i] = entry;
  }

  void Heapify()
  {
    const std::size_t n = this->Heap.size();
    for (std::size_t i = n / Arity + 1; i-- > 0;)
    {
      if (i < n)
      {
        this->SiftDown(i);
      }
    }
  }

  // Removes the stale entries of `list`, keeping the order of the others.
  std::size_t Filter(std::vector<Entry>& list)
  {
    const auto end = std::remove_if(
      list.begin(), list.end(), [this](const Entry& e) { return !this->Current(e); });
    const std::size_t dropped = list.end() - end;
    list.erase(end, list.end());
    return dropped;
  }

  // Makes the next non-empty bucket the heap; false when none is left. The
  // last bucket is split first when large.
  bool OpenNextBucket()
  {
    while (this->NextBucket < this->Buckets.size())
    {
      const std::size_t b = this->NextBucket++;
      std::vector<Entry>& bucket = this->Buckets[b];
      this->Stored -= this->Filter(bucket);
      if (b == this->Bounds.size() && bucket.size() > 2 * BucketSize)
      {
        const double lower = b > 0 ? this->Bounds[b - 1] : this->HeapLimit;
        std::vector<double> bounds = QuantileBounds(bucket, lower);
        if (!bounds.empty())
        {
          std::vector<Entry> all = std::move(bucket);
          this->Spread(std::move(all), std::move(bounds), lower);
          continue;
        }
      }
      this->HeapLimit =
        b < this->Bounds.size() ? this->Bounds[b] : std::numeric_limits<double>::infinity();
      if (!bucket.empty())
      {
        this->Heap = std::move(bucket);
        bucket = std::vector<Entry>();
        this->Heapify();
        return true;
      }
    }
    return false;
  }

  // Bucket bounds above `lower` at quantiles of the costs of `list` (of a
  // regular sample of them), BucketSize entries apart; none for a short list.
  static std::vector<double> QuantileBounds(const std::vector<Entry>& list, double lower)
  {
    std::vector<double> sample, bounds;
    const std::size_t buckets = list.size() / BucketSize;
    if (buckets < 2)
    {
      return bounds;
    }
    for (std::size_t i = 0; i < list.size(); i += BucketSize / 16)
    {
      sample.push_back(list[i].Cost);
    }
    std::sort(sample.begin(), sample.end());
    for (std::size_t k = 1; k < buckets; ++k)
    {
      const double bound = sample[k * sample.size() / buckets];
      if (bound > lower && (bounds.empty() || bound > bounds.back()))
      {
        bounds.push_back(bound);
      }
    }
    return bounds;
  }

  // Replaces the (empty) buckets with `all` split at `bounds`; every cost is
  // at least `lower`, the heap's limit from now on (the heap is empty).
  // Buckets are sized first: `all` and the buckets are the peak memory.
  void Spread(std::vector<Entry> all, std::vector<double> bounds, double lower)
  {
    this->Bounds = std::move(bounds);
    this->Buckets.assign(this->Bounds.size() + 1, std::vector<Entry>());
    this->NextBucket = 0;
    this->HeapLimit = lower;
    std::vector<std::size_t> counts(this->Buckets.size(), 0);
    for (const Entry& e : all)
    {
      ++counts[this->BucketOf(e.Cost)];
    }
    for (std::size_t b = 0; b < counts.size(); ++b)
    {
      this->Buckets[b].reserve(counts[b]);
    }
    for (const Entry& e : all)
    {
      this->Place(e);
    }
  }

  // The first unopened bucket whose upper bound exceeds `cost` (the last one
  // has none).
  std::size_t BucketOf(double cost) const
  {
    return std::upper_bound(this->Bounds.begin() + this->NextBucket, this->Bounds.end(), cost) -
      this->Bounds.begin();
  }

  // Into the heap when cheaper than its limit, else into its bucket.
  void Place(const Entry& entry)
  {
    if (entry.Cost < this->HeapLimit)
    {
      this->Heap.push_back(entry);
      this->SiftUp(this->Heap.size() - 1);
    }
    else
    {
      this->Buckets[this->BucketOf(entry.Cost)].push_back(entry);
    }
  }

  // Moves every entry (heap and buckets) to `out` and empties the queue.
  void MoveAllTo(std::vector<Entry>& out)
  {
    out.insert(out.end(), this->Heap.begin(), this->Heap.end());
    for (std::size_t b = this->NextBucket; b < this->Buckets.size(); ++b)
    {
      out.insert(out.end(), this->Buckets[b].begin(), this->Buckets[b].end());
    }
    this->Clear();
  }

  void DropStale()
  {
    this->Stored -= this->Filter(this->Heap);
    this->Heapify();
    for (std::size_t b = this->NextBucket; b < this->Buckets.size(); ++b)
    {
      this->Stored -= this->Filter(this->Buckets[b]);
    }
    this->SizeAfterCleanUp = this->Stored;
    this->PushesSinceCleanUp = 0;
  }

  IsCurrent Current;
  std::vector<Entry> Heap; // entries cheaper than HeapLimit
  double HeapLimit = -std::numeric_limits<double>::infinity();
  // Bucket b (from NextBucket on) holds costs in [Bounds[b - 1], Bounds[b]);
  // the last one, Buckets[Bounds.size()], has no upper bound.
  std::vector<std::vector<Entry>> Buckets;
  std::vector<double> Bounds;
  std::size_t NextBucket = 0;
  std::size_t Stored = 0;
  std::size_t PushesSinceCleanUp = 0;
  std::size_t SizeAfterCleanUp = 0;
};
} // namespace medialaxis

#endif
