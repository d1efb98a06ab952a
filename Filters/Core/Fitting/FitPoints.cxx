// SPDX-License-Identifier: GPL-3.0-or-later
#include "Fitting/FitPoints.h"

#include "Geometry/MortonOrder.h"
#include "Geometry/Vec3.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace medialaxis
{
namespace
{
/// The distinct vertices of the polygons [first, last) (one surface
/// triangle) into out.Surface with `dense` and, with `corners`, those that three or more
/// polygons share into out.Points. Equal means within `tolerance`, since each
/// polygon is clipped on its own. Sorted by x, each vertex is compared with
/// those within the tolerance in x only (large triangles of CAD meshes hold
/// thousands of polygons).
void TriangleVertices(const RestrictedVoronoiDiagram& rvd, const std::vector<double>& area,
  std::size_t first, std::size_t last, double tolerance, bool corners, bool dense, FitTarget& out)
{
  std::vector<std::pair<Point3, Index>> vertices; // position, site
  for (std::size_t p = first; p < last; ++p)
  {
    for (Index k = rvd.Offsets[p]; k < rvd.Offsets[p + 1]; ++k)
    {
      vertices.emplace_back(rvd.Vertices[k], rvd.PolygonSite[p]);
    }
  }
  std::sort(vertices.begin(), vertices.end());
  const double tolerance2 = tolerance * tolerance;
  std::vector<char> taken(vertices.size(), 0);
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    if (taken[i])
    {
      continue;
    }
    if (dense)
    {
      out.Surface.push_back(vertices[i].first);
    }
    Index cells[3] = { vertices[i].second, -1, -1 };
    int count = 1;
    for (std::size_t j = i + 1;
         j < vertices.size() && vertices[j].first[0] - vertices[i].first[0] <= tolerance; ++j)
    {
      if (!taken[j] && Distance2(vertices[i].first, vertices[j].first) <= tolerance2)
      {
        taken[j] = 1;
        if (count < 3 && vertices[j].second != cells[0] && vertices[j].second != cells[1])
        {
          cells[count++] = vertices[j].second;
        }
      }
    }
    if (corners && count == 3)
    {
      out.Points.push_back(vertices[i].first);
      out.Weights.push_back((area[cells[0]] + area[cells[1]] + area[cells[2]]) / 12.0);
    }
  }
}
}

FitTarget FitPoints(const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const FitPointsOptions& options)
{
  std::vector<double> area(sites.size(), 0.0);
  for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
  {
    const Point3& a = rvd.Vertices[rvd.Offsets[p]];
    for (Index k = rvd.Offsets[p] + 1; k + 1 < rvd.Offsets[p + 1]; ++k)
    {
      area[rvd.PolygonSite[p]] += 0.5 * Norm(Cross(rvd.Vertices[k] - a, rvd.Vertices[k + 1] - a));
    }
  }
  FitTarget out;
  out.Points = sites;
  out.Weights.resize(sites.size());
  // Corners need the polygons' triangles (absent: the sites alone, and every
  // polygon vertex as the dense surface).
  const bool triangles = rvd.PolygonTriangle.size() == rvd.NumberOfPolygons();
  const bool corners = options.Corners && triangles && !rvd.Vertices.empty();
  const bool dense = options.DenseSurface;
  if (dense)
  {
    out.Surface = sites;
  }
  for (std::size_t s = 0; s < sites.size(); ++s)
  {
    // Without corners a site stands for its whole cell.
    out.Weights[s] = (corners ? 0.5 : 1.0) * area[s];
  }
  if (!corners && !dense)
  {
    return out;
  }
  if (!triangles)
  {
    out.Surface.insert(out.Surface.end(), rvd.Vertices.begin(), rvd.Vertices.end());
    return out;
  }
  const auto [lo, hi] = BoundingBox(rvd.Vertices);
  const double tolerance = 1e-9 * std::sqrt(Distance2(lo, hi));
  // Chunks of about 4,096 polygons that end at a triangle's last polygon,
  // searched in parallel and joined in order (the same at any thread count).
  std::vector<std::size_t> starts{ 0 };
  const std::size_t np = rvd.NumberOfPolygons();
  for (std::size_t p = 4096; p < np; p += 4096)
  {
    while (p < np && rvd.PolygonTriangle[p] == rvd.PolygonTriangle[p - 1])
    {
      ++p;
    }
    if (p < np && p > starts.back())
    {
      starts.push_back(p);
    }
  }
  starts.push_back(np);
  std::vector<FitTarget> chunks(starts.size() - 1);
  tbb::parallel_for(std::size_t(0), chunks.size(),
    [&](std::size_t c)
    {
      for (std::size_t first = starts[c]; first < starts[c + 1];)
      {
        std::size_t last = first + 1;
        while (last < starts[c + 1] && rvd.PolygonTriangle[last] == rvd.PolygonTriangle[first])
        {
          ++last;
        }
        TriangleVertices(rvd, area, first, last, tolerance, corners, dense, chunks[c]);
        first = last;
      }
    });
  for (const FitTarget& chunk : chunks)
  {
    out.Points.insert(out.Points.end(), chunk.Points.begin(), chunk.Points.end());
    out.Weights.insert(out.Weights.end(), chunk.Weights.begin(), chunk.Weights.end());
    out.Surface.insert(out.Surface.end(), chunk.Surface.begin(), chunk.Surface.end());
  }
  // In space-filling-curve order: consecutive distance queries then share
  // their nearest primitives (warm starts).
  const std::vector<std::uint32_t> order =
    MortonOrder(out.Points.size(), [&](std::size_t i) { return out.Points[i]; });
  FitTarget sorted;
  sorted.Surface = std::move(out.Surface);
  sorted.Points.reserve(order.size());
  sorted.Weights.reserve(order.size());
  for (std::uint32_t i : order)
  {
    sorted.Points.push_back(out.Points[i]);
    sorted.Weights.push_back(out.Weights[i]);
  }
  return sorted;
}
}
