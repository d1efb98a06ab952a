// SPDX-License-Identifier: GPL-3.0-or-later
#include "Envelope/EnvelopeMesher.h"

#include "Geometry/Vec3.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace medialaxis
{
namespace
{
// Point and triangle counts of one primitive's surface, and where its points
// and triangles start in the output.
struct Piece
{
  PrimitiveRef Ref;
  Index Points, Triangles;
  Index FirstPoint = 0, FirstTriangle = 0;
};

int Bands(int sphereResolution)
{
  return std::max(2, sphereResolution / 2);
}

// Radius below which a ball, ring or band end is a point.
double Tiny(const MedialEnvelope& envelope)
{
  return 1e-12 * std::max(envelope.Diagonal(), 1e-300);
}

struct Writer
{
  TriangleMesh& Mesh;
  std::vector<PrimitiveRef>& Refs;
  Index P, T;
  PrimitiveRef Ref;

  Index Point(const Point3& x)
  {
    this->Mesh.Points[this->P] = x;
    return this->P++;
  }
  void Triangle(Index a, Index b, Index c)
  {
    this->Mesh.Triangles[this->T] = { a, b, c };
    this->Refs[this->T++] = this->Ref;
  }
};

void WriteSphere(Writer& w, const SpherePrimitive& s, int n)
{
  const int m = Bands(n);
  const Index north = w.Point(s.Center + s.Radius * Point3{ 0, 0, 1 });
  const Index first = w.P;
  for (int k = 1; k < m; ++k)
  {
    const double phi = Pi * k / m;
    for (int i = 0; i < n; ++i)
    {
      const double theta = 2.0 * Pi * i / n;
      w.Point(s.Center +
        s.Radius *
          Point3{
            std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi) });
    }
  }
  const Index south = w.Point(s.Center + s.Radius * Point3{ 0, 0, -1 });
  auto ring = [&](int k, int i) { return first + (k - 1) * n + (i % n); };
  for (int i = 0; i < n; ++i)
  {
    w.Triangle(north, ring(1, i), ring(1, i + 1));
    for (int k = 1; k + 1 < m; ++k)
    {
      w.Triangle(ring(k, i), ring(k + 1, i), ring(k + 1, i + 1));
      w.Triangle(ring(k, i), ring(k + 1, i + 1), ring(k, i + 1));
    }
    w.Triangle(ring(m - 1, i), south, ring(m - 1, i + 1));
  }
}

// The band between the two tangent circles; an end of zero radius is an apex.
void WriteCone(Writer& w, const ConePrimitive& c, int n, double tiny)
{
  Index ring[2][2] = { { 0, 0 }, { 0, 0 } }; // [end] -> first point, is apex
  for (int end = 0; end < 2; ++end)
  {
    const Circle3 circle = ConeTangentCircle(c, end);
    ring[end][1] = circle.Radius <= tiny ? 1 : 0;
    ring[end][0] = w.P;
    if (ring[end][1])
    {
      w.Point(ConeTangentPoint(c, end, 0.0));
      continue;
    }
    for (int i = 0; i < n; ++i)
    {
      w.Point(ConeTangentPoint(c, end, 2.0 * Pi * i / n));
    }
  }
  auto at = [&](int end, int i) { return ring[end][1] ? ring[end][0] : ring[end][0] + (i % n); };
  for (int i = 0; i < n; ++i)
  {
    if (!ring[0][1])
    {
      w.Triangle(at(0, i), at(0, i + 1), at(1, i));
    }
    if (!ring[1][1])
    {
      w.Triangle(at(0, i + 1), at(1, i + 1), at(1, i));
    }
  }
}
}

EnvelopeSurface MeshEnvelopePrimitives(
  const MedialEnvelope& envelope, const EnvelopeMeshOptions& options)
{
  const int ns = std::max(4, options.SphereResolution);
  const int nc = std::max(3, options.ConeResolution);
  const double tiny = Tiny(envelope);
  std::vector<Piece> pieces;
  for (std::size_t v = 0; v < envelope.Spheres().size(); ++v)
  {
    if (envelope.Spheres()[v].Radius > tiny)
    {
      const int m = Bands(ns);
      pieces.push_back(
        { { PrimitiveKind::Sphere, static_cast<Index>(v) }, 2 + (m - 1) * ns, 2 * ns * (m - 1) });
    }
  }
  for (std::size_t e = 0; e < envelope.Cones().size(); ++e)
  {
    const ConePrimitive& c = envelope.Cones()[e];
    if (c.Nested)
    {
      continue;
    }
    const bool apex0 = ConeTangentCircle(c, 0).Radius <= tiny;
    const bool apex1 = ConeTangentCircle(c, 1).Radius <= tiny;
    if (apex0 && apex1)
    {
      continue; // a segment: no surface
    }
    pieces.push_back({ { PrimitiveKind::Cone, static_cast<Index>(e) },
      (apex0 ? 1 : nc) + (apex1 ? 1 : nc), (apex0 || apex1) ? nc : 2 * nc });
  }
  for (std::size_t f = 0; f < envelope.Slabs().size(); ++f)
  {
    if (envelope.Slabs()[f].HasTangentPlanes)
    {
      pieces.push_back({ { PrimitiveKind::Slab, static_cast<Index>(f) }, 6, 2 });
    }
  }
  Index points = 0, triangles = 0;
  for (Piece& p : pieces)
  {
    p.FirstPoint = points;
    p.FirstTriangle = triangles;
    points += p.Points;
    triangles += p.Triangles;
  }
  EnvelopeSurface out;
  out.Mesh.Points.resize(static_cast<std::size_t>(points));
  out.Mesh.Triangles.resize(static_cast<std::size_t>(triangles));
  out.Primitive.resize(static_cast<std::size_t>(triangles));

  const std::size_t chunk = 4096;
  for (std::size_t begin = 0; begin < pieces.size(); begin += chunk)
  {
    const std::size_t end = std::min(pieces.size(), begin + chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 64),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          const Piece& p = pieces[i];
          Writer w{ out.Mesh, out.Primitive, p.FirstPoint, p.FirstTriangle, p.Ref };
          switch (p.Ref.Kind)
          {
            case PrimitiveKind::Sphere:
              WriteSphere(w, envelope.Spheres()[p.Ref.Id], ns);
              break;
            case PrimitiveKind::Cone:
              WriteCone(w, envelope.Cones()[p.Ref.Id], nc, tiny);
              break;
            case PrimitiveKind::Slab:
              for (int side = 0; side < 2; ++side)
              {
                const auto t = SlabTangentTriangle(envelope.Slabs()[p.Ref.Id], side);
                const Index a = w.Point(t[0]), b = w.Point(t[1]), c = w.Point(t[2]);
                w.Triangle(a, b, c);
              }
              break;
          }
        }
      });
    if (options.Progress && !options.Progress(double(end) / double(pieces.size())))
    {
      out.Aborted = true;
      return out;
    }
  }
  return out;
}

DistanceGrid SampleUnionDistance(
  const MedialEnvelope& envelope, double spacing, const std::function<bool(double)>& progress)
{
  if (envelope.Empty())
  {
    return DistanceGrid();
  }
  return SampleNarrowBand(
    envelope.Bounds(), spacing,
    [&envelope](const Point3& x) { return envelope.SignedDistance(x).Distance; }, progress);
}

PrimitiveRef SurfacePrimitive(const MedialEnvelope& envelope, const Point3& x)
{
  const MedialEnvelope::Nearest n = envelope.SignedDistance(x);
  if (n.Primitive.Kind != PrimitiveKind::Cone || n.Primitive.Id < 0)
  {
    return n.Primitive;
  }
  const ConePrimitive& c = envelope.Cones()[n.Primitive.Id];
  const auto& edge = envelope.ConeEdges()[n.Primitive.Id];
  if (c.Nested)
  {
    return { PrimitiveKind::Sphere, edge[c.Big] };
  }
  const Point3 v = x - c.C[0];
  const double a = Dot(v, c.Axis);
  const double b = Norm(v - a * c.Axis);
  const double s = a * c.CosPhi - b * c.SinPhi;
  if (s <= 0.0)
  {
    return { PrimitiveKind::Sphere, edge[0] };
  }
  if (s >= c.Length * c.CosPhi)
  {
    return { PrimitiveKind::Sphere, edge[1] };
  }
  return n.Primitive;
}

std::vector<PrimitiveRef> SurfacePrimitives(
  const MedialEnvelope& envelope, const std::vector<Point3>& points)
{
  std::vector<PrimitiveRef> refs(points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t i = r.begin(); i < r.end(); ++i)
      {
        refs[i] = SurfacePrimitive(envelope, points[i]);
      }
    });
  return refs;
}
}
