// SPDX-License-Identifier: GPL-3.0-or-later
#include "Envelope/EnvelopeMaximum.h"

#include "Geometry/ClosestPoint.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace medialaxis
{
namespace
{
int SlabSide(const SlabPrimitive& slab, const Point3& p)
{
  return std::abs(Dot(slab.Normals[0], p) - slab.Offsets[0]) <=
      std::abs(Dot(slab.Normals[1], p) - slab.Offsets[1])
    ? 0
    : 1;
}

// Outward unit normal of the primitive's surface at its point p.
Point3 SurfaceNormal(const MedialEnvelope& envelope, const PrimitiveRef& ref, const Point3& p)
{
  switch (ref.Kind)
  {
    case PrimitiveKind::Sphere:
      return Normalized(p - envelope.Spheres()[ref.Id].Center);
    case PrimitiveKind::Cone:
    {
      const ConePrimitive& c = envelope.Cones()[ref.Id];
      if (c.Nested)
      {
        return Normalized(p - c.C[c.Big]);
      }
      const Point3 v = p - c.C[0];
      const Point3 radial = Normalized(v - Dot(v, c.Axis) * c.Axis);
      return Normalized(c.SinPhi * c.Axis + c.CosPhi * radial);
    }
    default:
    {
      const SlabPrimitive& s = envelope.Slabs()[ref.Id];
      return s.Normals[SlabSide(s, p)];
    }
  }
}

// Point of the sphere (centre, radius) nearest to p; `fallback` at the centre.
Point3 OntoSphere(const Point3& centre, double radius, const Point3& p, const Point3& fallback)
{
  const Point3 v = p - centre;
  const double length = Norm(v);
  return length > 0.0 ? centre + (radius / length) * v : fallback;
}

// Two unit vectors completing n to an orthonormal frame.
void TangentFrame(const Point3& n, Point3& t1, Point3& t2)
{
  int k = 0;
  for (int i = 1; i < 3; ++i)
  {
    k = std::abs(n[i]) < std::abs(n[k]) ? i : k;
  }
  Point3 e{ 0, 0, 0 };
  e[k] = 1.0;
  t1 = Normalized(Cross(n, e));
  t2 = Cross(n, t1);
}

// The farthest samples, at most one within `separation` of another (the
// climbs from two close samples would mostly end on the same maximum).
std::vector<std::size_t> FarthestSeeds(const std::vector<Point3>& samples,
  const std::vector<double>& distances, std::size_t count, double separation)
{
  std::vector<std::size_t> order(samples.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  const auto farther = [&](std::size_t a, std::size_t b)
  { return distances[a] > distances[b] || (distances[a] == distances[b] && a < b); };
  const std::size_t considered = std::min(order.size(), 64 * count);
  std::partial_sort(order.begin(), order.begin() + considered, order.end(), farther);
  std::vector<std::size_t> seeds;
  for (std::size_t k = 0; k < considered && seeds.size() < count; ++k)
  {
    const Point3& p = samples[order[k]];
    if (std::none_of(seeds.begin(), seeds.end(),
          [&](std::size_t s) { return Norm(samples[s] - p) < separation; }))
    {
      seeds.push_back(order[k]);
    }
  }
  return seeds;
}
}

Point3 ProjectOntoPrimitiveSurface(
  const MedialEnvelope& envelope, const PrimitiveRef& ref, const Point3& onSide, const Point3& p)
{
  switch (ref.Kind)
  {
    case PrimitiveKind::Sphere:
    {
      const SpherePrimitive& s = envelope.Spheres()[ref.Id];
      return OntoSphere(s.Center, s.Radius, p, onSide);
    }
    case PrimitiveKind::Cone:
    {
      // In p's meridian plane the lateral surface is the segment between
      // the two tangent circles' points at p's angle.
      const ConePrimitive& c = envelope.Cones()[ref.Id];
      if (c.Nested)
      {
        return OntoSphere(c.C[c.Big], c.R[c.Big], p, onSide);
      }
      const Point3 v = p - c.C[0];
      const double angle = std::atan2(Dot(v, c.Perp2), Dot(v, c.Perp1));
      const Point3 a = ConeTangentPoint(c, 0, angle), b = ConeTangentPoint(c, 1, angle);
      const Point3 ab = b - a;
      const double length2 = Dot(ab, ab);
      const double t = length2 > 0.0 ? std::clamp(Dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
      return a + t * ab;
    }
    default:
    {
      const SlabPrimitive& s = envelope.Slabs()[ref.Id];
      const auto t = SlabTangentTriangle(s, SlabSide(s, onSide));
      return ClosestPointOnTriangle(p, t[0], t[1], t[2]);
    }
  }
}

EnvelopeMaximum RefineEnvelopeMaximum(const MedialEnvelope& envelope,
  const std::vector<Point3>& samples, const std::vector<PrimitiveRef>& primitives,
  const std::vector<double>& distances, const std::function<double(const Point3&)>& distance,
  const EnvelopeMaximumOptions& options)
{
  EnvelopeMaximum best;
  if (samples.empty() || !(options.Step > 0.0))
  {
    return best;
  }
  const std::vector<std::size_t> seeds =
    FarthestSeeds(samples, distances, options.Seeds, 4.0 * options.Step);
  std::vector<EnvelopeMaximum> climbs(seeds.size());
  const double tolerance = envelope.Tolerance();
  tbb::parallel_for(std::size_t(0), seeds.size(),
    [&](std::size_t k)
    {
      const std::size_t s = seeds[k];
      EnvelopeMaximum& climb = climbs[k];
      climb = { distances[s], samples[s], primitives[s], 0 };
      Index vertices[3];
      int count = envelope.MedialVertices(climb.Primitive, vertices);
      // A point of the climb's primitive that gains, if it is on the
      // boundary; else its projection onto the primitive that buries it, if
      // that is on the boundary and gains (the climb crosses a crease).
      auto tryPoint = [&](const Point3& q)
      {
        ++climb.Evaluations;
        const double value = distance(q);
        if (!(value > climb.Distance))
        {
          return false;
        }
        const std::uint32_t by = envelope.FindBurying(q, tolerance, vertices, count);
        if (by == MedialEnvelope::NoBurial)
        {
          climb.Point = q;
          climb.Distance = value;
          return true;
        }
        const PrimitiveRef other = envelope.BuryingPrimitive(by);
        const Point3 r = ProjectOntoPrimitiveSurface(envelope, other, q, q);
        ++climb.Evaluations;
        const double otherValue = distance(r);
        Index otherVertices[3];
        const int otherCount = envelope.MedialVertices(other, otherVertices);
        if (!(otherValue > climb.Distance) ||
          envelope.FindBurying(r, tolerance, otherVertices, otherCount) != MedialEnvelope::NoBurial)
        {
          return false;
        }
        climb.Point = r;
        climb.Distance = otherValue;
        climb.Primitive = other;
        count = std::copy_n(otherVertices, otherCount, vertices) - vertices;
        return true;
      };
      double step = options.Step;
      while (step > 1e-3 * options.Step && climb.Evaluations < options.EvaluationsPerSeed)
      {
        // Eight directions in the tangent plane, projected back onto the
        // primitive's surface; the first that gains is taken.
        Point3 t1, t2;
        TangentFrame(SurfaceNormal(envelope, climb.Primitive, climb.Point), t1, t2);
        const double diagonal = std::sqrt(0.5);
        const Point3 directions[8] = { t1, -1.0 * t1, t2, -1.0 * t2, diagonal * (t1 + t2),
          diagonal * (t1 - t2), diagonal * (t2 - t1), -diagonal * (t1 + t2) };
        bool moved = false;
        for (const Point3& d : directions)
        {
          const Point3 q = ProjectOntoPrimitiveSurface(
            envelope, climb.Primitive, climb.Point, climb.Point + step * d);
          if (!(Norm(q - climb.Point) > 0.1 * step))
          {
            continue; // stopped at the primitive's rim
          }
          if (tryPoint(q))
          {
            moved = true;
            break;
          }
        }
        step = moved ? step : 0.5 * step;
      }
    });
  for (const EnvelopeMaximum& climb : climbs)
  {

    best.Evaluations += climb.Evaluations;
    if (climb.Distance > best.Distance)
    {
      const std::size_t evaluations = best.Evaluations;
      best = climb;
      best.Evaluations = evaluations;
    }
  }
  return best;
}
}
