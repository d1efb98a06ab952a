// SPDX-License-Identifier: GPL-3.0-or-later
// How well a medial mesh's envelope reconstructs a surface: dense samples on
// both, the two one-sided distances and their statistics.
//
// Surface -> envelope: the surface's vertices and NumberOfSamples
// area-uniform random points on it, each with its distance to the boundary of
// the envelope (MedialEnvelope::DistanceToBoundary: exact outside the union,
// a certified two-sided bound inside it, of which the upper one is used).
// Envelope -> surface: NumberOfEnvelopeSamples area-uniform random points on
// the boundary of the union (points of primitive surfaces strictly inside
// another primitive are rejected), each with its distance to the surface.
// Hausdorff distances are maxima over the samples (vertices included on the
// surface side); on the envelope side the maximum is then raised by local
// searches from the farthest samples (EnvelopeMaximum.h). Mean and RMS are over the area-uniform
// samples. Two-sided values are the larger of the two one-sided ones. Deterministic for a seed,
// whatever the number of threads.
#ifndef medialaxis_ReconstructionError_h
#define medialaxis_ReconstructionError_h

#include "Envelope/EnvelopeDistance.h"
#include "Mesh/PolygonMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace medialaxis
{
struct ReconstructionErrorOptions
{
  std::size_t NumberOfSamples = 100000; // on the surface, besides its vertices
  // On the boundary of the union. Their largest distance is raised by the
  // local searches below, which is what a denser sampling would otherwise be
  // needed for (bunny, kitten and a CAD part, 5,000 spheres: 50,000 samples
  // and the searches come out higher than 1,000,000 samples without them).
  std::size_t NumberOfEnvelopeSamples = 50000;
  std::uint64_t RandomSeed = 0;
  /// Local searches that raise the envelope -> surface maximum from the
  /// farthest envelope samples (EnvelopeMaximum.h); 0 keeps the samples'.
  std::size_t MaximumSearches = 16;
  /// Called with the fraction done; return false to abort.
  std::function<bool(double)> Progress;
};

struct OneSidedError
{
  double Hausdorff = 0.0;
  /// Largest lower bound: the Hausdorff distance lies in [this, Hausdorff].
  double HausdorffLowerBound = 0.0;
  double Mean = 0.0;
  double RMS = 0.0;
  std::size_t Samples = 0;
};

struct ReconstructionErrorResult
{
  double Diagonal = 0.0; // of the surface's bounding box
  OneSidedError SurfaceToEnvelope, EnvelopeToSurface;
  double Hausdorff = 0.0, Mean = 0.0, RMS = 0.0; // two-sided

  // Per surface vertex: distance to the envelope's boundary (the upper bound
  // inside the union), its lower bound, and the signed value (negative
  // inside the envelope).
  std::vector<double> VertexDistance, VertexLowerBound, VertexSignedDistance;

  // Surface points (vertices and samples) inside the union, and those of them
  // whose distance is a bound rather than exact, with the largest gap.
  std::size_t InsidePoints = 0, UncertifiedPoints = 0;
  double LargestBoundGap = 0.0;

  std::vector<Point3> EnvelopeSamples;
  std::vector<double> EnvelopeSampleDistance; // to the surface
  std::vector<PrimitiveRef> EnvelopeSamplePrimitive;
  // Where the envelope -> surface Hausdorff distance is attained: a sample or
  // the end of a local search from one (on the boundary of the union).
  Point3 EnvelopeFarthestPoint{ 0, 0, 0 };
  std::size_t EnvelopeCandidates = 0; // primitive-surface points drawn (accepted or not)

  // Wall-clock seconds of each part, for benchmarks: surface -> envelope,
  // exposed pieces of the primitives, drawing and testing envelope
  // candidates, envelope -> surface, tightening inside bounds.
  double SurfaceSeconds = 0.0, PiecesSeconds = 0.0, CandidatesSeconds = 0.0, EnvelopeSeconds = 0.0,
         TighteningSeconds = 0.0;

  bool Aborted = false;
};

ReconstructionErrorResult ComputeReconstructionError(const TriangleMesh& surface,
  const MedialEnvelope& envelope, const ReconstructionErrorOptions& options = {});

/// The same measures between the surface and a closed triangle surface that
/// reconstructs it (outward; a contoured union of primitives, a remeshed
/// envelope): at the surface's vertices and samples the distance to the
/// reconstruction (signed by an inside test of the reconstruction; exact,
/// so the lower bounds equal the distances), and at NumberOfEnvelopeSamples
/// area-uniform samples of the reconstruction the distance to the surface.
/// No local search raises the maximum (MaximumSearches is not used), and
/// EnvelopeSamplePrimitive is left empty.
ReconstructionErrorResult ComputeSurfaceDistanceError(const TriangleMesh& surface,
  const TriangleMesh& reconstruction, const ReconstructionErrorOptions& options = {});

/// Area-uniform random points on a triangle mesh with their triangle's unit
/// normal; point k depends only on (seed, k).
void SampleTriangleMesh(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed,
  std::vector<Point3>& points, std::vector<Point3>& normals);
}

#endif
