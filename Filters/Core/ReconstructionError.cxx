// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReconstructionError.h"

#include "Random.h"
#include "TriangleLocator.h"
#include "Vec3.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr std::size_t Chunk = 16384;

// The generator of sample k: independent of how samples are split over threads.
Random SampleRandom(std::uint64_t seed, std::size_t k)
{
  return Random(seed ^ (0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(k) + 1)));
}

// Index of the item whose cumulative range holds u in [0, total).
std::size_t PickFromCdf(const std::vector<double>& cdf, double u)
{
  const auto it = std::upper_bound(cdf.begin(), cdf.end(), u * cdf.back());
  return std::min<std::size_t>(static_cast<std::size_t>(it - cdf.begin()), cdf.size() - 1);
}

Point3 PointInTriangle(const Point3& a, const Point3& b, const Point3& c, double u, double v)
{
  const double s = std::sqrt(u);
  return (1.0 - s) * a + (s * (1.0 - v)) * b + (s * v) * c;
}

// Runs f(i) for i in [begin, end) in parallel, in chunks, reporting progress
// as first + span x fraction; false when aborted.
template <typename F>
bool ForEachChunked(
  std::size_t n, double first, double span, const std::function<bool(double)>& progress, F&& f)
{
  for (std::size_t begin = 0; begin < n; begin += Chunk)
  {
    const std::size_t end = std::min(n, begin + Chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 64),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          f(i);
        }
      });
    if (progress && !progress(first + span * double(end) / double(n)))
    {
      return false;
    }
  }
  return true;
}

// A primitive surface patch envelope samples are drawn from.
struct Patch
{
  PrimitiveRef Ref;
  int Side; // slab: which tangent triangle
};

Point3 SamplePatch(const MedialEnvelope& envelope, const Patch& patch, Random& rng)
{
  const double u = rng.Uniform(), v = rng.Uniform();
  switch (patch.Ref.Kind)
  {
    case PrimitiveKind::Sphere:
    {
      const SpherePrimitive& s = envelope.Spheres()[patch.Ref.Id];
      const double z = 1.0 - 2.0 * u, theta = 2.0 * Pi * v;
      const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
      return s.Center + s.Radius * Point3{ rho * std::cos(theta), rho * std::sin(theta), z };
    }
    case PrimitiveKind::Cone:
    {
      // Area density along the slant grows linearly with the ring radius.
      const ConePrimitive& c = envelope.Cones()[patch.Ref.Id];
      const double rho0 = c.R[0] * c.CosPhi, rho1 = c.R[1] * c.CosPhi;
      double sigma = u;
      if (std::abs(rho1 - rho0) > 1e-12 * (rho0 + rho1))
      {
        sigma = (std::sqrt(rho0 * rho0 + u * (rho1 * rho1 - rho0 * rho0)) - rho0) / (rho1 - rho0);
      }
      const double theta = 2.0 * Pi * v;
      const Point3 radial = std::cos(theta) * c.Perp1 + std::sin(theta) * c.Perp2;
      const Point3 slant = c.CosPhi * c.Axis - c.SinPhi * radial;
      return ConeTangentPoint(c, 0, theta) + (sigma * c.Length * c.CosPhi) * slant;
    }
    default:
    {
      const auto t = SlabTangentTriangle(envelope.Slabs()[patch.Ref.Id], patch.Side);
      return PointInTriangle(t[0], t[1], t[2], u, v);
    }
  }
}

double PatchArea(const MedialEnvelope& envelope, const Patch& patch)
{
  switch (patch.Ref.Kind)
  {
    case PrimitiveKind::Sphere:
    {
      const double r = envelope.Spheres()[patch.Ref.Id].Radius;
      return 4.0 * Pi * r * r;
    }
    case PrimitiveKind::Cone:
      return ConeLateralArea(envelope.Cones()[patch.Ref.Id]);
    default:
    {
      const auto t = SlabTangentTriangle(envelope.Slabs()[patch.Ref.Id], patch.Side);
      return 0.5 * Norm(Cross(t[1] - t[0], t[2] - t[0]));
    }
  }
}

void Summarise(const std::vector<double>& values, std::size_t meanBegin, OneSidedError& out)
{
  out.Samples = values.size();
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    out.Hausdorff = std::max(out.Hausdorff, values[i]);
    if (i >= meanBegin)
    {
      sum += values[i];
      sum2 += values[i] * values[i];
    }
  }
  const std::size_t n = values.size() - meanBegin;
  if (n > 0)
  {
    out.Mean = sum / double(n);
    out.RMS = std::sqrt(sum2 / double(n));
  }
}
}

void SampleTriangleMesh(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed,
  std::vector<Point3>& points, std::vector<Point3>& normals)
{
  points.resize(count);
  normals.resize(count);
  if (count == 0 || mesh.Triangles.empty())
  {
    points.clear();
    normals.clear();
    return;
  }
  std::vector<double> cdf(mesh.Triangles.size());
  double total = 0.0;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const Triangle& tri = mesh.Triangles[t];
    const Point3& a = mesh.Points[tri[0]];
    total += 0.5 * Norm(Cross(mesh.Points[tri[1]] - a, mesh.Points[tri[2]] - a));
    cdf[t] = total;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t k = r.begin(); k < r.end(); ++k)
      {
        Random rng = SampleRandom(seed, k);
        const Triangle& tri = mesh.Triangles[PickFromCdf(cdf, rng.Uniform())];
        const Point3 &a = mesh.Points[tri[0]], &b = mesh.Points[tri[1]], &c = mesh.Points[tri[2]];
        const double u = rng.Uniform(), v = rng.Uniform();
        points[k] = PointInTriangle(a, b, c, u, v);
        normals[k] = Normalized(Cross(b - a, c - a));
      }
    });
}

ReconstructionErrorResult ComputeReconstructionError(const TriangleMesh& surface,
  const MedialEnvelope& envelope, const ReconstructionErrorOptions& options)
{
  ReconstructionErrorResult result;
  if (surface.Points.empty() || surface.Triangles.empty() || envelope.Empty())
  {
    return result;
  }
  const auto box = BoundingBox(surface.Points);
  result.Diagonal = Norm(box.second - box.first);

  // Surface -> envelope, at the vertices (normals: area-weighted) and samples.
  const std::size_t nv = surface.Points.size();
  std::vector<Point3> vertexNormals(nv, Point3{ 0, 0, 0 });
  for (const Triangle& t : surface.Triangles)
  {
    const Point3 n = Cross(
      surface.Points[t[1]] - surface.Points[t[0]], surface.Points[t[2]] - surface.Points[t[0]]);
    for (Index v : t)
    {
      vertexNormals[v] = vertexNormals[v] + n;
    }
  }
  std::vector<Point3> samples, sampleNormals;
  SampleTriangleMesh(surface, options.NumberOfSamples, options.RandomSeed, samples, sampleNormals);
  const std::size_t ns = samples.size();
  std::vector<MedialEnvelope::BoundaryDistance> distances(nv + ns);
  if (!ForEachChunked(nv + ns, 0.0, 0.6, options.Progress,
        [&](std::size_t i)
        {
          distances[i] = i < nv
            ? envelope.DistanceToBoundary(surface.Points[i], &vertexNormals[i])
            : envelope.DistanceToBoundary(samples[i - nv], &sampleNormals[i - nv]);
        }))
  {
    result.Aborted = true;
    return result;
  }
  result.VertexDistance.resize(nv);
  result.VertexLowerBound.resize(nv);
  result.VertexSignedDistance.resize(nv);
  std::vector<double> upper(nv + ns);
  for (std::size_t i = 0; i < nv + ns; ++i)
  {
    const auto& d = distances[i];
    upper[i] = d.Upper;
    if (i < nv)
    {
      result.VertexDistance[i] = d.Upper;
      result.VertexLowerBound[i] = d.Lower;
      result.VertexSignedDistance[i] = d.Signed;
    }
    result.SurfaceToEnvelope.HausdorffLowerBound =
      std::max(result.SurfaceToEnvelope.HausdorffLowerBound, d.Lower);
    result.InsidePoints += d.Inside ? 1 : 0;
    result.UncertifiedPoints += d.Exact ? 0 : 1;
    result.LargestBoundGap = std::max(result.LargestBoundGap, d.Upper - d.Lower);
  }
  // Mean and RMS over the area-uniform samples (over the vertices if none).
  Summarise(upper, ns > 0 ? nv : 0, result.SurfaceToEnvelope);

  // Envelope -> surface: candidates on every primitive surface, area-uniform,
  // kept when on the boundary of the union; drawn in batches until enough
  // are kept. Candidate k depends only on (seed, k).
  std::vector<Patch> patches;
  std::vector<double> cdf;
  double totalArea = 0.0;
  auto addPatch = [&](const Patch& p)
  {
    const double a = PatchArea(envelope, p);
    if (a > 0.0)
    {
      totalArea += a;
      patches.push_back(p);
      cdf.push_back(totalArea);
    }
  };
  for (std::size_t v = 0; v < envelope.Spheres().size(); ++v)
  {
    addPatch({ { PrimitiveKind::Sphere, static_cast<Index>(v) }, 0 });
  }
  for (std::size_t e = 0; e < envelope.Cones().size(); ++e)
  {
    addPatch({ { PrimitiveKind::Cone, static_cast<Index>(e) }, 0 });
  }
  for (std::size_t f = 0; f < envelope.Slabs().size(); ++f)
  {
    if (envelope.Slabs()[f].HasTangentPlanes)
    {
      addPatch({ { PrimitiveKind::Slab, static_cast<Index>(f) }, 0 });
      addPatch({ { PrimitiveKind::Slab, static_cast<Index>(f) }, 1 });
    }
  }
  const std::size_t target = patches.empty() ? 0 : options.NumberOfEnvelopeSamples;
  const std::uint64_t envelopeSeed = options.RandomSeed ^ 0x5DEECE66Dull;
  std::size_t drawn = 0;
  std::vector<Point3> batchPoints;
  std::vector<PrimitiveRef> batchRefs;
  std::vector<std::uint8_t> keep;
  while (result.EnvelopeSamples.size() < target && drawn < 1000 * target)
  {
    const std::size_t have = result.EnvelopeSamples.size();
    const double rate = drawn > 0 ? std::max(double(have) / double(drawn), 1e-3) : 0.5;
    const std::size_t batch = std::min<std::size_t>(
      static_cast<std::size_t>(1.2 * double(target - have) / rate) + 1024, 1000 * target - drawn);
    batchPoints.resize(batch);
    batchRefs.resize(batch);
    keep.assign(batch, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          Random rng = SampleRandom(envelopeSeed, drawn + i);
          const Patch& patch = patches[PickFromCdf(cdf, rng.Uniform())];
          batchPoints[i] = SamplePatch(envelope, patch, rng);
          batchRefs[i] = patch.Ref;
          keep[i] = envelope.StrictlyInside(batchPoints[i], envelope.Tolerance()) ? 0 : 1;
        }
      });
    for (std::size_t i = 0; i < batch && result.EnvelopeSamples.size() < target; ++i)
    {
      result.EnvelopeCandidates = drawn + i + 1;
      if (keep[i])
      {
        result.EnvelopeSamples.push_back(batchPoints[i]);
        result.EnvelopeSamplePrimitive.push_back(batchRefs[i]);
      }
    }
    drawn += batch;
    if (options.Progress &&
      !options.Progress(0.6 + 0.2 * double(result.EnvelopeSamples.size()) / double(target)))
    {
      result.Aborted = true;
      return result;
    }
  }
  const TriangleLocator locator(surface);
  result.EnvelopeSampleDistance.resize(result.EnvelopeSamples.size());
  if (!ForEachChunked(result.EnvelopeSamples.size(), 0.8, 0.2, options.Progress,
        [&](std::size_t i)
        { result.EnvelopeSampleDistance[i] = locator.Distance(result.EnvelopeSamples[i]); }))
  {
    result.Aborted = true;
    return result;
  }
  Summarise(result.EnvelopeSampleDistance, 0, result.EnvelopeToSurface);
  result.EnvelopeToSurface.HausdorffLowerBound = result.EnvelopeToSurface.Hausdorff;

  result.Hausdorff =
    std::max(result.SurfaceToEnvelope.Hausdorff, result.EnvelopeToSurface.Hausdorff);
  result.Mean = std::max(result.SurfaceToEnvelope.Mean, result.EnvelopeToSurface.Mean);
  result.RMS = std::max(result.SurfaceToEnvelope.RMS, result.EnvelopeToSurface.RMS);
  return result;
}
}
