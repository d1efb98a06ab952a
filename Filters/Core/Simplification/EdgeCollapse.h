// SPDX-License-Identifier: GPL-3.0-or-later
// Greedy edge-collapse simplification of medial meshes: one framework (the
// mesh, its validity checks, the link condition and the queue) shared by
// every cost policy (Structural MAT's Atlas energy, Q-MAT's slab quadrics).
#ifndef medialaxis_EdgeCollapse_h
#define medialaxis_EdgeCollapse_h

#include "Envelope/PrimitiveRecords.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialMesh.h"
#include "Mesh/MedialMeshQuality.h"
#include "Mesh/MedialPrimitives.h"
#include "Simplification/CollapseQueue.h"
#include "Simplification/EdgeCollapseCounts.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace medialaxis
{
using Sphere = std::array<double, 4>; // centre and radius

/// The model is scaled into a unit frame so that a policy's constants mean the
/// same for every input; results are mapped back at the end.
struct Normalisation
{
  Point3 Origin{ 0, 0, 0 };
  double Scale = 1.0;
  Point3 To(const Point3& p) const { return this->Scale * (p - this->Origin); }
  Point3 From(const Point3& p) const { return (1.0 / this->Scale) * p + this->Origin; }
};

struct EdgeCollapseOptions
{
  std::size_t TargetNumberOfVertices = 1000;
  /// Stop when the cheapest collapse costs more.
  double MaximumCost = std::numeric_limits<double>::infinity();
  /// Edges whose stability ratio is below this are spikes: the flip test is
  /// skipped when they collapse (their needle triangles turn any way), and
  /// the fold test too unless FoldTestOnSpikes.
  double SpikeThreshold = 0.025;
  bool FoldTestOnSpikes = true;
  /// Queue every spike edge again when TargetNumberOfVertices + 2% remain:
  /// a spike refused earlier (by the fold or link tests of a neighbourhood
  /// that has changed since) gets another chance before the end.
  bool RequeueSpikes = false;
  /// Below this many vertices the link condition guards every collapse.
  std::size_t TopologyGuardVertexCount = std::numeric_limits<std::size_t>::max();
  /// See AtlasSimplifierOptions::FringeCollapses and
  /// EulerNeutralSpikeCollapses (the latter only for spike edges).
  bool FringeCollapses = false;
  bool EulerNeutralSpikeCollapses = false;
  std::size_t StrictLinkConditionVertexCount = 200;
  /// When no collapse below the guard keeps the link condition: stop (strict)
  /// or go on without it (counted in RelaxedCollapses).
  bool StrictTopologyGuard = false;
  /// Refuse collapses that fold two triangles onto each other (dihedral
  /// angle below 10 degrees); allowed anyway once nothing else is left.
  bool PreventFolds = true;
  /// The dihedral angle (degrees) below which PreventFolds counts two
  /// triangles as folded; up to 90 it also refuses pleats (sharp hinges).
  double FoldAngle = FoldAngleDegrees;
  /// Most collapses taken from the queue at once and made in parallel: the
  /// cheapest candidates whose edges lie at least five edges apart (the
  /// result is the same at any thread count, but not the strictly
  /// sequential greedy order). 1: one at a time, in that order. Large
  /// enough that a batch's work (tens of microseconds per collapse)
  /// outweighs handing it to the threads.
  std::size_t MaximumBatch = 64;
  /// One at a time (MaximumBatch 1) with a second thread: check the next
  /// candidate's validity there while the current one collapses. The same
  /// result either way; off only to compare with the plain loop.
  bool CheckAhead = true;
  /// The policy bounds the collapses itself (CollapsePolicy::WithinBound):
  /// when none within the bound is left, the simplification ends there,
  /// short of the target, instead of lifting the fold guard and the link
  /// condition to reach it.
  bool StopWhenStalled = false;
  /// Fins (see MedialEdgeCollapse::CollapseFins) whose balls reach out of
  /// the cones of their junction by at most this much (unit frame) are
  /// collapsed into it at checkpoints on the way to the target (0: never).
  double FinBudget = 0.0;
  /// Only sheets smaller than this share of the triangle area can be fins.
  double FinAreaShare = 0.05;
  /// Fraction in [0, 1]; returning false aborts.
  std::function<bool(double)> Progress;
};

/// Scratch space and the state of the collapse under way: collapses of
/// distant edges run at once, each thread with its own.
struct CollapseScratch
{
  // For policies.
  std::vector<std::pair<Point3, double>> Anchors;
  std::vector<Index> Indices;
  std::vector<records::Round> RoundRecords;
  std::vector<records::Slab> SlabRecords;
  std::vector<double> SiteX, SiteY, SiteZ, SiteValues;
  // The sphere a policy last proved clear of the surface samples by
  // ProvenClearance (a lower bound of the distance from its centre to the
  // nearest one; -1: none), for the collapse that places it.
  Sphere ProvenTarget{};
  double ProvenClearance = -1.0;
  // For the validity checks, reused to spare allocations on every collapse.
  std::vector<std::pair<std::array<Index, 3>, Index>> FaceKeys;
  std::vector<Index> MergedAway, MergedNeighbours;
  std::vector<std::array<Index, 3>> CentreBefore, Outer;
  std::vector<std::array<Index, 4>> EdgeIncidences; // (min, max, apex, centre?)
  std::vector<std::array<Index, 2>> RingPairs;
  // Folds around (a, b) before its collapse, which every placement tried
  // for that edge compares with: counted once per edge taken from the queue.
  Index FoldsBeforeA = -1, FoldsBeforeB = -1;
  std::size_t FoldsBefore = 0;
  // Fold repair: a collapse must leave fewer folds around it than before.
  bool FewerFolds = false;
  bool EulerNeutral = false; // the collapse passed the link test as Euler-neutral
  std::size_t MergedFaces = 0, EulerNeutralMerges = 0;
};

class MedialEdgeCollapse;

/// What distinguishes one simplifier from another: the cost of a collapse,
/// where it puts the merged sphere and what per-vertex data merges with it.
class CollapsePolicy
{
public:
  struct Evaluation
  {
    double Cost = HUGE_VAL; // HUGE_VAL: never collapse
    Sphere Target{};
  };
  virtual ~CollapsePolicy() = default;
  /// Cost of collapsing (a, b), a < b, and the merged sphere. Called from
  /// several threads at once while the mesh does not change.
  virtual Evaluation Evaluate(
    const MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch) const = 0;
  /// Whether merging b into a at `target` stays within the policy's own
  /// bound (e.g. on the local reconstruction error; see
  /// EdgeCollapseOptions::StopWhenStalled). Called after the validity checks
  /// pass, with scratch.FaceKeys holding the faces that stay (b renamed a),
  /// from several threads at once while the mesh does not change.
  virtual bool WithinBound(
    const MedialEdgeCollapse&, Index, Index, const Sphere&, CollapseScratch&) const
  {
    return true;
  }
  /// At a stall short of the target: raise that bound and return true (every
  /// edge is then queued again), or return false to stall.
  virtual bool RaiseBound() { return false; }
  /// The spheres to try, best first, when the optimal one breaks validity.
  virtual std::array<Sphere, 3> FallbackSpheres(
    const MedialEdgeCollapse& mesh, Index a, Index b) const = 0;
  /// b has just been merged into a (mesh.Sphere(a) is the merged sphere).
  /// Collapses of edges at least five edges apart run at once: this may
  /// change data of a and b alone.
  virtual void Merged(MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch) = 0;
  /// Before the queue is filled: returns vertices whose edges must collapse
  /// before any other (e.g. after a forced move).
  virtual std::vector<Index> Prepare(MedialEdgeCollapse&) { return {}; }
  /// After every collapse into a (e.g. retry moves that were refused). May
  /// move a and its neighbours, and read up to three edges away from a.
  virtual void AfterCollapse(MedialEdgeCollapse&, Index, CollapseScratch&) {}
  /// A hint that Evaluate will soon read vertex v's data: requests it from
  /// memory so that the misses of several edges overlap. No effect on results.
  virtual void Prefetch(Index) const {}
};

/// The medial mesh being simplified, in the policy's unit frame, with the
/// collapse loop. Deterministic at any thread count: the cheapest edges are
/// taken from the queue in batches whose members lie at least five edges
/// apart (so that none reads what another writes), collapsed at once and
/// their new candidates queued in batch order.
class MedialEdgeCollapse
{
public:
  MedialEdgeCollapse(const MedialMesh& input, const Normalisation& frame,
    const EdgeCollapseOptions& options, CollapsePolicy& policy);

  /// Collapses until the target is reached, the queue runs dry or the cost
  /// limit is hit (lifting the fold guard, then the link condition, when
  /// the collapses that keep them are exhausted).
  EdgeCollapseCounts Run();
  /// The surviving vertices (in input units), their faces and edges; the
  /// input index of every output vertex goes to `outputToInput`.
  MedialMesh Output(std::vector<Index>& outputToInput) const;

  const Normalisation& Frame() const { return this->UnitFrame; }
  std::size_t NumberOfVertices() const { return this->Spheres.size(); }
  const Sphere& SphereOf(Index v) const { return this->Spheres[v]; }
  Point3 Position(Index v) const
  {
    return { this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  }
  const std::vector<Index>& Neighbours(Index v) const { return this->VertexNeighbours[v]; }
  bool Alive(Index v) const { return this->VertexAlive[v] != 0; }
  std::size_t AliveCount() const { return this->NumberAlive; }
  /// Stability ratio of edge (a, b) (Q-MAT's Gamma): 0 for a pure spike
  /// (one ball internally tangent to the other), 1 for equal radii.
  double StabilityRatio(Index a, Index b) const;
  /// Sums the centres (and their squared norms) of the merged one-ring of
  /// (a, b), shared neighbours once; returns how many.
  std::size_t MergedRingSums(Index a, Index b, Point3& sum, double& sumSquares) const;

  /// Whether moving v to `target` makes no zero-area triangle and no more
  /// folds than it leaves.
  bool MoveKeepsValid(Index v, const Point3& target, CollapseScratch& scratch) const;
  /// Fins: sheets (triangles joined across two-triangle edges) smaller than
  /// `areaShare` of the triangle area that branch off other sheets at every
  /// junction edge they touch (at a junction, the two triangles closest to a
  /// straight continuation of each other go through it, the others branch
  /// off), and whose balls reach out of the cones of those junction edges
  /// by at most `budget`. Each is listed as its junction's vertices (sorted),
  /// -1, then its other vertices (sorted).
  std::vector<std::vector<Index>> FindFins(double budget, double areaShare) const;
  /// Collapses the vertices of every fin into its junction, farthest first,
  /// keeping the junction's spheres, with the link condition and validity
  /// checks (but not the policy's bound); repeated while fins are found (at
  /// most four times). Returns how many collapses were made.
  std::size_t CollapseFins(double budget, double areaShare);
  void Move(Index v, const Sphere& s) { this->Spheres[v] = s; }

private:
  // A queued candidate is current while neither endpoint has changed (a
  // vertex merged away has changed too).
  struct EndpointsUnchanged
  {
    const std::vector<std::uint32_t>* Version;
    template <typename Entry>
    bool operator()(const Entry& c) const
    {
      return (*this->Version)[c.A] == c.VersionA && (*this->Version)[c.B] == c.VersionB;
    }
  };
  using CandidateQueue = CollapseQueue<Sphere, EndpointsUnchanged>;
  using Candidate = CandidateQueue::Entry;
  // A candidate taken from the queue and what its collapse did.
  struct BatchItem
  {
    Candidate Taken;
    bool Collapsed = false;
    bool EulerNeutral = false;
    std::size_t MergedFaces = 0, EulerNeutralMerges = 0;
    std::vector<Candidate> Pushes; // the merged vertex's edges, re-evaluated
  };
  Candidate MakeCandidate(Index a, Index b, CollapseScratch& scratch) const;
  /// Queues every edge (with `spikesOnly`, the spike edges).
  void PushAllEdges(bool spikesOnly = false);
  bool CollapseUntil(std::size_t target, const std::function<bool(std::size_t)>& progress);
  // CollapseUntil, raising the policy's bound at every stall short of
  // `target` (CollapsePolicy::RaiseBound) while it lets it.
  bool CollapseWithinBounds(std::size_t target, const std::function<bool(std::size_t)>& progress);
  // CollapseWithinBounds, with the fins collapsed at a few checkpoints on
  // the way (EdgeCollapseOptions::FinBudget).
  bool CollapseWithoutFins(std::size_t target, const std::function<bool(std::size_t)>& progress);
  std::size_t BatchLimit(std::size_t target) const;
  // The vertices within two edges of a or b (with repeats).
  void GatherRegion(Index a, Index b, std::vector<Index>& region) const;
  bool ClaimRegion(const std::vector<Index>& region);
  // Takes up to `count` more current candidates off the queue for the batch
  // under way (none above the cost limit) and gathers their regions at once.
  // False when none is left.
  bool LookFurther(std::size_t count, bool gather);
  void CollapseTaken(BatchItem& item, CollapseScratch& scratch);
  // What a collapse's checks found, when made ahead (CollapseInOrder).
  struct CollapseCheck
  {
    bool LinkHolds = false, EulerNeutral = false, Valid = false;
  };
  // CollapseTaken without re-evaluating the merged vertex's edges; with
  // `checked`, the link condition and the placement's validity found ahead.
  void CollapseOnly(
    BatchItem& item, CollapseScratch& scratch, const CollapseCheck* checked = nullptr);
  // Copies what the collapse did (Euler-neutral, merged faces) to the item.
  void NoteCollapse(BatchItem& item, const CollapseScratch& scratch) const;
  // The policy's follow-up, then the merged vertex's edges into item.Pushes.
  void EvaluateMergedEdges(BatchItem& item, CollapseScratch& scratch);
  // Counts the item and queues its pushes; true when it collapsed.
  bool Finish(const BatchItem& item);
  // The cheapest current candidate off the queue, unless the queue is dry
  // or it costs more than MaximumCost (then AboveCostLimit).
  bool TakeNext(Candidate& out);
  // CollapseUntil for MaximumBatch 1: the greedy order, checked ahead on a
  // second thread (CheckAhead).
  bool CollapseInOrder(std::size_t target, const std::function<bool(std::size_t)>& progress);
  // Sets scratch.EulerNeutral when it holds only as an Euler-neutral collapse.
  bool LinkConditionHolds(Index a, Index b, CollapseScratch& scratch) const;
  bool Collapse(Index a, Index b, const Sphere& target, CollapseScratch& scratch);
  // Collapse's two halves: the validity checks (filling scratch's face keys
  // and merged faces), then the changes, from that scratch.
  bool CollapseIsValid(Index a, Index b, const Sphere& target, CollapseScratch& scratch) const;
  void ApplyCollapse(Index a, Index b, const Sphere& target, CollapseScratch& scratch);
  bool CollapseAtFallback(Index a, Index b, CollapseScratch& scratch);
  bool CreatesFold(Index a, Index b, const Point3& newPosition, CollapseScratch& scratch) const;
  void PrefetchFaces(const std::vector<Index>& faces) const;
  void PrefetchCollapse(Index a, Index b) const;
  std::size_t FoldsAroundMerged(
    Index a, Index b, const Point3& newPosition, CollapseScratch& scratch) const;
  std::vector<std::array<Index, 4>> FindFolds(CollapseScratch& scratch) const;
  void CollapseFolds(std::size_t target);
  // What a hinge (u, v, x), (v, u, y) adds to the fold counts: a fold (the
  // triangles folded onto each other) FoldCountWeight, a pleat (below the
  // pleat guard's angle) 1, so that no collapse may add a fold, nor a pleat
  // without removing a fold.
  static constexpr std::size_t FoldCountWeight = 1000;
  std::size_t FoldWeight(const Point3& u, const Point3& v, const Point3& x, const Point3& y) const;
  std::size_t CountFolds(const std::vector<std::array<Index, 3>>& centre, Index moved,
    const Point3& movedTo, CollapseScratch& scratch) const;

  const EdgeCollapseOptions& Options;
  CollapsePolicy& Policy;
  Normalisation UnitFrame;
  // Per vertex.
  std::vector<Sphere> Spheres;
  std::vector<std::vector<Index>> VertexNeighbours; // sorted
  std::vector<std::vector<Index>> VertexFaces;
  std::vector<std::uint32_t> Version;
  std::vector<char> VertexAlive;
  std::size_t NumberAlive = 0;
  // Faces.
  std::vector<std::array<Index, 3>> Faces;
  std::vector<char> FaceAlive;

  CandidateQueue Queue;
  CollapseScratch Scratch; // for the serial parts
  // The batch under way. Every candidate looked at claims the vertices
  // within two edges of its endpoints: they carry the number of the claim,
  // and those claimed since BatchStart belong to the batch.
  std::vector<BatchItem> Batch;
  std::vector<Candidate> Looked, PassedOver; // taken off the queue; passed over
  std::vector<std::vector<Index>> Regions;   // of the candidates looked at
  std::size_t LookedLastTime = 0;
  bool AboveCostLimit = false; // the queue's cheapest current entry costs too much
  std::vector<std::uint32_t> RegionStamp;
  std::uint32_t ClaimStamp = 0, BatchStart = 1;
  EdgeCollapseCounts Counts;
  bool Relaxed = false;            // the link condition no longer guards collapses
  bool FoldGuard = true;           // collapses may not fold triangles onto each other
  bool FoldsAllowedAtLast = false; // the fold guard was lifted after a stall
  bool IgnorePolicyBound = false;  // fin collapses do not ask the policy's bound
  double GuardCosine = 1.0;        // cos(Options.FoldAngle), then FoldCosine
};
}

#endif
