// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeletal/SkeletalDiagram.h"

#include "Mesh/TriangleLocator.h"
#include "Skeletal/PrimitiveUnion.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <stdexcept>
#include <tuple>

namespace medialaxis
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

struct Graph
{
  std::vector<std::vector<std::pair<Index, double>>> Neighbours;
};

Graph MedialGraph(const MedialMesh& medial)
{
  Graph graph;
  graph.Neighbours.resize(medial.NumberOfVertices());
  for (const auto& e : AllEdges(medial))
  {
    const double length = Norm(medial.Centers[e[1]] - medial.Centers[e[0]]);
    graph.Neighbours[e[0]].push_back({ e[1], length });
    graph.Neighbours[e[1]].push_back({ e[0], length });
  }
  return graph;
}

// Multi-source Dijkstra along the medial edges: each vertex's nearest
// site (by position in `sites`; ties to the earlier site) and distance.
void NearestSites(const Graph& graph, const std::vector<Index>& sites, std::vector<int>& owner,
  std::vector<double>& distance)
{
  const std::size_t n = graph.Neighbours.size();
  owner.assign(n, -1);
  distance.assign(n, Infinity);
  using Entry = std::tuple<double, int, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t s = 0; s < sites.size(); ++s)
  {
    queue.push({ 0.0, static_cast<int>(s), sites[s] });
  }
  while (!queue.empty())
  {
    const auto [d, site, v] = queue.top();
    queue.pop();
    if (owner[v] >= 0)
    {
      continue;
    }
    owner[v] = site;
    distance[v] = d;
    for (const auto& [w, length] : graph.Neighbours[v])
    {
      if (owner[w] < 0)
      {
        queue.push({ d + length, site, w });
      }
    }
  }
}

// The element of the skeleton a template stands for, as a key of site
// indices (sorted) and its kind: fits are reused while it stays.
using ElementKey = std::pair<int, std::array<Index, 3>>;

struct Fitted
{
  PrimitiveTemplate Template;
  FittedPrimitive Fit;
};

// The distance from each check point to the union of the diagram's
// primitives; sets Error, MeanError and FailedElements and returns the
// farthest point. `exact`: to the boundary of the union, so that a point
// inside a primitive (where the primitive passes the surface) counts by
// its depth (|F| of PrimitiveUnion); otherwise to the nearest primitive
// surface, which is the same outside the primitives, where coverage is
// lacking, and far cheaper (what the insertions go by).
std::size_t MeasureCoverage(SkeletalDiagram& diagram, const std::vector<Point3>& checks, bool exact)
{
  std::vector<TriangleMesh> pieces;
  diagram.FailedElements = 0;
  for (std::size_t e = 0; e < diagram.Primitives.size(); ++e)
  {
    pieces.push_back(PrimitiveSurface(diagram.Templates[e], diagram.Primitives[e]));
    diagram.FailedElements += pieces.back().Triangles.empty() ? 1 : 0;
  }
  std::vector<double> gap(checks.size(), Infinity);
  if (exact)
  {
    const PrimitiveUnion united(pieces);
    if (!united.Empty())
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, checks.size(), 256),
        [&](const tbb::blocked_range<std::size_t>& range)
        {
          for (std::size_t k = range.begin(); k != range.end(); ++k)
          {
            gap[k] = std::abs(united.SignedDistance(checks[k]));
          }
        });
    }
  }
  else
  {
    TriangleMesh all;
    for (const TriangleMesh& piece : pieces)
    {
      const Index offset = static_cast<Index>(all.Points.size());
      all.Points.insert(all.Points.end(), piece.Points.begin(), piece.Points.end());
      for (const Triangle& t : piece.Triangles)
      {
        all.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
      }
    }
    if (!all.Triangles.empty())
    {
      const TriangleLocator nearest(all);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, checks.size(), 256),
        [&](const tbb::blocked_range<std::size_t>& range)
        {
          for (std::size_t k = range.begin(); k != range.end(); ++k)
          {
            gap[k] = nearest.Distance(checks[k]);
          }
        });
    }
  }
  const std::size_t worst =
    static_cast<std::size_t>(std::max_element(gap.begin(), gap.end()) - gap.begin());
  diagram.Error = gap[worst];
  double sum = 0.0;
  for (double g : gap)
  {
    sum += std::isfinite(g) ? g : diagram.Diagonal;
  }
  diagram.MeanError = sum / static_cast<double>(gap.size());
  return worst;
}
}

SkeletalDiagram BuildSkeletalDiagram(
  const TriangleMesh& surface, const MedialMesh& medial, const SkeletalDiagramOptions& options)
{
  const std::size_t n = medial.NumberOfVertices();
  if (n == 0)
  {
    throw std::invalid_argument("skeletal diagram: the medial mesh has no vertex");
  }
  const auto box = BoundingBox(surface.Points);
  const double diagonal = Norm(box.second - box.first);
  const double spacing = options.Spacing * diagonal;
  const double bound = options.MaximumError * diagonal;
  const TriangleLocator locator(surface);
  const Graph graph = MedialGraph(medial);

  // Where coverage is measured: the surface's vertices and centroids.
  std::vector<Point3> checks = surface.Points;
  for (const Triangle& t : surface.Triangles)
  {
    checks.push_back(
      (1.0 / 3.0) * (surface.Points[t[0]] + surface.Points[t[1]] + surface.Points[t[2]]));
  }

  // Initial sites: the largest sphere, then farthest-point selection along
  // the medial edges (an unreachable vertex, on another component, first).
  std::vector<Index> sites;
  sites.push_back(static_cast<Index>(
    std::max_element(medial.Radii.begin(), medial.Radii.end()) - medial.Radii.begin()));
  std::vector<int> owner;
  std::vector<double> distance;
  while (static_cast<int>(sites.size()) < std::min<int>(options.InitialSites, static_cast<int>(n)))
  {
    NearestSites(graph, sites, owner, distance);
    sites.push_back(
      static_cast<Index>(std::max_element(distance.begin(), distance.end()) - distance.begin()));
  }

  std::map<ElementKey, Fitted> cache;
  // The insertions go by smooth fits: exact radii on a template not yet
  // refined follow every long ray (an edge from a neck into a ball), and
  // the chords between them would call for sites the refined primitive
  // does not need.
  PrimitiveFitOptions insertionFit = options.Fit;
  insertionFit.ExactRadii = false;
  auto fitElement = [&](const ElementKey& key)
  {
    Fitted fitted;
    const auto& ids = key.second;
    try
    {
      std::array<Point3, 3> corners{};
      for (int k = 0; k <= key.first; ++k)
      {
        corners[k] = medial.Centers[ids[k]];
      }
      fitted.Template = MakeElementTemplate(static_cast<SkeletalElement>(key.first), corners,
        options.VertexSubdivisions, options.AngularResolution, spacing);
      fitted.Fit = FitPrimitive(surface, locator, fitted.Template, insertionFit);
    }
    catch (const std::invalid_argument& error)
    {
      fitted.Fit.Error = error.what();
    }
    return fitted;
  };

  SkeletalDiagram best;
  for (;;)
  {
    // The skeleton: the dual of the sites' cells on the medial mesh.
    NearestSites(graph, sites, owner, distance);
    SkeletalDiagram current;
    current.Diagonal = diagonal;
    current.Sites = sites;
    current.Insertions =
      static_cast<int>(sites.size()) - std::min<int>(options.InitialSites, static_cast<int>(n));
    for (Index s : sites)
    {
      current.Points.push_back(medial.Centers[s]);
    }
    std::set<std::array<Index, 2>> edges;
    for (const auto& e : AllEdges(medial))
    {
      const int a = owner[e[0]], b = owner[e[1]];
      if (a >= 0 && b >= 0 && a != b)
      {
        edges.insert({ std::min<Index>(a, b), std::max<Index>(a, b) });
      }
    }
    std::set<std::array<Index, 3>> triangles;
    for (const auto& f : medial.Faces)
    {
      std::array<Index, 3> cells = { owner[f[0]], owner[f[1]], owner[f[2]] };
      std::sort(cells.begin(), cells.end());
      if (cells[0] >= 0 && cells[0] != cells[1] && cells[1] != cells[2])
      {
        triangles.insert(cells);
      }
    }
    current.Edges.assign(edges.begin(), edges.end());
    current.Triangles.assign(triangles.begin(), triangles.end());

    // The primitives, new ones fitted in parallel (each on its own, so the
    // result does not depend on the threads).
    std::vector<ElementKey> keys;
    for (std::size_t v = 0; v < sites.size(); ++v)
    {
      keys.push_back({ 0, { sites[v], -1, -1 } });
    }
    for (const auto& e : current.Edges)
    {
      keys.push_back({ 1, { sites[e[0]], sites[e[1]], -1 } });
    }
    for (const auto& t : current.Triangles)
    {
      keys.push_back({ 2, { sites[t[0]], sites[t[1]], sites[t[2]] } });
    }
    std::vector<ElementKey> missing;
    for (const ElementKey& key : keys)
    {
      if (!cache.count(key))
      {
        missing.push_back(key);
      }
    }
    std::vector<Fitted> fresh(missing.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, missing.size(), 1),
      [&](const tbb::blocked_range<std::size_t>& range)
      {
        for (std::size_t k = range.begin(); k != range.end(); ++k)
        {
          fresh[k] = fitElement(missing[k]);
        }
      });
    for (std::size_t k = 0; k < missing.size(); ++k)
    {
      cache.emplace(missing[k], std::move(fresh[k]));
    }
    for (const ElementKey& key : keys)
    {
      const Fitted& fitted = cache.at(key);
      current.Templates.push_back(fitted.Template);
      current.Primitives.push_back(fitted.Fit);
    }
    const std::size_t worst = MeasureCoverage(current, checks, false);

    const bool tooMany = static_cast<int>(current.NumberOfElements()) > options.MaximumElements;
    if (tooMany && !best.Points.empty())
    {
      break; // the last insertion went past the budget: keep the one before
    }
    best = std::move(current);
    if (best.Error <= bound || tooMany || sites.size() == n)
    {
      break;
    }
    if (options.Progress &&
      !options.Progress(std::min(
        1.0, static_cast<double>(best.NumberOfElements()) / std::max(1, options.MaximumElements))))
    {
      best.Aborted = true;
      break;
    }
    // A new site where the surface is farthest from the union: the medial
    // vertex whose sphere comes closest to touching that point.
    const Point3& p = checks[worst];
    Index chosen = -1;
    double closest = Infinity;
    for (std::size_t v = 0; v < n; ++v)
    {
      const double d = std::abs(Norm(p - medial.Centers[v]) - medial.Radii[v]);
      if (d < closest &&
        std::find(sites.begin(), sites.end(), static_cast<Index>(v)) == sites.end())
      {
        closest = d;
        chosen = static_cast<Index>(v);
      }
    }
    if (chosen < 0)
    {
      break;
    }
    sites.push_back(chosen);
  }

  // The primitives of the diagram kept, refined where they pass the
  // surface between their directions (not during the insertions: most of
  // those primitives are dropped again, and the refinement costs several
  // fits), then measured again.
  PrimitiveFitOptions refinement = options.Fit;
  if (refinement.RefinementTolerance <= 0.0)
  {
    refinement.RefinementTolerance = 0.2 * bound;
  }
  if (!best.Aborted)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, best.Primitives.size(), 1),
      [&](const tbb::blocked_range<std::size_t>& range)
      {
        for (std::size_t e = range.begin(); e != range.end(); ++e)
        {
          if (refinement.ExactRadii)
          {
            // The smooth fit has each direction's exit already.
            best.Primitives[e].Radius = best.Primitives[e].MaximumRadius;
          }
          RefinePrimitive(surface, locator, best.Templates[e], best.Primitives[e], refinement);
        }
      });
    MeasureCoverage(best, checks, true);
  }
  return best;
}
std::vector<Point3> ElementPoints(const SkeletalDiagram& diagram, int perEdge)
{
  std::vector<Point3> points = diagram.Points;
  for (const auto& e : diagram.Edges)
  {
    for (int k = 1; k < perEdge; ++k)
    {
      const double t = static_cast<double>(k) / perEdge;
      points.push_back((1.0 - t) * diagram.Points[e[0]] + t * diagram.Points[e[1]]);
    }
  }
  for (const Triangle& f : diagram.Triangles)
  {
    points.push_back(
      (1.0 / 3.0) * (diagram.Points[f[0]] + diagram.Points[f[1]] + diagram.Points[f[2]]));
  }
  return points;
}
}
