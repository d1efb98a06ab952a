// SPDX-License-Identifier: GPL-3.0-or-later
// Q-MAT medial mesh simplification (Li et al., "Q-MAT: Computing Medial Axis
// Transform by Quadratic Error Minimization", 2015) on the edge-collapse
// framework shared with the Atlas simplifier: every vertex carries the slab
// quadric error (SQE) of the slabs and cones of the input medial mesh it
// stands for, and edges collapse in order of (E + k) x stability ratio^2.
#ifndef medialaxis_QMatSimplifier_h
#define medialaxis_QMatSimplifier_h

#include "Simplification/AtlasSimplifier.h" // AtlasMedialMesh

#include <functional>
#include <limits>

namespace medialaxis
{
struct QMatSimplifierOptions
{
  std::size_t TargetNumberOfVertices = 1000;
  /// Stop when the cheapest collapse costs more (in the unit-diagonal model).
  double MaximumCost = std::numeric_limits<double>::infinity();
  /// The paper's k (Eq. 8), in the model scaled to a unit bounding-box
  /// diagonal: while the SQE is far below k, edges collapse in order of
  /// their stability ratio (spikes first); later the SQE dominates.
  double K = 1e-5;
  /// The paper's k0 (section 4.4): weight of the soft planes that keep stable
  /// boundary vertices and edges from shrinking (times the stability
  /// ratio squared); 0 switches them off.
  double BoundaryWeight = 0.1;
  /// The paper's eta: below this many vertices the link condition guards
  /// every collapse.
  std::size_t TopologyGuardVertexCount = 200;
  /// Where the link condition fails, still allow a collapse that keeps the
  /// Euler characteristic (each extra loop it closes matched by a face pair
  /// it merges). Spikes entangled with the sheets around them go this way;
  /// with the strict condition alone many survive to the end (noisy unit
  /// sphere, 50 vertices: radii down to 0.37 instead of 0.69). Off follows
  /// the paper.
  bool EulerNeutralCollapses = true;
  /// Edges whose stability ratio is below this are spikes: the smaller ball
  /// lies almost inside the bigger one, so the edge merges into the bigger
  /// ball (along a spike the SQE minimiser is ill-defined), and the flip and
  /// fold tests are skipped for it. 0 follows the paper.
  double SpikeRatio = 0.1;
  /// When no collapse below the guard keeps the link condition: stop there
  /// (strict) or go on without it (counted in RelaxedCollapses).
  bool StrictTopologyGuard = false;
  /// Refuse collapses that fold two triangles onto each other; allowed
  /// anyway once nothing else is left.
  bool PreventFolds = true;
  /// Fraction in [0, 1]; returning false aborts (the result is then empty).
  std::function<bool(double)> Progress;
};

/// The collapse counts (see EdgeCollapseCounts) and the result.
struct QMatSimplifierResult : EdgeCollapseCounts
{
  /// The simplified mesh; when the input had Atlases (AtlasOffsets of size
  /// vertices + 1), every vertex has the union of the Atlases merged into it.
  AtlasMedialMesh Medial;
  /// Input faces whose three balls have no common tangent planes (their
  /// edges' cone terms stand in for them) and input cones with one ball
  /// inside the other (no SQE term).
  std::size_t FacesWithoutTangentPlanes = 0;
  std::size_t NestedCones = 0;
};

/// Any medial mesh (ours or read from a .ma file). One collapse at a time in
/// the greedy order (a second thread, if any, evaluates every edge first,
/// then checks the next candidate and shares the re-evaluations; see
/// EdgeCollapseOptions::CheckAhead), and deterministic.
QMatSimplifierResult SimplifyMedialAxisQMat(
  const AtlasMedialMesh& input, const QMatSimplifierOptions& options = QMatSimplifierOptions());
}

#endif
