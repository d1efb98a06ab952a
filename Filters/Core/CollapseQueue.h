// SPDX-License-Identifier: GPL-3.0-or-later
// Priority queue of edge-collapse candidates for greedy simplifiers.
#ifndef medialaxis_CollapseQueue_h
#define medialaxis_CollapseQueue_h

#include "MedialMesh.h"

#include <algorithm>
#include <cstdint>
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
/// pile up, and popping through a large heap of fat entries was the single
/// biggest cost of simplification. Hence, written by hand rather than with
/// std::priority_queue or boost::heap: the heap holds 16-byte keys (cost and
/// the slot of the candidate's record), is 4-ary (one cache line holds all
/// children of a node, half the depth of a binary heap), and stale entries
/// are dropped in bulk (filter + linear heapify) whenever the pushes since
/// the last clean-up exceed the size it left, which keeps the heap within
/// about twice the number of live candidates at amortised O(1) per push.
///
/// Order: cheapest first; equal costs by (A, B), then by versions, so the
/// pop sequence depends on the pushed entries alone, not on the heap layout.
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
  }

  /// Pushes many entries at once: a linear heapify rather than one sift-up
  /// each.
  void PushAll(const std::vector<Entry>& entries)
  {
    for (const Entry& entry : entries)
    {
      this->Entries.push_back(entry);
      this->Heap.push_back({ entry.Cost, static_cast<std::uint32_t>(this->Entries.size() - 1) });
    }
    this->Heapify();
  }

  void Push(const Entry& entry)
  {
    std::uint32_t slot;
    if (this->FreeSlots.empty())
    {
      slot = static_cast<std::uint32_t>(this->Entries.size());
      this->Entries.push_back(entry);
    }
    else
    {
      slot = this->FreeSlots.back();
      this->FreeSlots.pop_back();
      this->Entries[slot] = entry;
    }
    this->Heap.push_back({ entry.Cost, slot });
    this->SiftUp(this->Heap.size() - 1);
    if (++this->PushesSinceCleanUp > std::max<std::size_t>(this->SizeAfterCleanUp, 4096))
    {
      this->DropStale();
    }
  }

  /// The cheapest current entry (stale ones above it are dropped), or null
  /// when none is left; valid until the next push.
  const Entry* TopCurrent()
  {
    while (!this->Heap.empty())
    {
      const std::uint32_t slot = this->Heap.front().Slot;
      if (this->Current(this->Entries[slot]))
      {
        return &this->Entries[slot];
      }
      this->PopTop();
    }
    return nullptr;
  }

  /// Removes the cheapest entry, current or not.
  void PopTop()
  {
    this->FreeSlots.push_back(this->Heap.front().Slot);
    this->Heap.front() = this->Heap.back();
    this->Heap.pop_back();
    if (!this->Heap.empty())
    {
      this->SiftDown(0);
    }
  }

  void Clear()
  {
    this->Heap.clear();
    this->Entries.clear();
    this->FreeSlots.clear();
    this->PushesSinceCleanUp = this->SizeAfterCleanUp = 0;
  }

  std::size_t Size() const { return this->Heap.size(); }

private:
  struct Key
  {
    double Cost;
    std::uint32_t Slot;
  };
  static constexpr std::size_t Arity = 4;

  // True when `x` is popped before `y`.
  bool Before(const Key& x, const Key& y) const
  {
    if (x.Cost != y.Cost)
    {
      return x.Cost < y.Cost;
    }
    const Entry& p = this->Entries[x.Slot];
    const Entry& q = this->Entries[y.Slot];
    return std::tie(p.A, p.B, p.VersionA, p.VersionB) < std::tie(q.A, q.B, q.VersionA, q.VersionB);
  }

  void SiftUp(std::size_t i)
  {
    const Key key = this->Heap[i];
    while (i > 0)
    {
      const std::size_t parent = (i - 1) / Arity;
      if (!this->Before(key, this->Heap[parent]))
      {
        break;
      }
      this->Heap[i] = this->Heap[parent];
      i = parent;
    }
    this->Heap[i] = key;
  }

  void SiftDown(std::size_t i)
  {
    const Key key = this->Heap[i];
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
        best = this->Before(this->Heap[c], this->Heap[best]) ? c : best;
      }
      if (!this->Before(this->Heap[best], key))
      {
        break;
      }
      this->Heap[i] = this->Heap[best];
      i = best;
    }
    this->Heap[i] = key;
  }

  void DropStale()
  {
    std::size_t kept = 0;
    for (const Key& key : this->Heap)
    {
      if (this->Current(this->Entries[key.Slot]))
      {
        this->Heap[kept++] = key;
      }
      else
      {
        this->FreeSlots.push_back(key.Slot);
      }
    }
    this->Heap.resize(kept);
    this->Heapify();
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
    this->SizeAfterCleanUp = n;
    this->PushesSinceCleanUp = 0;
  }

  IsCurrent Current;
  std::vector<Key> Heap;
  std::vector<Entry> Entries; // by slot
  std::vector<std::uint32_t> FreeSlots;
  std::size_t PushesSinceCleanUp = 0;
  std::size_t SizeAfterCleanUp = 0;
};
} // namespace medialaxis

#endif
