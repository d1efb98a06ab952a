// SPDX-License-Identifier: GPL-3.0-or-later
#include "Envelope/ReconstructionError.h"

#include "Envelope/EnvelopeMaximum.h"
#include "Envelope/ExposedPieces.h"
#include "Geometry/AreaSampling.h"

#include "Geometry/KdTree.h"
#include "Geometry/MortonOrder.h"
#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Support/Random.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace medialaxis
{
namespace
{
constexpr std::size_t Chunk = 16384;

// The generator of sample k: independent of how samples are split over threads.
Random SampleRandom(std::uint64_t seed, std::size_t k)
{
  return Random(seed ^ (0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(k) + 1)));
}

// Runs f(i, state) for i in [begin, end) in parallel, in chunks, reporting
// progress as first + span x fraction; false when aborted. `state` is a
// State made afresh for every range of indices run in order on one thread.
template <typename State = int, typename F>
bool ForEachChunked(
  std::size_t n, double first, double span, const std::function<bool(double)>& progress, F&& f)
{
  for (std::size_t begin = 0; begin < n; begin += Chunk)
  {
    const std::size_t end = std::min(n, begin + Chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 64),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        State state{};
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          f(i, state);
        }
      });
    if (progress && !progress(first + span * double(end) / double(n)))
    {
      return false;
    }
  }
  return true;
}

// Seconds since `start`, restarting it.
double Lap(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
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
  auto clock = std::chrono::steady_clock::now();
  // Two serial builds run in the background while the other threads work:
  // the surface's triangle hierarchy (for envelope -> surface) during
  // surface -> envelope, and the tree over the envelope samples (for the
  // inside bounds) during envelope -> surface. Waited for before anything
  // they use is moved or destroyed, and by the guard on other ways out.
  std::optional<TriangleLocator> locator;
  std::optional<KdTree> boundary;
  tbb::task_group background;
  struct WaitOnExit
  {
    tbb::task_group& Tasks;
    ~WaitOnExit() { this->Tasks.wait(); }
  } waitOnExit{ background };

  // Surface -> envelope, at the vertices (normals: area-weighted) and samples.
  std::vector<Point3> samples, sampleNormals;
  SampleTriangleMesh(surface, options.NumberOfSamples, options.RandomSeed, samples, sampleNormals);
  background.run([&] { locator.emplace(surface); });
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
  const std::size_t ns = samples.size();
  std::vector<MedialEnvelope::BoundaryDistance> distances(nv + ns);
  const std::vector<std::uint32_t> surfaceOrder = MortonOrder(
    nv + ns, [&](std::size_t i) { return i < nv ? surface.Points[i] : samples[i - nv]; });
  // Along the Morton curve each point's search starts from the previous
  // point's nearest primitive (the values do not depend on it).
  struct Warm
  {
    std::uint32_t Position = MedialEnvelope::NoPrimitive;
  };
  // Isolated, so that this thread, waiting for its loops, does not take up
  // the background task and leave the loops to the others.
  const bool surfaceDone = tbb::this_task_arena::isolate(
    [&]
    {
      return ForEachChunked<Warm>(nv + ns, 0.0, 0.6, options.Progress,
        [&](std::size_t k, Warm& warm)
        {
          const std::size_t i = surfaceOrder[k];
          distances[i] = i < nv
            ? envelope.DistanceToBoundary(surface.Points[i], &vertexNormals[i], &warm.Position)
            : envelope.DistanceToBoundary(samples[i - nv], &sampleNormals[i - nv], &warm.Position);
        });
    });
  if (!surfaceDone)
  {
    result.Aborted = true;
    return result;
  }
  // Envelope -> surface: candidates on the primitive surfaces (where they
  // can be exposed, see EnvelopePieces), area-uniform, kept when on the
  // boundary of the union; drawn in batches until enough are kept.
  // Candidate k depends only on (seed, k).
  result.SurfaceSeconds = Lap(clock);
  const ExposedPieceSet pieces = EnvelopePieces(envelope);
  result.PiecesSeconds = Lap(clock);
  const std::size_t target = pieces.Pieces.empty() ? 0 : options.NumberOfEnvelopeSamples;
  const std::size_t limit = 1000 * target;
  const std::uint64_t envelopeSeed = options.RandomSeed ^ 0x5DEECE66Dull;
  std::size_t drawn = 0;
  std::vector<Point3> batchPoints;
  std::vector<std::uint32_t> batchPieces;
  std::vector<std::uint8_t> keep;
  std::vector<double> batchKeys;
  std::vector<std::uint32_t> accepted;
  while (result.EnvelopeSamples.size() < target && drawn < limit)
  {
    const std::size_t have = result.EnvelopeSamples.size();
    const double rate = drawn > 0 ? std::max(double(have) / double(drawn), 1e-3) : 0.5;
    const std::size_t batch =
      std::min<std::size_t>({ static_cast<std::size_t>(1.2 * double(target - have) / rate) + 1024,
        std::size_t(1) << 18, limit - drawn });
    batchPoints.resize(batch);
    batchPieces.resize(batch);
    keep.assign(batch, 0);
    // Stratified over the pieces' cumulative area: candidate i of the batch
    // takes u in [i, i + 1) / batch, so that a range of candidates walks
    // through the pieces in order (a random pick per candidate was mostly
    // cache misses). Each candidate is still uniform on the pieces.
    batchKeys.resize(batch);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        std::size_t piece = 0;
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          Random rng = SampleRandom(envelopeSeed, drawn + i);
          const double u = std::min((double(i) + rng.Uniform()) / double(batch), 1.0);
          piece = i == r.begin() ? pieces.Cdf.Pick(u) : pieces.Cdf.PickFrom(u, piece);
          batchPieces[i] = static_cast<std::uint32_t>(piece);
          batchPoints[i] = SamplePiece(envelope, pieces.Pieces[piece], rng);
          batchKeys[i] = rng.Uniform();
        }
      });
    // Tested in order: consecutive candidates are close (the pieces are in
    // Morton order), so a primitive that buried one is tried first on the
    // next, and they share cached tree nodes. keep[i] does not depend on
    // that order.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        std::uint32_t hint = MedialEnvelope::NoBurial;
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          // Neighbours next: they bury most rejected candidates.
          Index vertices[3];
          const int count = envelope.MedialVertices(pieces.Pieces[batchPieces[i]].Ref, vertices);
          const std::uint32_t by =
            envelope.FindBurying(batchPoints[i], envelope.Tolerance(), vertices, count, hint);
          keep[i] = by == MedialEnvelope::NoBurial ? 1 : 0;
          hint = keep[i] ? hint : by;
        }
      });
    // Kept candidates beyond the target: a random subset (by key), not the
    // first ones, which would favour the pieces at the start of the order.
    accepted.clear();
    for (std::size_t i = 0; i < batch; ++i)
    {
      if (keep[i])
      {
        accepted.push_back(static_cast<std::uint32_t>(i));
      }
    }
    const std::size_t wanted = target - result.EnvelopeSamples.size();
    if (accepted.size() > wanted)
    {
      auto byKey = [&](std::uint32_t a, std::uint32_t b)
      { return batchKeys[a] < batchKeys[b] || (batchKeys[a] == batchKeys[b] && a < b); };
      std::nth_element(accepted.begin(), accepted.begin() + wanted, accepted.end(), byKey);
      accepted.resize(wanted);
      std::sort(accepted.begin(), accepted.end());
    }
    for (const std::uint32_t i : accepted)
    {
      result.EnvelopeSamples.push_back(batchPoints[i]);
      result.EnvelopeSamplePrimitive.push_back(pieces.Pieces[batchPieces[i]].Ref);
    }
    result.EnvelopeCandidates = drawn + batch;
    drawn += batch;
    if (options.Progress &&
      !options.Progress(0.6 + 0.2 * double(result.EnvelopeSamples.size()) / double(target)))
    {
      result.Aborted = true;
      return result;
    }
  }
  result.CandidatesSeconds = Lap(clock);
  background.wait();
  if (!result.EnvelopeSamples.empty())
  {
    background.run([&] { boundary.emplace(result.EnvelopeSamples); });
  }
  result.EnvelopeSampleDistance.resize(result.EnvelopeSamples.size());
  const bool envelopeDone = tbb::this_task_arena::isolate(
    [&]
    {
      return ForEachChunked(result.EnvelopeSamples.size(), 0.8, 0.2, options.Progress,
        [&](std::size_t i, int)
        { result.EnvelopeSampleDistance[i] = locator->Distance(result.EnvelopeSamples[i]); });
    });
  if (!envelopeDone)
  {
    background.wait();
    result.Aborted = true;
    return result;
  }
  Summarise(result.EnvelopeSampleDistance, 0, result.EnvelopeToSurface);
  // The samples' largest distance, raised by climbing from the farthest ones
  // (EnvelopeMaximum.h). First step: the samples' spacing, from the exposed
  // area estimated as the pieces' area times the share of candidates kept.
  if (!result.EnvelopeSamples.empty())
  {
    const auto farthest =
      std::max_element(result.EnvelopeSampleDistance.begin(), result.EnvelopeSampleDistance.end());
    result.EnvelopeFarthestPoint =
      result.EnvelopeSamples[farthest - result.EnvelopeSampleDistance.begin()];
    const double kept = double(result.EnvelopeSamples.size()) / double(result.EnvelopeCandidates);
    EnvelopeMaximumOptions climb;
    climb.Seeds = options.MaximumSearches;
    climb.Step = std::sqrt(pieces.Cdf.Total() * kept / double(result.EnvelopeSamples.size()));
    const EnvelopeMaximum refined = RefineEnvelopeMaximum(
      envelope, result.EnvelopeSamples, result.EnvelopeSamplePrimitive,
      result.EnvelopeSampleDistance, [&](const Point3& p) { return locator->Distance(p); }, climb);
    if (refined.Distance > result.EnvelopeToSurface.Hausdorff)
    {
      result.EnvelopeToSurface.Hausdorff = refined.Distance;
      result.EnvelopeFarthestPoint = refined.Point;
    }
  }
  result.EnvelopeToSurface.HausdorffLowerBound = result.EnvelopeToSurface.Hausdorff;
  result.EnvelopeSeconds = Lap(clock);

  // Inside points whose distance to the union's boundary is not certified
  // exact carry an upper bound from projections and ray traces, which can be
  // far off where many primitives meet. Every envelope sample is a point of
  // that boundary, so the nearest one bounds the distance from above too.
  background.wait();
  if (boundary)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv + ns, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          auto& d = distances[i];
          if (d.Inside && !d.Exact)
          {
            const Point3& p = i < nv ? surface.Points[i] : samples[i - nv];
            const double nearest = Norm(p - result.EnvelopeSamples[boundary->Nearest(p)]);
            d.Upper = std::max(d.Lower, std::min(d.Upper, nearest));
          }
        }
      });
  }
  result.TighteningSeconds = Lap(clock);
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

  result.Hausdorff =
    std::max(result.SurfaceToEnvelope.Hausdorff, result.EnvelopeToSurface.Hausdorff);
  result.Mean = std::max(result.SurfaceToEnvelope.Mean, result.EnvelopeToSurface.Mean);
  result.RMS = std::max(result.SurfaceToEnvelope.RMS, result.EnvelopeToSurface.RMS);
  return result;
}

ReconstructionErrorResult ComputeSurfaceDistanceError(const TriangleMesh& surface,
  const TriangleMesh& reconstruction, const ReconstructionErrorOptions& options)
{
  ReconstructionErrorResult result;
  if (surface.Points.empty() || surface.Triangles.empty() || reconstruction.Triangles.empty())
  {
    return result;
  }
  const auto box = BoundingBox(surface.Points);
  result.Diagonal = Norm(box.second - box.first);
  auto clock = std::chrono::steady_clock::now();
  const TriangleLocator toReconstruction(reconstruction);
  std::vector<Point3> samples, normals;
  SampleTriangleMesh(surface, options.NumberOfSamples, options.RandomSeed, samples, normals);
  const std::size_t nv = surface.Points.size(), ns = samples.size();
  std::vector<double> distance(nv + ns);
  result.VertexSignedDistance.resize(nv);
  if (!ForEachChunked(nv + ns, 0.0, 0.6, options.Progress,
        [&](std::size_t i, int)
        {
          const Point3& p = i < nv ? surface.Points[i] : samples[i - nv];
          distance[i] = toReconstruction.Distance(p);
          if (i < nv)
          {
            result.VertexSignedDistance[i] =
              toReconstruction.Inside(p) ? -distance[i] : distance[i];
          }
        }))
  {
    result.Aborted = true;
    return result;
  }
  for (double signedDistance : result.VertexSignedDistance)
  {
    result.InsidePoints += signedDistance < 0.0 ? 1 : 0;
  }
  result.VertexDistance.assign(
    distance.begin(), distance.begin() + static_cast<std::ptrdiff_t>(nv));
  result.VertexLowerBound = result.VertexDistance;
  Summarise(distance, ns > 0 ? nv : 0, result.SurfaceToEnvelope);
  result.SurfaceToEnvelope.HausdorffLowerBound = result.SurfaceToEnvelope.Hausdorff;
  result.SurfaceSeconds = Lap(clock);

  const TriangleLocator toSurface(surface);
  SampleTriangleMesh(reconstruction, options.NumberOfEnvelopeSamples,
    options.RandomSeed ^ 0x5DEECE66Dull, result.EnvelopeSamples, normals);
  result.EnvelopeCandidates = result.EnvelopeSamples.size();
  result.EnvelopeSampleDistance.resize(result.EnvelopeSamples.size());
  if (!ForEachChunked(result.EnvelopeSamples.size(), 0.6, 0.4, options.Progress,
        [&](std::size_t i, int)
        { result.EnvelopeSampleDistance[i] = toSurface.Distance(result.EnvelopeSamples[i]); }))
  {
    result.Aborted = true;
    return result;
  }
  Summarise(result.EnvelopeSampleDistance, 0, result.EnvelopeToSurface);
  result.EnvelopeToSurface.HausdorffLowerBound = result.EnvelopeToSurface.Hausdorff;
  for (std::size_t i = 0; i < result.EnvelopeSamples.size(); ++i)
  {
    if (result.EnvelopeSampleDistance[i] == result.EnvelopeToSurface.Hausdorff)
    {
      result.EnvelopeFarthestPoint = result.EnvelopeSamples[i];
      break;
    }
  }
  result.EnvelopeSeconds = Lap(clock);
  result.Hausdorff =
    std::max(result.SurfaceToEnvelope.Hausdorff, result.EnvelopeToSurface.Hausdorff);
  result.Mean = std::max(result.SurfaceToEnvelope.Mean, result.EnvelopeToSurface.Mean);
  result.RMS = std::max(result.SurfaceToEnvelope.RMS, result.EnvelopeToSurface.RMS);
  return result;
}
}
