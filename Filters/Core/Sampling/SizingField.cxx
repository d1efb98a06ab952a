// SPDX-License-Identifier: GPL-3.0-or-later
#include "Sampling/SizingField.h"

#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Sampling/SurfaceCandidates.h"
#include "Surface/SurfacePreparation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>

namespace medialaxis
{
namespace
{
// Lowers every value to at most its neighbours' plus `gradation` times their
// distance over the symmetric k-nearest graph, so the spacing grows
// gradually away from a thin part. The result is each value's minimum over
// the paths to it (the sum along a path taken in its order): rounding is
// monotone, so that minimum is the same whatever order the edges are
// relaxed in. Hence only the points that lower a neighbour start the
// search: on most surfaces they are few.
void LimitGradation(const std::vector<Point3>& points, const KdTree& tree, double gradation,
  std::vector<double>& values)
{
  const std::size_t n = points.size();
  constexpr std::size_t k = 8;
  // The k nearest of each point (itself left out), then the graph made
  // symmetric, in compressed rows.
  std::vector<std::uint32_t> nearest(n * k);
  std::vector<std::uint8_t> found(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      std::vector<std::uint32_t> ids;
      std::vector<double> d2;
      for (std::size_t i = r.begin(); i != r.end(); ++i)
      {
        tree.Nearest(points[i], k + 1, ids, d2);
        std::uint8_t c = 0;
        for (std::uint32_t j : ids)
        {
          if (j != i && c < k)
          {
            nearest[i * k + c++] = j;
          }
        }
        found[i] = c;
      }
    });
  std::vector<std::size_t> start(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    start[i + 1] += found[i];
    for (std::size_t c = 0; c < found[i]; ++c)
    {
      ++start[nearest[i * k + c] + 1];
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    start[i + 1] += start[i];
  }
  std::vector<std::uint32_t> adjacent(start[n]);
  {
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (std::size_t c = 0; c < found[i]; ++c)
      {
        const std::uint32_t j = nearest[i * k + c];
        adjacent[cursor[i]++] = j;
        adjacent[cursor[j]++] = static_cast<std::uint32_t>(i);
      }
    }
  }
  auto limit = [&](std::uint32_t i, std::uint32_t j)
  { return values[i] + gradation * std::sqrt(Distance2(points[i], points[j])); };
  using Entry = std::pair<double, std::uint32_t>;
  std::vector<Entry> seeds;
  for (std::uint32_t i = 0; i < n; ++i)
  {
    if (std::any_of(adjacent.begin() + static_cast<std::ptrdiff_t>(start[i]),
          adjacent.begin() + static_cast<std::ptrdiff_t>(start[i + 1]),
          [&](std::uint32_t j) { return limit(i, j) < values[j]; }))
    {
      seeds.emplace_back(values[i], i);
    }
  }
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue(
    std::greater<Entry>(), std::move(seeds));
  while (!queue.empty())
  {
    const auto [value, i] = queue.top();
    queue.pop();
    if (value > values[i])
    {
      continue; // a stale entry
    }
    for (std::size_t a = start[i]; a < start[i + 1]; ++a)
    {
      const std::uint32_t j = adjacent[a];
      const double limited = limit(i, j);
      if (limited < values[j])
      {
        values[j] = limited;
        queue.push({ limited, j });
      }
    }
  }
}
}

SizingField::SizingField(const TriangleMesh& surface, std::size_t numberOfSamples,
  std::uint64_t seed, const SizingOptions& options)
{
  const double area = SurfaceArea(surface);
  // Samples beyond the budget (ExtraSampleFraction) go on thin parts, whose
  // thickness the probes must then resolve as finely.
  const double extraFraction = std::max(0.0, options.ExtraSampleFraction);
  const std::size_t probes = std::max<std::size_t>(64,
    static_cast<std::size_t>(
      std::ceil(options.ProbesPerSample * (1.0 + extraFraction) * numberOfSamples)));
  // A stream of its own, so the probes do not repeat the candidates.
  Candidates drawn = UniformCandidates(surface, probes, seed ^ 0x5151A7E3C0FFEE11ull);
  this->ProbePoints = std::move(drawn.Points);
  this->Tree = std::make_unique<KdTree>(this->ProbePoints);
  const double uniform = IdealSampleSpacing(area, std::max<std::size_t>(1, numberOfSamples));
  const double finest = std::clamp(options.FinestSpacingRatio, 1e-3, 1.0);
  const double perThickness = std::max(options.SpacingPerThickness, 1e-6);
  // No spacing exceeds uniform / finest, so thicker than that / perThickness
  // is thick enough: the rays stop there, which keeps them short.
  this->ThickEnough = uniform / finest / perThickness;
  {
    const TriangleLocator locator(surface);
    ThicknessOptions thickness = options.Thickness;
    thickness.MaximumThickness = std::min(thickness.MaximumThickness, this->ThickEnough);
    this->ProbeThickness =
      EstimateLocalThickness(surface, locator, this->ProbePoints, drawn.Triangles, thickness);
  }
  std::vector<double> wanted(probes);
  for (std::size_t i = 0; i < probes; ++i)
  {
    wanted[i] = std::min(perThickness * this->ProbeThickness[i], uniform / finest);
  }
  LimitGradation(this->ProbePoints, *this->Tree, options.Gradation, wanted);

  this->Coarsest = uniform;
  this->Uniform = *std::min_element(wanted.begin(), wanted.end()) >= uniform;
  if (this->Uniform)
  {
    this->ProbeSpacing.assign(probes, uniform);
    return;
  }
  // Each probe stands for area / probes of surface; a hexagonal packing of
  // spacing h puts 2 / (sqrt(3) h^2) samples on unit area. The coarsest
  // spacing H is found so that the total is the budget, with every spacing
  // in [finest * H, H].
  auto count = [&](double coarsest)
  {
    double sum = 0.0;
    for (double w : wanted)
    {
      const double h = std::clamp(w, finest * coarsest, coarsest);
      sum += 1.0 / (h * h);
    }
    return sum * (area / probes) * 2.0 / std::sqrt(3.0);
  };
  double lo = uniform, hi = uniform / finest;
  for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it)
  {
    const double mid = 0.5 * (lo + hi);
    (count(mid) > static_cast<double>(numberOfSamples) ? lo : hi) = mid;
  }
  this->Coarsest = hi;
  this->ProbeSpacing.resize(probes);
  for (std::size_t i = 0; i < probes; ++i)
  {
    this->ProbeSpacing[i] = std::clamp(wanted[i], finest * hi, hi);
  }
  if (extraFraction > 0.0)
  {
    this->FollowThinPartsBeyondBudget(
      wanted, area, finest * hi, extraFraction * static_cast<double>(numberOfSamples));
  }
}

void SizingField::FollowThinPartsBeyondBudget(
  const std::vector<double>& wanted, double area, double finest, double budget)
{
  // Samples more than at the finest spacing, where the parts are thinner,
  // if no spacing is below `floor`.
  const double perProbe = (area / static_cast<double>(wanted.size())) * 2.0 / std::sqrt(3.0);
  auto extra = [&](double floor)
  {
    double sum = 0.0;
    for (double w : wanted)
    {
      if (w < finest)
      {
        const double h = std::max(w, floor);
        sum += 1.0 / (h * h) - 1.0 / (finest * finest);
      }
    }
    return sum * perProbe;
  };
  // The lowest floor within the budget (a part measured far thinner than
  // the rest, e.g. a ray that ended on a nearby crease, cannot take more).
  double lo = 1e-3 * finest, hi = finest;
  if (extra(lo) > budget)
  {
    for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (extra(mid) > budget ? lo : hi) = mid;
    }
    lo = hi;
  }
  for (std::size_t i = 0; i < wanted.size(); ++i)
  {
    if (wanted[i] < finest)
    {
      this->ProbeSpacing[i] = std::max(wanted[i], lo);
    }
  }
  this->Extra = static_cast<std::size_t>(std::llround(extra(lo)));
}
}
