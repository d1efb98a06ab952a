// SPDX-License-Identifier: GPL-3.0-or-later
// Blue-noise sampling of a triangle surface by weighted sample elimination
// (Yuksel, "Sample Elimination for Generating Poisson Disk Sample Sets",
// Eurographics 2015), optionally followed by restricted centroidal Voronoi
// (Lloyd) relaxation on the surface.
#ifndef medialaxis_BlueNoiseSampler_h
#define medialaxis_BlueNoiseSampler_h

#include "Mesh/PolygonMesh.h"
#include "Sampling/SizingField.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace medialaxis
{
struct SamplingOptions
{
  std::size_t NumberOfSamples = 10000; // exactly this many come out (see
                                       // Sizing.ExtraSampleFraction)
  std::uint64_t Seed = 0;
  /// Random candidates per output sample before elimination.
  double CandidateRatio = 4.0;
  /// Lloyd steps of restricted centroidal Voronoi relaxation. They keep
  /// each region's count of samples, so an adaptive density stays.
  int RelaxationIterations = 0;
  /// Denser on thin parts, by the local thickness (SizingField.h); the same
  /// as uniform where no part is thin.
  bool Adaptive = false;
  SizingOptions Sizing;
  /// Fraction in [0, 1]; returning false aborts (the result is then empty).
  std::function<bool(double)> Progress;
};

struct SurfaceSamples
{
  std::vector<Point3> Points;
  std::vector<Index> TriangleIds; // the triangle each sample lies on
  std::vector<Point3> Normals;    // unit normal of that triangle
  // Adaptive only: the local thickness and the wanted spacing at each sample.
  std::vector<double> LocalThickness, Spacing;
  /// Samples beyond NumberOfSamples, on thin parts finer than the finest
  /// spacing ratio (Sizing.ExtraSampleFraction).
  std::size_t AddedSamples = 0;
  bool Aborted = false;
};

/// Thin parts sampled at Sizing.SpacingPerThickness can still be too sparse
/// for the Voronoi diagram to keep a loop round a thin handle. When the
/// medial axis misses handles of the surface, sample again with this called
/// for rounds 1, 2, ...: thin parts twice as dense each round, the count
/// growing beyond the budget there by up to `round` times it. False after
/// the last round (3).
inline bool DenserOnThinParts(SizingOptions& sizing, int round)
{
  if (round < 1 || round > 3)
  {
    return false;
  }
  sizing.SpacingPerThickness *= 0.5;
  sizing.ExtraSampleFraction = static_cast<double>(round);
  return true;
}

/// The surface must have positive area. Deterministic for a given seed,
/// whatever the number of threads.
SurfaceSamples SampleSurface(const TriangleMesh& surface, const SamplingOptions& options);

/// The ideal spacing of n samples on area A: the nearest-neighbour distance
/// of a hexagonal packing, sqrt(2 A / (sqrt(3) n)).
double IdealSampleSpacing(double area, std::size_t n);
}

#endif
