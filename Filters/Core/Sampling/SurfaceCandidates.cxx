// SPDX-License-Identifier: GPL-3.0-or-later
#include "Sampling/SurfaceCandidates.h"

#include "Geometry/AreaSampling.h"
#include "Geometry/MortonOrder.h"
#include "Geometry/Vec3.h"
#include "Sampling/SizingField.h"
#include "Support/Random.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
double TriangleArea(const TriangleMesh& surface, const Triangle& tri)
{
  const Point3& a = surface.Points[tri[0]];
  return 0.5 * Norm(Cross(surface.Points[tri[1]] - a, surface.Points[tri[2]] - a));
}

// The triangle whose cumulative range holds u in [0, 1) (PickFromCdf),
// moved back past any of zero weight.
std::size_t PickTriangle(const std::vector<double>& cumulative, double u)
{
  std::size_t t = PickFromCdf(cumulative, u);
  while (t > 0 && cumulative[t] == cumulative[t - 1])
  {
    --t;
  }
  return t;
}
}

Candidates UniformCandidates(const TriangleMesh& surface, std::size_t count, std::uint64_t seed)
{
  const std::size_t nt = surface.Triangles.size();
  std::vector<double> cumulative(nt);
  double total = 0.0;
  for (std::size_t t = 0; t < nt; ++t)
  {
    total += TriangleArea(surface, surface.Triangles[t]);
    cumulative[t] = total;
  }
  Candidates candidates;
  candidates.Points.resize(count);
  candidates.Triangles.resize(count);
  const Random random(seed);
  // Candidate i takes draws 3i, 3i + 1 and 3i + 2 of the stream: in parallel,
  // the points of one sequential loop.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      Random draws = random.After(3 * range.begin());
      for (std::size_t i = range.begin(); i != range.end(); ++i)
      {
        const std::size_t t = PickTriangle(cumulative, draws.Uniform());
        const Triangle& tri = surface.Triangles[t];
        const double r1 = draws.Uniform(), r2 = draws.Uniform(); // drawn in this order
        candidates.Points[i] = PointInTriangle(
          surface.Points[tri[0]], surface.Points[tri[1]], surface.Points[tri[2]], r1, r2);
        candidates.Triangles[i] = static_cast<Index>(t);
      }
    });
  return candidates;
}

Candidates AdaptiveCandidates(
  const TriangleMesh& surface, const SizingField& field, std::size_t count, std::uint64_t seed)
{
  // The density bound of a triangle: the finest spacing at its corners and
  // centre. Inside, a point is kept with probability (bound / spacing)^2.
  const std::size_t nv = surface.Points.size(), nt = surface.Triangles.size();
  std::vector<double> vertexSpacing(nv), triangleSpacing(nt);
  std::vector<char> constant(nt); // one spacing all over: no rejection needed
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 1024),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t v = r.begin(); v != r.end(); ++v)
      {
        vertexSpacing[v] = field.Spacing(surface.Points[v]);
      }
    });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, 1024),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t t = r.begin(); t != r.end(); ++t)
      {
        const Triangle& tri = surface.Triangles[t];
        const Point3 centre =
          (1.0 / 3.0) * (surface.Points[tri[0]] + surface.Points[tri[1]] + surface.Points[tri[2]]);
        const auto [lo, hi] = std::minmax({ vertexSpacing[tri[0]], vertexSpacing[tri[1]],
          vertexSpacing[tri[2]], field.Spacing(centre) });
        triangleSpacing[t] = lo;
        constant[t] = lo == hi;
      }
    });
  std::vector<double> cumulative(nt);
  double total = 0.0;
  for (std::size_t t = 0; t < nt; ++t)
  {
    const double h = triangleSpacing[t];
    total += TriangleArea(surface, surface.Triangles[t]) / (h * h);
    cumulative[t] = total;
  }

  Candidates candidates;
  candidates.Points.reserve(count);
  candidates.Triangles.reserve(count);
  candidates.Spacing.reserve(count);
  const Random random(seed);
  // Attempt j takes draws 4j to 4j + 3 of the stream. Attempts are made in
  // parallel, a batch at a time, and kept in their order until there are
  // enough: the candidates of one sequential loop.
  struct Attempt
  {
    Point3 P;
    double Spacing;
    Index Triangle;
    bool Kept;
  };
  std::vector<Attempt> attempts;
  for (std::size_t first = 0; candidates.Points.size() < count;)
  {
    const std::size_t batch = std::max<std::size_t>(4096, count - candidates.Points.size());
    attempts.resize(batch);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch, 1024),
      [&](const tbb::blocked_range<std::size_t>& range)
      {
        Random draws = random.After(4 * (first + range.begin()));
        for (std::size_t j = range.begin(); j != range.end(); ++j)
        {
          const std::size_t t = PickTriangle(cumulative, draws.Uniform());
          const Triangle& tri = surface.Triangles[t];
          const double r1 = draws.Uniform(), r2 = draws.Uniform(), keep = draws.Uniform();
          const Point3 p = PointInTriangle(
            surface.Points[tri[0]], surface.Points[tri[1]], surface.Points[tri[2]], r1, r2);
          const double h = constant[t] ? triangleSpacing[t] : field.Spacing(p);
          const double ratio = triangleSpacing[t] / h;
          attempts[j] = { p, h, static_cast<Index>(t), keep < ratio * ratio };
        }
      });
    for (std::size_t j = 0; j < batch && candidates.Points.size() < count; ++j)
    {
      if (attempts[j].Kept)
      {
        candidates.Points.push_back(attempts[j].P);
        candidates.Triangles.push_back(attempts[j].Triangle);
        candidates.Spacing.push_back(attempts[j].Spacing);
      }
    }
    first += batch;
  }
  return candidates;
}

void SortSpatially(Candidates& candidates)
{
  const std::size_t n = candidates.Points.size();
  const std::vector<std::uint32_t> order =
    MortonOrder(n, [&candidates](std::size_t i) { return candidates.Points[i]; });
  Candidates sorted;
  sorted.Points.resize(n);
  sorted.Triangles.resize(n);
  sorted.Spacing.resize(candidates.Spacing.empty() ? 0 : n);
  for (std::size_t i = 0; i < n; ++i)
  {
    sorted.Points[i] = candidates.Points[order[i]];
    sorted.Triangles[i] = candidates.Triangles[order[i]];
    if (!sorted.Spacing.empty())
    {
      sorted.Spacing[i] = candidates.Spacing[order[i]];
    }
  }
  candidates = std::move(sorted);
}
}
