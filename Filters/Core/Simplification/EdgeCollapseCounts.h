// SPDX-License-Identifier: GPL-3.0-or-later
// What an edge-collapse simplification did, shared by the results of every
// cost policy (see EdgeCollapse.h).
#ifndef medialaxis_EdgeCollapseCounts_h
#define medialaxis_EdgeCollapseCounts_h

#include <cstddef>

namespace medialaxis
{
struct EdgeCollapseCounts
{
  std::size_t Collapses = 0;
  std::size_t RejectedCollapses = 0; // would have broken validity or topology
  std::size_t RelaxedCollapses = 0;  // made without the link condition after a stall
  /// Made after every collapse that keeps triangles from folding onto each
  /// other was exhausted (e.g. tubes whose sheets shrink to a curve).
  std::size_t FoldingAllowedCollapses = 0;
  /// Collapses chosen to remove the folds left by forced moves (see
  /// MedialEdgeCollapse::CollapseFolds).
  std::size_t FoldRepairCollapses = 0;
  /// Collapses that folded fins into the junctions they hang on
  /// (EdgeCollapseOptions::FinBudget); counted in Collapses too.
  std::size_t FinCollapses = 0;
  std::size_t MergedFaces = 0; // each closed a bubble (lowered the Euler characteristic)
  /// Collapses past the link condition that keep the Euler characteristic
  /// (FringeCollapses, EulerNeutralSpikeCollapses) and the face pairs they
  /// merged (not counted in MergedFaces).
  std::size_t EulerNeutralCollapses = 0;
  std::size_t EulerNeutralMerges = 0;
  /// Batches of candidates taken from the queue and collapsed at once
  /// (EdgeCollapseOptions::MaximumBatch): (Collapses + RejectedCollapses) /
  /// Batches is their mean size.
  std::size_t Batches = 0;
  /// Wall time of the set-up and the first evaluation of every edge (the
  /// rest of the run is the collapsing itself).
  double QueueInitialisationSeconds = 0.0;
  bool Aborted = false;
};
}

#endif
