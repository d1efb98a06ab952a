// SPDX-License-Identifier: GPL-3.0-or-later
// Greedy edge-collapse simplification of medial meshes: one framework (the
// mesh, its validity checks, the link condition and the queue) shared by
// every cost policy (Structural MAT's Atlas energy, Q-MAT's slab quadrics).
#ifndef medialaxis_EdgeCollapse_h
#define medialaxis_EdgeCollapse_h

#include "CollapseQueue.h"
#include "EdgeCollapseCounts.h"
#include "MedialMesh.h"
#include "Vec3.h"

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
  /// Fraction in [0, 1]; returning false aborts.
  std::function<bool(double)> Progress;
};

/// Per-thread scratch space handed to CollapsePolicy::Evaluate.
struct CollapseScratch
{
  std::vector<std::pair<Point3, double>> Anchors;
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
  /// The spheres to try, best first, when the optimal one breaks validity.
  virtual std::array<Sphere, 3> FallbackSpheres(
    const MedialEdgeCollapse& mesh, Index a, Index b) const = 0;
  /// b has just been merged into a (mesh.Sphere(a) is the merged sphere).
  virtual void Merged(MedialEdgeCollapse& mesh, Index a, Index b) = 0;
  /// Before the queue is filled: returns vertices whose edges must collapse
  /// before any other (e.g. after a forced move).
  virtual std::vector<Index> Prepare(MedialEdgeCollapse&) { return {}; }
  /// After every collapse into a (e.g. retry moves that were refused).
  virtual void AfterCollapse(MedialEdgeCollapse&, Index) {}
};

/// The medial mesh being simplified, in the policy's unit frame, with the
/// collapse loop. Single-threaded apart from the first evaluation of every
/// edge, and deterministic.
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
  bool MoveKeepsValid(Index v, const Point3& target);
  void Move(Index v, const Sphere& s) { this->Spheres[v] = s; }

private:
  using Candidate = CollapseQueue<Sphere>::Entry;
  Candidate MakeCandidate(Index a, Index b, CollapseScratch& scratch) const;
  void Push(Index a, Index b);
  void PushAllEdges();
  bool CollapseUntil(std::size_t target, const std::function<bool(std::size_t)>& progress);
  // Sets EulerNeutral when it holds only as an Euler-neutral collapse.
  bool LinkConditionHolds(Index a, Index b);
  bool Collapse(Index a, Index b, const Sphere& target);
  bool CollapseAtFallback(Index a, Index b);
  bool CreatesFold(Index a, Index b, const Point3& newPosition);
  std::size_t FoldsAroundMerged(Index a, Index b, const Point3& newPosition);
  std::size_t CountFolds(
    const std::vector<std::array<Index, 3>>& centre, Index moved, const Point3& movedTo);

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

  CollapseQueue<Sphere> Queue;
  // Scratch buffers, reused to spare allocations on every collapse.
  CollapseScratch Scratch;
  std::vector<std::pair<std::array<Index, 3>, Index>> FaceKeys;
  std::vector<Index> MergedAway, MergedNeighbours;
  std::vector<std::array<Index, 3>> CentreBefore, Outer;
  std::vector<std::array<Index, 4>> EdgeIncidences; // (min, max, apex, centre?)
  std::vector<std::array<Index, 2>> RingPairs, Spokes;
  // Folds around (a, b) before its collapse, which every placement tried
  // for that edge compares with: counted once per edge taken from the queue.
  Index FoldsBeforeA = -1, FoldsBeforeB = -1;
  std::size_t FoldsBefore = 0;
  EdgeCollapseCounts Counts;
  bool Relaxed = false;            // the link condition no longer guards collapses
  bool EulerNeutral = false;       // the collapse being made passed as Euler-neutral
  bool FoldGuard = true;           // collapses may not fold triangles onto each other
  bool FoldsAllowedAtLast = false; // the fold guard was lifted after a stall
};
}

#endif
