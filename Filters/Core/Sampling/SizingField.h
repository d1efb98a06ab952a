// SPDX-License-Identifier: GPL-3.0-or-later
// The spacing the samples should have across the surface: uniform where the
// solid is thick, a fraction of the local thickness where it is thin, with
// exactly the sample budget spent in total. Thin parts (tentacles, ears,
// plates) sampled at the uniform spacing are missed by the Voronoi diagram
// (paper 000, Fig. 19); sampled at half their thickness they are not.
#ifndef medialaxis_SizingField_h
#define medialaxis_SizingField_h

#include "Geometry/KdTree.h"
#include "Mesh/PolygonMesh.h"
#include "Sampling/LocalThickness.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace medialaxis
{
struct SizingOptions
{
  /// Spacing wanted on thin parts, as a fraction of their thickness.
  double SpacingPerThickness = 0.5;
  /// The finest spacing, as a fraction of the spacing on thick parts (0.25:
  /// at most 16 times the density there).
  double FinestSpacingRatio = 0.25;
  /// How fast the spacing may grow with distance (Lipschitz constant), so
  /// that the density changes gradually around a thin part.
  double Gradation = 0.5;
  /// Where thin parts want a spacing finer than FinestSpacingRatio allows
  /// (a handle or a tentacle much thinner than the budget can follow), they
  /// get it with up to this fraction of the budget in samples beyond it: the
  /// count grows. 0 (default): exactly the budget, thin parts capped.
  double ExtraSampleFraction = 0.0;
  /// Thickness probes per sample (uniform random points on the surface).
  double ProbesPerSample = 1.0;
  ThicknessOptions Thickness;
};

class SizingField
{
public:
  /// The field for `numberOfSamples` samples on the closed `surface`;
  /// deterministic for a seed, at any thread count.
  SizingField(const TriangleMesh& surface, std::size_t numberOfSamples, std::uint64_t seed,
    const SizingOptions& options = {});
  SizingField(const SizingField&) = delete;
  SizingField& operator=(const SizingField&) = delete;

  /// True if no part is thin: the spacing is the uniform one everywhere.
  bool IsUniform() const { return this->Uniform; }
  /// The spacing on thick parts (the uniform spacing of the budget if no
  /// part is thin, larger otherwise).
  double ThickSpacing() const { return this->Coarsest; }

  /// The probe nearest to p, whose values stand for p's.
  std::size_t NearestProbe(const Point3& p) const { return this->Tree->Nearest(p); }
  /// The wanted nearest-neighbour spacing at probe i.
  double Spacing(std::size_t i) const { return this->ProbeSpacing[i]; }
  /// The local thickness at probe i, at most ThicknessLimit(); infinity if
  /// no ray found the far side.
  double Thickness(std::size_t i) const { return this->ProbeThickness[i]; }
  /// The wanted spacing at p (of the nearest probe).
  double Spacing(const Point3& p) const { return this->Spacing(this->NearestProbe(p)); }
  /// The thickness from which the spacing no longer depends on it: the rays
  /// are not followed further.
  double ThicknessLimit() const { return this->ThickEnough; }

  const std::vector<Point3>& Probes() const { return this->ProbePoints; }

  /// Samples beyond the budget that the spacing asks for (with
  /// ExtraSampleFraction, where thin parts are finer than the finest ratio).
  std::size_t ExtraSamples() const { return this->Extra; }

private:
  // Spacing below `finest` where wanted, for at most `budget` more samples.
  void FollowThinPartsBeyondBudget(
    const std::vector<double>& wanted, double area, double finest, double budget);

  std::vector<Point3> ProbePoints;
  std::vector<double> ProbeThickness, ProbeSpacing;
  std::unique_ptr<KdTree> Tree;
  double Coarsest = 0.0;
  double ThickEnough = 0.0;
  std::size_t Extra = 0;
  bool Uniform = true;
};
}

#endif
