// SPDX-License-Identifier: GPL-3.0-or-later
#include "Sampling/BlueNoiseSampler.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"
#include "Sampling/SizingField.h"
#include "Sampling/SurfaceCandidates.h"
#include "Surface/SurfacePreparation.h"
#include "Voronoi/RestrictedVoronoi.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace medialaxis
{
namespace
{
// Yuksel's weighted sample elimination: repeatedly removes the candidate
// with the largest crowding weight until `target` remain. Returns the kept
// candidate ids in increasing order. Written by hand: no library offers it.
// With `spacing` (one wanted spacing per candidate) two candidates crowd each
// other within the smaller of their spacings, so the neighbour lists stay
// symmetric and every region thins to its own density (Yuksel's adaptive
// sampling, section 5).
std::vector<std::uint32_t> EliminateSamples(const std::vector<Point3>& candidates,
  const std::vector<double>& spacing, std::size_t target, double area)
{
  const std::size_t m = candidates.size();
  constexpr double beta = 0.65, gamma = 1.5; // and alpha = 8, in `weight`
  const double rMax = std::sqrt(area / (2.0 * std::sqrt(3.0) * target));
  const double shrink = (1.0 - std::pow(double(target) / double(m), gamma)) * beta;
  const double rMin = rMax * shrink;
  const double uniformReach = 2.0 * rMax;
  const bool adaptive = !spacing.empty();
  auto weight = [&](double d, std::size_t i, std::size_t j)
  {
    const double reach = adaptive ? std::min(spacing[i], spacing[j]) : uniformReach;
    if (adaptive && d >= reach)
    {
      return 0.0;
    }
    const double floor = adaptive ? reach * shrink : 2.0 * rMin;
    d = std::max(std::min(d, reach), floor); // weight limiting
    const double x = 1.0 - d / reach;
    const double x2 = x * x, x4 = x2 * x2;
    return x4 * x4; // alpha = 8
  };

  // Neighbour lists (compressed rows), computed in parallel in fixed blocks.
  const KdTree tree(candidates);
  constexpr std::size_t block = 2048;
  const std::size_t blocks = (m + block - 1) / block;
  std::vector<std::vector<std::uint32_t>> blockIds(blocks);
  std::vector<std::vector<float>> blockWeights(blocks);
  std::vector<std::uint32_t> rowSize(m);
  std::vector<double> total(m, 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      std::vector<std::pair<std::uint32_t, double>> matches;
      for (std::size_t b = r.begin(); b != r.end(); ++b)
      {
        for (std::size_t i = b * block; i < std::min(m, (b + 1) * block); ++i)
        {
          tree.WithinRadius(candidates[i], adaptive ? spacing[i] : uniformReach, matches, false);
          std::uint32_t n = 0;
          for (const auto& [j, d2] : matches)
          {
            const double w = j == i ? 0.0 : weight(std::sqrt(d2), i, j);
            if (w == 0.0 && (j == i || adaptive))
            {
              continue;
            }
            blockIds[b].push_back(j);
            blockWeights[b].push_back(static_cast<float>(w));
            total[i] += w;
            ++n;
          }
          rowSize[i] = n;
        }
      }
    });
  std::vector<std::size_t> rowStart(m + 1, 0);
  for (std::size_t i = 0; i < m; ++i)
  {
    rowStart[i + 1] = rowStart[i] + rowSize[i];
  }
  std::vector<std::uint32_t> ids;
  std::vector<float> weights;
  ids.reserve(rowStart[m]);
  weights.reserve(rowStart[m]);
  for (std::size_t b = 0; b < blocks; ++b)
  {
    ids.insert(ids.end(), blockIds[b].begin(), blockIds[b].end());
    weights.insert(weights.end(), blockWeights[b].begin(), blockWeights[b].end());
    std::vector<std::uint32_t>().swap(blockIds[b]);
    std::vector<float>().swap(blockWeights[b]);
  }

  // Indexed 4-ary max-heap of (weight, id) with in-place updates: a removal
  // only lowers its neighbours' weights, which then sift down. Keys live in
  // the heap array itself so a sift touches one cache line per level. Ties
  // go to the lower id, so the order is fully determined.
  struct Node
  {
    float Weight; // 8-byte nodes: four children share one cache line
    std::uint32_t Id;
  };
  auto above = [](const Node& a, const Node& b)
  { return a.Weight != b.Weight ? a.Weight > b.Weight : a.Id < b.Id; };
  std::vector<Node> heap(m);
  std::vector<std::uint32_t> position(m);
  for (std::uint32_t i = 0; i < m; ++i)
  {
    heap[i] = { static_cast<float>(total[i]), i };
  }
  std::size_t heapSize = m;
  auto siftDown = [&](std::size_t k)
  {
    const Node item = heap[k];
    for (;;)
    {
      const std::size_t first = 4 * k + 1;
      if (first >= heapSize)
      {
        break;
      }
      std::size_t best = first;
      const std::size_t last = std::min(first + 4, heapSize);
      for (std::size_t c = first + 1; c < last; ++c)
      {
        if (above(heap[c], heap[best]))
        {
          best = c;
        }
      }
      if (!above(heap[best], item))
      {
        break;
      }
      heap[k] = heap[best];
      position[heap[k].Id] = static_cast<std::uint32_t>(k);
      k = best;
    }
    heap[k] = item;
    position[item.Id] = static_cast<std::uint32_t>(k);
  };
  for (std::size_t k = (m + 2) / 4 + 1; k-- > 0;)
  {
    if (k < m)
    {
      siftDown(k);
    }
  }
  for (std::size_t k = 0; k < m; ++k)
  {
    position[heap[k].Id] = static_cast<std::uint32_t>(k);
  }
  std::vector<char> removed(m, 0);
  while (heapSize > target)
  {
    const std::uint32_t i = heap[0].Id;
    removed[i] = 1;
    heap[0] = heap[--heapSize];
    position[heap[0].Id] = 0;
    siftDown(0);
    for (std::size_t k = rowStart[i]; k < rowStart[i + 1]; ++k)
    {
      const std::uint32_t j = ids[k];
      if (!removed[j])
      {
        total[j] -= weights[k];
        heap[position[j]].Weight = static_cast<float>(total[j]);
        siftDown(position[j]);
      }
    }
  }
  std::vector<std::uint32_t> kept;
  kept.reserve(target);
  for (std::size_t i = 0; i < m; ++i)
  {
    if (!removed[i])
    {
      kept.push_back(static_cast<std::uint32_t>(i));
    }
  }
  return kept;
}

// One Lloyd step: every site moves to the point of its own restricted cell's
// triangles nearest to the cell's centroid.
bool RelaxOnce(
  const TriangleMesh& surface, SurfaceSamples& samples, const std::function<bool(double)>& progress)
{
  RestrictedVoronoiOptions options;
  options.Progress = progress;
  const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(surface, samples.Points, options);
  if (rvd.Aborted)
  {
    return false;
  }
  const std::size_t ns = samples.Points.size();
  std::vector<Index> first(ns + 1, 0), order(rvd.NumberOfPolygons());
  for (Index s : rvd.PolygonSite)
  {
    ++first[s + 1];
  }
  for (std::size_t i = 0; i < ns; ++i)
  {
    first[i + 1] += first[i];
  }
  {
    std::vector<Index> cursor(first.begin(), first.end() - 1);
    for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
    {
      order[cursor[rvd.PolygonSite[p]]++] = static_cast<Index>(p);
    }
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ns, 1024),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t i = r.begin(); i != r.end(); ++i)
      {
        if (first[i] == first[i + 1])
        {
          continue; // an empty cell (coincident site): stay
        }
        const Point3 c = rvd.CellCentroid[i];
        double best = HUGE_VAL;
        for (Index k = first[i]; k < first[i + 1]; ++k)
        {
          const Index t = rvd.PolygonTriangle[order[k]];
          const Triangle& tri = surface.Triangles[t];
          const Point3 q = ClosestPointOnTriangle(
            c, surface.Points[tri[0]], surface.Points[tri[1]], surface.Points[tri[2]]);
          const double d2 = Distance2(q, c);
          if (d2 < best)
          {
            best = d2;
            samples.Points[i] = q;
            samples.TriangleIds[i] = t;
          }
        }
      }
    });
  return true;
}
}

double IdealSampleSpacing(double area, std::size_t n)
{
  return std::sqrt(2.0 * area / (std::sqrt(3.0) * static_cast<double>(n)));
}

SurfaceSamples SampleSurface(const TriangleMesh& surface, const SamplingOptions& options)
{
  SurfaceSamples samples;
  std::size_t n = options.NumberOfSamples;
  if (n == 0)
  {
    return samples;
  }
  const double area = SurfaceArea(surface);
  if (!(area > 0.0))
  {
    throw std::invalid_argument("cannot sample a surface of zero area");
  }
  auto report = [&options](double f) { return !options.Progress || options.Progress(f); };
  // Elimination takes about as long as one relaxation step.
  const double share = 1.0 / (1.0 + options.RelaxationIterations);

  std::unique_ptr<SizingField> field;
  if (options.Adaptive)
  {
    field = std::make_unique<SizingField>(surface, n, options.Seed, options.Sizing);
    if (!report(0.1 * share))
    {
      samples.Aborted = true;
      return samples;
    }
    samples.AddedSamples = field->ExtraSamples();
    n += samples.AddedSamples;
  }
  const std::size_t m =
    std::max(n, static_cast<std::size_t>(std::ceil(std::max(1.0, options.CandidateRatio) * n)));
  // A field without thin parts samples uniformly: exactly as without it.
  Candidates candidates = field && !field->IsUniform()
    ? AdaptiveCandidates(surface, *field, m, options.Seed)
    : UniformCandidates(surface, m, options.Seed);
  SortSpatially(candidates);
  if (!report(0.3 * share))
  {
    samples.Aborted = true;
    return samples;
  }
  const std::vector<std::uint32_t> kept =
    EliminateSamples(candidates.Points, candidates.Spacing, n, area);
  samples.Points.reserve(n);
  samples.TriangleIds.reserve(n);
  for (std::uint32_t i : kept)
  {
    samples.Points.push_back(candidates.Points[i]);
    samples.TriangleIds.push_back(candidates.Triangles[i]);
  }
  if (!report(share))
  {
    samples = SurfaceSamples();
    samples.Aborted = true;
    return samples;
  }

  for (int it = 0; it < options.RelaxationIterations; ++it)
  {
    const double start = share * (1 + it);
    const bool ok =
      RelaxOnce(surface, samples, [&](double f) { return report(start + share * f); });
    if (!ok)
    {
      samples = SurfaceSamples();
      samples.Aborted = true;
      return samples;
    }
  }

  samples.Normals.resize(samples.Points.size());
  for (std::size_t i = 0; i < samples.Points.size(); ++i)
  {
    samples.Normals[i] = TriangleNormal(surface, samples.TriangleIds[i]);
  }
  if (field)
  {
    samples.LocalThickness.resize(samples.Points.size());
    samples.Spacing.resize(samples.Points.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.Points.size(), 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
        {
          const std::size_t probe = field->NearestProbe(samples.Points[i]);
          samples.LocalThickness[i] = field->Thickness(probe);
          samples.Spacing[i] = field->Spacing(probe);
        }
      });
  }
  report(1.0);
  return samples;
}
}
