// SPDX-License-Identifier: GPL-3.0-or-later
// The final fit's guard on each step: moves of the spheres that would make a
// triangle degenerate, fold or pleat two triangles, or make a spike edge are
// shortened, sphere by sphere, until none is left.
#ifndef medialaxis_FitValidityGuard_h
#define medialaxis_FitValidityGuard_h

#include "Mesh/MedialMesh.h"
#include "Mesh/MedialMeshQuality.h"

#include <array>
#include <cstdint>
#include <vector>

namespace medialaxis
{
/// What a move of the spheres must not create: degenerate triangles, folds
/// (and pleats, below EnvelopeFitOptions::FoldAngle) and spike edges
/// (stability ratio below the threshold), unless the mesh had them before
/// the fit.
class ValidityGuard
{
public:
  /// Records what `mesh` has before the fit; `edges` must outlive the guard.
  ValidityGuard(const MedialMesh& mesh, const std::vector<std::array<Index, 2>>& edges,
    double spikeThreshold, double foldAngleDegrees);

  /// Shortens the moves from `current` to `candidate` of the spheres of
  /// every element the move made invalid (halving them, at last putting the
  /// sphere back) until none is left. Degenerate and folded triangles depend
  /// on the centres alone: a sphere that shrinks keeps its new radius (a
  /// ball reaching out of the surface at a folded corner of the sheet can
  /// still draw back; growth without the centre's move could make it reach
  /// out); spikes shorten both.
  void Shorten(const MedialMesh& current, MedialMesh& candidate) const;

private:
  bool Spike(const MedialMesh& mesh, const std::array<Index, 2>& e) const;

  const std::vector<std::array<Index, 2>>& Edges;
  std::vector<TriangleHinge> Hinges;
  double SpikeThreshold;
  double GuardCosine;
  std::vector<std::uint8_t> FoldBefore; // FoldLevel of each hinge before the fit
  std::vector<std::uint8_t> DegenerateBefore, SpikeBefore;
};
}

#endif
