// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeletal/SkeletalDiagram.h"

#include "Mesh/TriangleLocator.h"
#include "Skeletal/DualSkeleton.h"
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

// The element (or edge piece) a template stands for, as its kind and the
// medial vertices of its corners: fits are reused while it stays.
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
  std::set<Index> failed;
  for (std::size_t k = 0; k < diagram.Primitives.size(); ++k)
  {
    pieces.push_back(PrimitiveSurface(diagram.Templates[k], diagram.Primitives[k]));
    if (pieces.back().Triangles.empty())
    {
      failed.insert(diagram.PieceElement[k]);
    }
  }
  diagram.FailedElements = static_cast<int>(failed.size());
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
  const MedialGraph graph = BuildMedialGraph(medial);

  // Where coverage is measured: the surface's vertices and centroids.
  std::vector<Point3> checks = surface.Points;
  for (const Triangle& t : surface.Triangles)
  {
    checks.push_back(
      (1.0 / 3.0) * (surface.Points[t[0]] + surface.Points[t[1]] + surface.Points[t[2]]));
  }

  // Sites, and the bends of edges, are medial vertices inside the surface
  // (a simplified medial mesh may stray outside it in thin parts, where no
  // primitive can be fitted). If none is, all are candidates, and their
  // primitives fail and are counted.
  std::vector<std::uint8_t> inside(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t v = range.begin(); v != range.end(); ++v)
      {
        inside[v] = locator.Inside(medial.Centers[v]) ? 1 : 0;
      }
    });
  if (std::find(inside.begin(), inside.end(), 1) == inside.end())
  {
    std::fill(inside.begin(), inside.end(), 1);
  }
  // The candidate with the largest value (the first on a tie).
  auto largestInside = [&](const std::vector<double>& value)
  {
    Index best = -1;
    for (std::size_t v = 0; v < n; ++v)
    {
      if (inside[v] && (best < 0 || value[v] > value[best]))
      {
        best = static_cast<Index>(v);
      }
    }
    return best;
  };

  // Initial sites: the largest sphere, then farthest-point selection along
  // the medial edges (an unreachable vertex, on another component, first).
  std::vector<Index> sites = { largestInside(medial.Radii) };
  while (static_cast<int>(sites.size()) < std::min<int>(options.InitialSites, static_cast<int>(n)))
  {
    const Index farthest = largestInside(NearestSites(graph, sites).Distance);
    if (std::find(sites.begin(), sites.end(), farthest) != sites.end())
    {
      break; // every candidate is a site
    }
    sites.push_back(farthest);
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
    const DualSkeleton dual =
      BuildDualSkeleton(medial, locator, inside, sites, NearestSites(graph, sites));
    SkeletalDiagram current;
    current.Diagonal = diagonal;
    current.Sites = sites;
    current.Insertions =
      static_cast<int>(sites.size()) - std::min<int>(options.InitialSites, static_cast<int>(n));
    for (Index s : sites)
    {
      current.Points.push_back(medial.Centers[s]);
    }
    current.Edges = dual.Edges;
    for (const std::vector<Index>& route : dual.Routes)
    {
      current.EdgeBends.emplace_back(route.begin() + 1, route.end() - 1);
      std::vector<Point3>& points = current.EdgeBendPoints.emplace_back();
      for (Index v : current.EdgeBends.back())
      {
        points.push_back(medial.Centers[v]);
      }
    }

    // The primitives' keys: a vertex, each straight piece of an edge, a
    // triangle; new ones fitted in parallel (each on its own, so the result
    // does not depend on the threads).
    std::vector<ElementKey> keys;
    std::vector<Index> element;
    for (std::size_t v = 0; v < sites.size(); ++v)
    {
      keys.push_back({ 0, { sites[v], -1, -1 } });
      element.push_back(static_cast<Index>(v));
    }
    for (std::size_t e = 0; e < dual.Routes.size(); ++e)
    {
      const std::vector<Index>& route = dual.Routes[e];
      for (std::size_t k = 0; k + 1 < route.size(); ++k)
      {
        keys.push_back({ 1, { route[k], route[k + 1], -1 } });
        element.push_back(static_cast<Index>(sites.size() + e));
      }
    }
    for (const auto& t : dual.Triangles)
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
    // A triangle whose flat face leaves the surface has no primitive and
    // is left out (its sides stay; the insertions cover what it would
    // have).
    for (std::size_t k = 0; k < keys.size(); ++k)
    {
      const Fitted& fitted = cache.at(keys[k]);
      if (keys[k].first == 2)
      {
        const auto& t = dual.Triangles[k - element.size()];
        if (fitted.Fit.Radius.empty())
        {
          ++current.OmittedTriangles;
          continue;
        }
        current.PieceElement.push_back(
          static_cast<Index>(sites.size() + dual.Edges.size() + current.Triangles.size()));
        current.Triangles.push_back({ t[0], t[1], t[2] });
      }
      else
      {
        current.PieceElement.push_back(element[k]);
      }
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
      if (d < closest && inside[v] &&
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
  for (std::size_t e = 0; e < diagram.Edges.size(); ++e)
  {
    const std::vector<Point3> line = diagram.EdgePolyline(e);
    for (std::size_t piece = 0; piece + 1 < line.size(); ++piece)
    {
      if (piece > 0)
      {
        points.push_back(line[piece]);
      }
      for (int k = 1; k < perEdge; ++k)
      {
        const double t = static_cast<double>(k) / perEdge;
        points.push_back((1.0 - t) * line[piece] + t * line[piece + 1]);
      }
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
