// SPDX-License-Identifier: GPL-3.0-or-later
// The largest envelope -> surface distance, raised by local search from the
// farthest random samples.
//
// The largest distance over random points of the envelope's boundary falls
// short of the true one by how much the distance varies between samples
// (bunny, 5,000 spheres: 100,000 samples give 0.74-0.80 % of the diagonal
// over three seeds, a million give 0.81 %). From each of the farthest
// samples (at most one per neighbourhood), a pattern search climbs along the
// sample's primitive surface: a step is taken when the distance grows and
// the new point is on the boundary of the union (no primitive contains it
// deeper than the envelope's tolerance); the step is halved when no
// direction helps. Every point reached is a boundary point with its exact
// distance, so the result is still a lower bound of the Hausdorff distance,
// only a closer one.
#ifndef medialaxis_EnvelopeMaximum_h
#define medialaxis_EnvelopeMaximum_h

#include "Envelope/EnvelopeDistance.h"

#include <functional>
#include <vector>

namespace medialaxis
{
struct EnvelopeMaximumOptions
{
  std::size_t Seeds = 16;               // farthest samples climbed from
  std::size_t EvaluationsPerSeed = 200; // distance evaluations per climb
  double Step = 0.0;                    // first step (e.g. the samples' spacing); > 0
};

struct EnvelopeMaximum
{
  double Distance = 0.0; // largest distance found (0 without samples)
  Point3 Point{ 0, 0, 0 };
  PrimitiveRef Primitive{ PrimitiveKind::Sphere, -1 };
  std::size_t Evaluations = 0; // distance evaluations, over all climbs
};

/// Point of the surface of `ref` (a ball, a cone's lateral surface, or the
/// tangent triangle of a slab on the side of `onSide`) nearest to `p`, as the
/// envelope's pieces parametrise it.
Point3 ProjectOntoPrimitiveSurface(
  const MedialEnvelope& envelope, const PrimitiveRef& ref, const Point3& onSide, const Point3& p);

/// Climbs from the farthest of `samples` (points of the boundary of the
/// union on primitive `primitives[i]`, at distance `distances[i]` from the
/// surface; `distance(p)` gives that distance for any point). Deterministic:
/// the climbs run in parallel, each in a fixed order.
EnvelopeMaximum RefineEnvelopeMaximum(const MedialEnvelope& envelope,
  const std::vector<Point3>& samples, const std::vector<PrimitiveRef>& primitives,
  const std::vector<double>& distances, const std::function<double(const Point3&)>& distance,
  const EnvelopeMaximumOptions& options);
}

#endif
