// SPDX-License-Identifier: GPL-3.0-or-later
// One collapse at a time in the strict greedy order, the next candidate's
// checks made ahead on a second thread.
#include "Simplification/EdgeCollapse.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <thread>

namespace medialaxis
{
namespace
{
// A second thread that runs one posted job at a time, handed over by
// spinning on atomics. Written by hand: a job here takes about 10 us, and
// waking a TBB worker for each (parallel_invoke) cost as much as it saved.
// A job the helper has not started when its result is wanted is run by the
// waiting thread instead: on a busy machine the helper may not get a core
// for milliseconds, and waiting for it made the CAD parts' simplification
// ten times slower than on one thread.
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
  void Wait()
  {
    const std::uint64_t posted = this->Posted.load(std::memory_order_relaxed);
    if (this->Claim(posted))
    {
      (*this->Job)();
      this->Done.store(posted, std::memory_order_release);
      return;
    }
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
      seen = posted;
      if (this->Claim(posted))
      {
        (*this->Job)();
        this->Done.store(posted, std::memory_order_release);
      }
    }
  }

  // Job number `job` goes to the first thread that asks for it.
  bool Claim(std::uint64_t job)
  {
    std::uint64_t before = job - 1;
    return this->Claimed.compare_exchange_strong(before, job, std::memory_order_acq_rel);
  }

  const std::function<void()>* Job = nullptr;
  std::atomic<std::uint64_t> Posted{ 0 }, Claimed{ 0 }, Done{ 0 };
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
    for (unsigned spins = 0; shared.State.load(std::memory_order_acquire) == 0; ++spins)
    {
      if (spins > 1000)
      {
        std::this_thread::yield(); // the collapse needs the core more
      }
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
}
