// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeleton/CurveSkeleton.h"

#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Skeleton/MedialThinning.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace medialaxis
{
namespace
{
double BoxDiagonal(const TriangleMesh& surface)
{
  if (surface.Points.empty())
  {
    return 0.0;
  }
  const auto [lo, hi] = BoundingBox(surface.Points);
  return std::sqrt(Distance2(lo, hi));
}

// `point` if it lies inside the solid; else the nearest of `members`' centres
// inside; else the surface point nearest to `point`, moved `inset` inwards.
Point3 PlaceInside(const Point3& point, const std::vector<Index>& members, const MedialMesh& medial,
  const TriangleLocator& locator, double inset)
{
  if (locator.Inside(point))
  {
    return point;
  }
  Index best = -1;
  for (Index m : members)
  {
    if ((best < 0 ||
          Distance2(medial.Centers[m], point) < Distance2(medial.Centers[best], point)) &&
      locator.Inside(medial.Centers[m]))
    {
      best = m;
    }
  }
  if (best >= 0)
  {
    return medial.Centers[best];
  }
  const TriangleLocator::ClosestHit hit = locator.Closest(point, [](Index) { return true; });
  const Point3 inward = hit.Point - point;
  const double length = Norm(inward);
  if (hit.Triangle < 0 || !(length > 0.0))
  {
    return point;
  }
  const Point3 moved = hit.Point + (inset / length) * inward;
  return locator.Inside(moved) ? moved : point;
}

// Why `medial` cannot be the medial mesh of `surface` (see
// CheckMedialMeshOfSurface), or empty.
std::string MedialMeshProblem(
  const MedialMesh& medial, const TriangleMesh& surface, const TriangleLocator& locator)
{
  if (medial.NumberOfVertices() == 0)
  {
    return "the medial mesh is empty";
  }
  const double diagonal = BoxDiagonal(surface);
  // Up to 256 vertices spread over the mesh.
  const std::size_t nv = medial.NumberOfVertices(), step = std::max<std::size_t>(1, nv / 256);
  std::size_t tested = 0, outside = 0;
  std::vector<double> mismatch;
  for (std::size_t v = 0; v < nv; v += step)
  {
    ++tested;
    // Zero-radius spheres stand for sharp edges: they lie on the surface, up
    // to the chords a simplified mesh draws along curved edges.
    const double distance = locator.Distance(medial.Centers[v]);
    if (medial.Radii[v] > 1e-9 * diagonal && !locator.Inside(medial.Centers[v]))
    {
      ++outside;
    }
    mismatch.push_back(std::abs(distance - medial.Radii[v]));
  }
  if (10 * outside > tested)
  {
    return std::to_string(outside) + " of " + std::to_string(tested) +
      " sampled medial centres lie outside the surface: connect the medial mesh computed from "
      "this surface";
  }
  std::nth_element(mismatch.begin(), mismatch.begin() + mismatch.size() / 2, mismatch.end());
  if (mismatch[mismatch.size() / 2] > 0.05 * diagonal)
  {
    return "the medial radii do not match the centres' distances to the surface (median "
           "difference " +
      std::to_string(100.0 * mismatch[mismatch.size() / 2] / diagonal) +
      "% of the diagonal): connect the medial mesh computed from this surface";
  }
  return "";
}

// The thinned graph while its spurs are pruned and its nodes smoothed.
struct WorkGraph
{
  std::vector<Point3> Position;
  std::vector<std::vector<Index>> Adjacent; // sorted
  std::vector<char> Alive;
  std::vector<Index> PrunedInto; // -1: still there
  // Nodes that were junctions: a branch pruned there leaves the rest of the
  // skeleton's shape, so later branches still end there.
  std::vector<char> WasJunction;

  std::size_t Degree(Index v) const { return this->Adjacent[v].size(); }

  void Unlink(Index a, Index b)
  {
    auto& la = this->Adjacent[a];
    la.erase(std::remove(la.begin(), la.end(), b), la.end());
    auto& lb = this->Adjacent[b];
    lb.erase(std::remove(lb.begin(), lb.end(), a), lb.end());
  }

  // From a node of degree 1 along nodes of degree 2 to the first other
  // node; the path includes both ends.
  double Walk(Index leaf, std::vector<Index>& path) const
  {
    path.assign(1, leaf);
    double length = 0.0;
    Index previous = -1, current = leaf;
    while (true)
    {
      const auto& next = this->Adjacent[current];
      const Index step = next[0] != previous ? next[0] : next[1];
      length += std::sqrt(Distance2(this->Position[current], this->Position[step]));
      path.push_back(step);
      previous = current;
      current = step;
      if (this->Degree(current) != 2 || this->WasJunction[current] || current == leaf)
      {
        return length;
      }
    }
  }
};

// Prunes the branches from a free end to a junction whose medial balls all
// lie inside medial balls of the rest of the skeleton grown by `scale`, pass
// after pass (a pass tests each branch against the nodes on no branch of
// that pass), until none is left; a pruned node's medial vertices join the
// junction's. Returns how many branches went.
std::size_t PruneSpurs(
  WorkGraph& g, std::vector<std::vector<Index>>& members, const MedialMesh& medial, double scale)
{
  std::size_t pruned = 0;
  std::vector<Index> path;
  std::vector<std::pair<std::uint32_t, double>> near;
  for (bool changed = true; changed;)
  {
    changed = false;
    std::vector<std::vector<Index>> spurs; // leaf ... junction
    std::vector<char> onSpur(g.Alive.size(), 0);
    for (std::size_t v = 0; v < g.Alive.size(); ++v)
    {
      if (g.Alive[v] && g.Degree(static_cast<Index>(v)) >= 3)
      {
        g.WasJunction[v] = 1;
      }
    }
    for (std::size_t v = 0; v < g.Alive.size(); ++v)
    {
      if (g.Alive[v] && g.Degree(static_cast<Index>(v)) == 1)
      {
        g.Walk(static_cast<Index>(v), path);
        if (path.back() != static_cast<Index>(v) && g.WasJunction[path.back()] &&
          g.Degree(path.back()) >= 2)
        {
          for (std::size_t i = 0; i + 1 < path.size(); ++i)
          {
            onSpur[path[i]] = 1;
          }
          spurs.push_back(path);
        }
      }
    }
    // The medial balls of the nodes on no branch.
    std::vector<Point3> core;
    std::vector<double> coreRadius;
    double largest = 0.0;
    for (std::size_t v = 0; v < g.Alive.size(); ++v)
    {
      if (g.Alive[v] && !onSpur[v])
      {
        for (Index m : members[v])
        {
          core.push_back(medial.Centers[m]);
          coreRadius.push_back(medial.Radii[m]);
          largest = std::max(largest, medial.Radii[m]);
        }
      }
    }
    if (spurs.empty() || core.empty())
    {
      break;
    }
    const KdTree tree(core);
    const auto covered = [&](Index m)
    {
      const Point3& c = medial.Centers[m];
      const double r = medial.Radii[m], reach = scale * largest - r;
      if (reach < 0.0)
      {
        return false;
      }
      tree.WithinRadius(c, reach, near, false);
      for (const auto& [k, d2] : near)
      {
        if (std::sqrt(d2) + r <= scale * coreRadius[k])
        {
          return true;
        }
      }
      return false;
    };
    for (const auto& spur : spurs)
    {
      const bool bump = std::all_of(spur.begin(), spur.end() - 1,
        [&](Index v) { return std::all_of(members[v].begin(), members[v].end(), covered); });
      if (!bump)
      {
        continue;
      }
      const Index junction = spur.back();
      for (std::size_t i = 0; i + 1 < spur.size(); ++i)
      {
        g.Unlink(spur[i], spur[i + 1]);
        g.Alive[spur[i]] = 0;
        g.PrunedInto[spur[i]] = junction;
        members[junction].insert(
          members[junction].end(), members[spur[i]].begin(), members[spur[i]].end());
        std::vector<Index>().swap(members[spur[i]]);
      }
      ++pruned;
      changed = true;
    }
  }
  return pruned;
}

// Jacobi passes of Laplacian smoothing over the nodes of degree 2; a move
// that would leave the solid is not made.
void Smooth(WorkGraph& g, const TriangleLocator& locator, int iterations)
{
  for (int it = 0; it < iterations; ++it)
  {
    std::vector<Point3> next = g.Position;
    for (std::size_t v = 0; v < g.Alive.size(); ++v)
    {
      if (!g.Alive[v] || g.Degree(static_cast<Index>(v)) != 2)
      {
        continue;
      }
      const auto& n = g.Adjacent[v];
      const Point3 target = 0.5 * g.Position[v] + 0.25 * (g.Position[n[0]] + g.Position[n[1]]);
      if (locator.Inside(target))
      {
        next[v] = target;
      }
    }
    g.Position.swap(next);
  }
}

// From `start`, steps along `heading` while the surface point nearest to
// the next position lies more than 45 degrees off the heading (beside it,
// as in a tube, not ahead, as at its end), the distance to the surface
// stays above a quarter of its first value (the same limb, not a thin rim
// approached at a slant) and the step crosses no triangle. Inside a limb
// whose end the medial mesh does not reach (a simplified one stops short
// of thin tips), the march ends near the centre of the ball that touches
// the tip. Steps are a quarter of the distance to the surface, halved on
// refusal down to 1/64 of it; at most four radii of `start` are gone, as
// a straight march leaves the centre of a curling limb.
Point3 MarchToTip(const Point3& start, const Point3& heading, const TriangleLocator& locator)
{
  const auto nearest = [&](const Point3& p)
  { return locator.Closest(p, [](Index) { return true; }); };
  TriangleLocator::ClosestHit hit = nearest(start);
  const double radius = std::sqrt(hit.Distance2);
  Point3 position = start;
  double travelled = 0.0, fraction = 0.25;
  while (hit.Triangle >= 0 && travelled < 4.0 * radius && fraction >= 1.0 / 64.0)
  {
    const double step = fraction * std::sqrt(hit.Distance2);
    const Point3 next = position + step * heading;
    const TriangleLocator::ClosestHit ahead = nearest(next);
    const Point3 toSurface = ahead.Point - next;
    const double reach = Norm(toSurface);
    if (ahead.Triangle < 0 || !(reach >= 0.25 * radius) || !(reach > 0.0) ||
      Dot(toSurface, heading) > std::sqrt(0.5) * reach ||
      locator.FirstHit(position, heading, 0.0, step).Triangle >= 0)
    {
      fraction *= 0.5;
      continue;
    }
    position = next;
    hit = ahead;
    travelled += step;
  }
  return position;
}

// Each free end reaches on along the medial mesh to the farthest medial
// vertex ahead of it in the direction of the branch's last step: thinning
// and pruning stop short of a limb's end (by about the limb's width where
// it is flat, as an ear). The vertices followed are linked by medial edges
// to the end's own and lie ahead of it, within 30 degrees of that
// direction (widened by a quarter of the end's radius): the sheets of a
// rim or a corner, which spread sideways at 45 degrees or more, are not
// followed. The straight step there must stay inside the solid. From there
// (or from the end, where no vertex is ahead) it marches on to the tip
// (MarchToTip), which a simplified medial mesh stops short of.
void ExtendEnds(WorkGraph& g, const std::vector<std::vector<Index>>& members,
  const MedialMesh& medial, const TriangleLocator& locator)
{
  const std::size_t nm = medial.NumberOfVertices();
  const MedialAdjacency adjacency = VertexAdjacency(medial);
  const double cone = std::tan(30.0 * 3.14159265358979323846 / 180.0);
  std::vector<char> seen(nm, 0);
  std::vector<Index> queue, touched;
  const std::size_t n = g.Alive.size();
  for (std::size_t v = 0; v < n; ++v)
  {
    if (!g.Alive[v] || g.Degree(static_cast<Index>(v)) != 1)
    {
      continue;
    }
    const Point3 origin = g.Position[v];
    const Point3 step = origin - g.Position[g.Adjacent[v][0]];
    const double length = Norm(step);
    if (!(length > 0.0))
    {
      continue;
    }
    const Point3 direction = (1.0 / length) * step;
    const double radius = locator.Distance(origin);
    const auto ahead = [&](Index m, double& t)
    {
      const Point3 offset = medial.Centers[m] - origin;
      t = Dot(offset, direction);
      const double aside = std::sqrt(std::max(0.0, Dot(offset, offset) - t * t));
      return t > 0.0 && aside <= 0.25 * radius + cone * t;
    };
    double farthest = 1e-3 * radius;
    Index reach = -1;
    queue.clear();
    touched.clear();
    for (Index m : members[v])
    {
      if (!seen[m])
      {
        seen[m] = 1;
        touched.push_back(m);
        queue.push_back(m);
      }
    }
    for (std::size_t q = 0; q < queue.size(); ++q)
    {
      const Index m = queue[q];
      double t;
      if (ahead(m, t) && t > farthest && medial.Radii[m] > 0.0)
      {
        farthest = t;
        reach = m;
      }
      for (Index k = adjacency.Start[m]; k < adjacency.Start[m + 1]; ++k)
      {
        const Index o = adjacency.Next[k];
        if (!seen[o] && ahead(o, t))
        {
          seen[o] = 1;
          touched.push_back(o);
          queue.push_back(o);
        }
      }
    }
    for (Index m : touched)
    {
      seen[m] = 0;
    }
    Point3 target = origin, heading = direction;
    if (reach >= 0 && locator.Inside(medial.Centers[reach]))
    {
      const Point3 towards = medial.Centers[reach] - origin;
      const double span = Norm(towards);
      if (locator.FirstHit(origin, (1.0 / span) * towards, 0.0, span).Triangle < 0)
      {
        target = medial.Centers[reach];
        heading = Normalized(target - g.Position[g.Adjacent[v][0]]);
      }
    }
    target = MarchToTip(target, heading, locator);
    if (!(Distance2(target, origin) > 0.0))
    {
      continue;
    }
    const Index added = static_cast<Index>(g.Position.size());
    g.Position.push_back(target);
    g.Adjacent.push_back({ static_cast<Index>(v) });
    g.Adjacent[v].push_back(added);
    std::sort(g.Adjacent[v].begin(), g.Adjacent[v].end());
    g.Alive.push_back(1);
    g.PrunedInto.push_back(-1);
    g.WasJunction.push_back(0);
  }
}

// Edges longer than `spacing` times the larger distance to the surface at
// their ends (and than `shortest`) are split evenly, where every new node
// lies inside the solid: nodes then stand about that far apart, so that
// each one's share of the surface is local.
void Resample(WorkGraph& g, const TriangleLocator& locator, double spacing, double shortest)
{
  if (!(spacing > 0.0))
  {
    return;
  }
  std::vector<std::array<Index, 2>> edges;
  for (std::size_t a = 0; a < g.Alive.size(); ++a)
  {
    for (Index b : g.Adjacent[a])
    {
      if (static_cast<Index>(a) < b)
      {
        edges.push_back({ static_cast<Index>(a), b });
      }
    }
  }
  std::vector<Point3> inner;
  for (const auto& [a, b] : edges)
  {
    const Point3 pa = g.Position[a], pb = g.Position[b];
    const double step =
      std::max(shortest, spacing * std::max(locator.Distance(pa), locator.Distance(pb)));
    const double length = std::sqrt(Distance2(pa, pb));
    if (!(step > 0.0) || length <= step)
    {
      continue;
    }
    const int pieces = static_cast<int>(std::ceil(length / step));
    inner.clear();
    for (int k = 1; k < pieces; ++k)
    {
      const double t = static_cast<double>(k) / pieces;
      inner.push_back((1.0 - t) * pa + t * pb);
    }
    if (!std::all_of(
          inner.begin(), inner.end(), [&](const Point3& p) { return locator.Inside(p); }))
    {
      continue;
    }
    g.Unlink(a, b);
    Index previous = a;
    for (const Point3& p : inner)
    {
      const Index added = static_cast<Index>(g.Position.size());
      g.Position.push_back(p);
      g.Adjacent.push_back({ previous });
      g.Adjacent[previous].push_back(added);
      g.Alive.push_back(1);
      g.PrunedInto.push_back(-1);
      g.WasJunction.push_back(0);
      previous = added;
    }
    g.Adjacent[previous].push_back(b);
    g.Adjacent[b].push_back(previous);
  }
  for (auto& list : g.Adjacent)
  {
    std::sort(list.begin(), list.end());
  }
}

// Branches: chains between nodes of degree other than 2, then the loops
// through none, then lone nodes.
void TraceBranches(CurveSkeleton& s)
{
  const std::size_t n = s.Nodes.size();
  std::vector<std::vector<std::pair<Index, Index>>> incident(n); // (other node, edge)
  for (std::size_t e = 0; e < s.Edges.size(); ++e)
  {
    incident[s.Edges[e][0]].emplace_back(s.Edges[e][1], static_cast<Index>(e));
    incident[s.Edges[e][1]].emplace_back(s.Edges[e][0], static_cast<Index>(e));
  }
  std::vector<char> used(s.Edges.size(), 0);
  const auto trace = [&](Index start, std::pair<Index, Index> first)
  {
    std::vector<Index> chain{ start };
    Index current = start;
    auto step = first;
    while (true)
    {
      used[step.second] = 1;
      current = step.first;
      chain.push_back(current);
      if (incident[current].size() != 2 || current == start)
      {
        break;
      }
      step =
        incident[current][0].second == step.second ? incident[current][1] : incident[current][0];
    }
    s.Branches.push_back(std::move(chain));
  };
  for (int pass = 0; pass < 2; ++pass)
  {
    for (std::size_t v = 0; v < n; ++v)
    {
      if ((pass == 0) == (incident[v].size() != 2))
      {
        for (const auto& step : incident[v])
        {
          if (!used[step.second])
          {
            trace(static_cast<Index>(v), step);
          }
        }
      }
    }
  }
  for (std::size_t v = 0; v < n; ++v)
  {
    if (incident[v].empty())
    {
      s.Branches.push_back({ static_cast<Index>(v) });
    }
  }
  std::vector<double> length(s.Branches.size(), 0.0);
  for (std::size_t b = 0; b < s.Branches.size(); ++b)
  {
    for (std::size_t i = 0; i + 1 < s.Branches[b].size(); ++i)
    {
      length[b] += std::sqrt(Distance2(s.Nodes[s.Branches[b][i]], s.Nodes[s.Branches[b][i + 1]]));
    }
  }
  s.NodeBranch.assign(n, -1);
  for (std::size_t b = 0; b < s.Branches.size(); ++b)
  {
    for (Index v : s.Branches[b])
    {
      Index& mine = s.NodeBranch[v];
      if (mine < 0 || length[b] > length[mine])
      {
        mine = static_cast<Index>(b);
      }
    }
  }
  s.Types.resize(n);
  for (std::size_t v = 0; v < n; ++v)
  {
    const std::size_t degree = incident[v].size();
    s.Types[v] = degree <= 1
      ? SkeletonNodeType::End
      : (degree == 2 ? SkeletonNodeType::Regular : SkeletonNodeType::Junction);
  }
}
}

CurveSkeleton ComputeCurveSkeleton(
  const MedialMesh& medial, const TriangleMesh& surface, const CurveSkeletonOptions& options)
{
  CurveSkeleton out;
  const TriangleLocator locator(surface);
  out.Problem = MedialMeshProblem(medial, surface, locator);
  if (!out.Problem.empty())
  {
    return out;
  }
  const auto report = [&](double f) { return !options.Progress || options.Progress(f); };
  const ThinnedGraph thin = ThinMedialMesh(medial, [&](double f) { return report(0.7 * f); });
  if (thin.Aborted || !report(0.7))
  {
    out.Aborted = true;
    return out;
  }
  out.UncollapsedTriangles = thin.UncollapsedTriangles;

  // Each node at its medial vertices' centroid; where that lies outside the
  // solid, at the nearest of them inside, or else (a medial vertex a fit
  // left just outside) just inside the surface point nearest to it.
  const std::size_t n = thin.Centroid.size();
  WorkGraph g;
  g.Position = thin.Centroid;
  std::vector<std::vector<Index>> members(n);
  for (std::size_t v = 0; v < medial.NumberOfVertices(); ++v)
  {
    members[thin.VertexOf[v]].push_back(static_cast<Index>(v));
  }
  const double inset = 1e-4 * BoxDiagonal(surface);
  for (std::size_t i = 0; i < n; ++i)
  {
    g.Position[i] = PlaceInside(thin.Centroid[i], members[i], medial, locator, inset);
  }
  g.Adjacent.assign(n, {});
  for (const auto& e : thin.Edges)
  {
    g.Adjacent[e[0]].push_back(e[1]);
    g.Adjacent[e[1]].push_back(e[0]);
  }
  g.Alive.assign(n, 1);
  g.PrunedInto.assign(n, -1);
  g.WasJunction.assign(n, 0);
  out.PrunedBranches = PruneSpurs(g, members, medial, options.PruneScale);
  if (!report(0.85))
  {
    out.Aborted = true;
    return out;
  }
  Smooth(g, locator, options.SmoothingIterations);

  ExtendEnds(g, members, medial, locator);
  // (Not closer than 1% of the diagonal: thin tentacles would get thousands.)
  Resample(g, locator, options.NodeSpacing, 0.01 * BoxDiagonal(surface));

  // The nodes left, renumbered in order.
  const std::size_t total = g.Alive.size();
  std::vector<Index> id(total, -1);
  for (std::size_t i = 0; i < total; ++i)
  {
    if (g.Alive[i])
    {
      id[i] = static_cast<Index>(out.Nodes.size());
      out.Nodes.push_back(g.Position[i]);
      out.Radii.push_back(locator.Distance(g.Position[i]));
    }
  }
  DisjointSets pieces(out.Nodes.size());
  for (std::size_t i = 0; i < total; ++i)
  {
    for (Index j : g.Adjacent[i])
    {
      if (static_cast<Index>(i) < j)
      {
        out.Edges.push_back({ id[i], id[j] });
        pieces.Union(id[i], id[j]);
      }
    }
  }
  for (std::size_t i = 0; i < out.Nodes.size(); ++i)
  {
    out.Components += pieces.Find(static_cast<Index>(i)) == static_cast<Index>(i) ? 1 : 0;
  }
  out.CycleRank = out.Edges.size() + out.Components - out.Nodes.size();
  out.MedialVertexNode.resize(medial.NumberOfVertices());
  for (std::size_t v = 0; v < medial.NumberOfVertices(); ++v)
  {
    Index node = thin.VertexOf[v];
    while (g.PrunedInto[node] >= 0)
    {
      node = g.PrunedInto[node];
    }
    out.MedialVertexNode[v] = id[node];
  }
  TraceBranches(out);
  report(1.0);
  return out;
}

std::vector<Index> SegmentSurface(const CurveSkeleton& skeleton, const TriangleMesh& surface)
{
  std::vector<Index> node(surface.Points.size(), -1);
  if (skeleton.Nodes.empty())
  {
    return node;
  }
  // The node whose ball (radius: its distance to the surface) comes nearest
  // to the point, among the 16 nearest nodes: a ball touches the surface
  // where the node stands for it.
  const KdTree tree(skeleton.Nodes);
  std::vector<std::uint32_t> ids;
  std::vector<double> d2;
  for (std::size_t p = 0; p < surface.Points.size(); ++p)
  {
    tree.Nearest(surface.Points[p], 16, ids, d2);
    double best = HUGE_VAL;
    for (std::size_t k = 0; k < ids.size(); ++k)
    {
      const double gap = std::sqrt(d2[k]) - skeleton.Radii[ids[k]];
      if (gap < best || (gap == best && static_cast<Index>(ids[k]) < node[p]))
      {
        best = gap;
        node[p] = static_cast<Index>(ids[k]);
      }
    }
  }
  return node;
}

std::string CheckMedialMeshOfSurface(const MedialMesh& medial, const TriangleMesh& surface)
{
  return MedialMeshProblem(medial, surface, TriangleLocator(surface));
}
}
