// SPDX-License-Identifier: GPL-3.0-or-later
#include "Fillets/CentreLineGraph.h"

#include "Geometry/Vec3.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>

namespace medialaxis
{
namespace
{
using Edge = std::array<Index, 2>;

struct Geometry
{
  const std::vector<Point3>& Centres;
  const std::vector<double>& Radii;
  double Length(const Edge& e) const { return Norm(this->Centres[e[1]] - this->Centres[e[0]]); }
};

// Edge ids at each vertex.
std::vector<std::vector<Index>> Incidence(const std::vector<Edge>& edges, std::size_t vertices)
{
  std::vector<std::vector<Index>> incident(vertices);
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    incident[edges[e][0]].push_back(static_cast<Index>(e));
    incident[edges[e][1]].push_back(static_cast<Index>(e));
  }
  return incident;
}

Index Other(const Edge& e, Index v)
{
  return e[0] == v ? e[1] : e[0];
}

std::vector<Edge> Keep(const std::vector<Edge>& edges, const std::vector<std::uint8_t>& removed)
{
  std::vector<Edge> kept;
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    if (!removed[e])
    {
      kept.push_back(edges[e]);
    }
  }
  return kept;
}

// Snaps the graph to a scale of `radii` ball radii: vertices are taken by
// decreasing degree, then id, each unclaimed one claims the unclaimed vertices within that
// distance, and edges are mapped to the claiming vertices. Fins running side
// by side along a line collapse into one path; cluster diameters stay
// bounded (no chaining along the line).
std::vector<Edge> SnapToScale(const std::vector<Edge>& edges, const Geometry& g, double radii)
{
  std::vector<Index> used;
  for (const Edge& e : edges)
  {
    used.push_back(e[0]);
    used.push_back(e[1]);
  }
  std::sort(used.begin(), used.end());
  std::vector<std::size_t> degree(g.Centres.size(), 0);
  for (Index v : used)
  {
    ++degree[v];
  }
  used.erase(std::unique(used.begin(), used.end()), used.end());
  // Junctions first: they become the vertices the others snap to.
  std::stable_sort(
    used.begin(), used.end(), [&](Index a, Index b) { return degree[a] > degree[b]; });
  std::vector<Index> owner(g.Centres.size(), -1);
  for (Index v : used)
  {
    if (owner[v] >= 0)
    {
      continue;
    }
    const double reach = radii * g.Radii[v];
    for (Index w : used)
    {
      if (owner[w] < 0 && Norm(g.Centres[w] - g.Centres[v]) <= reach)
      {
        owner[w] = v;
      }
    }
  }
  std::vector<Edge> snapped;
  for (const Edge& e : edges)
  {
    const Index a = owner[e[0]], b = owner[e[1]];
    if (a != b)
    {
      snapped.push_back({ std::min(a, b), std::max(a, b) });
    }
  }
  std::sort(snapped.begin(), snapped.end());
  snapped.erase(std::unique(snapped.begin(), snapped.end()), snapped.end());
  return snapped;
}

// A spanning forest by increasing length; every other edge closes a cycle,
// dropped when that cycle is shorter than `radii` ball radii.
std::vector<Edge> OpenSmallCycles(const std::vector<Edge>& edges, const Geometry& g, double radii)
{
  std::vector<Index> order(edges.size());
  std::iota(order.begin(), order.end(), Index(0));
  std::stable_sort(order.begin(), order.end(),
    [&](Index a, Index b) { return g.Length(edges[a]) < g.Length(edges[b]); });
  DisjointSets sets(g.Centres.size());
  std::vector<std::vector<std::pair<Index, double>>> tree(g.Centres.size());
  std::vector<Index> closing;
  for (Index e : order)
  {
    const Index a = edges[e][0], b = edges[e][1];
    if (sets.Find(a) != sets.Find(b))
    {
      sets.Union(a, b);
      tree[a].push_back({ b, g.Length(edges[e]) });
      tree[b].push_back({ a, g.Length(edges[e]) });
    }
    else
    {
      closing.push_back(e);
    }
  }
  std::vector<std::uint8_t> removed(edges.size(), 0);
  for (Index e : closing)
  {
    const Index a = edges[e][0], b = edges[e][1];
    const double limit = radii * std::max(g.Radii[a], g.Radii[b]) - g.Length(edges[e]);
    // The tree path from a to b is unique: depth-first, cut beyond the limit.
    std::vector<std::pair<Index, std::pair<Index, double>>> stack{ { a, { -1, 0.0 } } };
    bool small = false;
    while (!stack.empty() && !small)
    {
      const auto [v, from] = stack.back();
      stack.pop_back();
      for (const auto& [u, length] : tree[v])
      {
        if (u == from.first || from.second + length > limit)
        {
          continue;
        }
        if (u == b)
        {
          small = true;
          break;
        }
        stack.push_back({ u, { v, from.second + length } });
      }
    }
    removed[e] = small ? 1 : 0;
  }
  return Keep(edges, removed);
}

// Walks from free end `v` through vertices of degree 2; returns the edges
// passed, the vertex reached and the length.
struct Walk
{
  std::vector<Index> Edges;
  Index End;
  double Length = 0.0;
};
Walk WalkFrom(Index v, const std::vector<Edge>& edges,
  const std::vector<std::vector<Index>>& incident, const Geometry& g, double stopAfter)
{
  Walk walk;
  Index at = v, e = incident[v][0];
  while (true)
  {
    walk.Edges.push_back(e);
    const Index next = Other(edges[e], at);
    walk.Length += g.Length(edges[e]);
    at = next;
    if (incident[at].size() != 2 || at == v || walk.Length >= stopAfter)
    {
      break;
    }
    e = incident[at][0] == e ? incident[at][1] : incident[at][0];
  }
  walk.End = at;
  return walk;
}

// Branches from a free end to a junction shorter than `radii` radii of the
// junction's ball, removed one at a time, shortest first: once a junction
// has lost its shortest branch, its other branches join into one line and
// are no spurs any more (a short fillet is not eaten from its ends).
std::vector<Edge> PruneSpurs(std::vector<Edge> edges, const Geometry& g, double radii)
{
  while (true)
  {
    const auto incident = Incidence(edges, g.Centres.size());
    std::vector<Index> shortest;
    double shortestLength = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < incident.size(); ++v)
    {
      if (incident[v].size() != 1)
      {
        continue;
      }
      const Walk walk =
        WalkFrom(static_cast<Index>(v), edges, incident, g, std::numeric_limits<double>::max());
      if (incident[walk.End].size() >= 3 && walk.Length < radii * g.Radii[walk.End] &&
        walk.Length < shortestLength)
      {
        shortest = walk.Edges;
        shortestLength = walk.Length;
      }
    }
    if (shortest.empty())
    {
      return edges;
    }
    std::vector<std::uint8_t> removed(edges.size(), 0);
    for (Index e : shortest)
    {
      removed[e] = 1;
    }
    edges = Keep(edges, removed);
  }
}

// Whether w is reachable from u along edges within `limit` (Dijkstra,
// cut at the limit).
bool WithinGraphDistance(Index u, Index w, double limit, const std::vector<Edge>& edges,
  const std::vector<std::vector<Index>>& incident, const Geometry& g)
{
  std::vector<std::pair<double, Index>> heap{ { 0.0, u } };
  std::vector<std::pair<Index, double>> settled;
  auto known = [&](Index v)
  {
    return std::find_if(settled.begin(), settled.end(),
             [v](const auto& s) { return s.first == v; }) != settled.end();
  };
  while (!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    const auto [distance, v] = heap.back();
    heap.pop_back();
    if (known(v))
    {
      continue;
    }
    if (v == w)
    {
      return true;
    }
    settled.push_back({ v, distance });
    for (Index e : incident[v])
    {
      const Index next = Other(edges[e], v);
      const double d = distance + g.Length(edges[e]);
      if (d <= limit && !known(next))
      {
        heap.push_back({ d, next });
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
      }
    }
  }
  return false;
}

// Joins each free end to the nearest vertex ahead of it, within `radii` of
// its ball radius and `angle` of its heading, with a similar ball.
std::vector<Edge> BridgeGaps(
  std::vector<Edge> edges, const Geometry& g, const CentreLineGraphOptions& options)
{
  auto incident = Incidence(edges, g.Centres.size());
  DisjointSets component(g.Centres.size());
  for (const Edge& e : edges)
  {
    component.Union(e[0], e[1]);
  }
  std::vector<Index> used;
  for (std::size_t v = 0; v < incident.size(); ++v)
  {
    if (!incident[v].empty())
    {
      used.push_back(static_cast<Index>(v));
    }
  }
  const double cosAngle = std::cos(options.GapAngle);
  for (Index u : used)
  {
    if (incident[u].size() != 1)
    {
      continue;
    }
    const double r = g.Radii[u];
    // Heading: from a vertex about one radius back along the line.
    const Walk back = WalkFrom(u, edges, incident, g, r);
    const Point3 heading = Normalized(g.Centres[u] - g.Centres[back.End]);
    Index best = -1;
    double bestDistance = options.GapRadii * r;
    for (Index w : used)
    {
      if (w == u || std::abs(g.Radii[w] - r) > 0.25 * r)
      {
        continue;
      }
      // Within its own line only a vertex far along it (closing a loop).
      if (component.Find(w) == component.Find(u) &&
        WithinGraphDistance(u, w, options.SmallCycleRadii * r, edges, incident, g))
      {
        continue;
      }
      const Point3 step = g.Centres[w] - g.Centres[u];
      const double distance = Norm(step);
      // Candidates come in increasing id: ties keep the smaller one.
      const bool closer = best < 0 ? distance <= bestDistance : distance < bestDistance;
      const bool touching = distance <= options.TouchRadii * r;
      if (closer && distance > 0.0 && (touching || Dot(step, heading) >= cosAngle * distance))
      {
        best = w;
        bestDistance = distance;
      }
    }
    if (best >= 0 && best != back.End)
    {
      edges.push_back({ std::min(u, best), std::max(u, best) });
      incident[u].push_back(static_cast<Index>(edges.size() - 1));
      incident[best].push_back(static_cast<Index>(edges.size() - 1));
      component.Union(u, best);
    }
  }
  return edges;
}

// Maximal paths between vertices of degree other than 2, and loops.
std::vector<CentreLine> Chain(const std::vector<Edge>& edges, std::size_t vertices)
{
  const auto incident = Incidence(edges, vertices);
  std::vector<std::uint8_t> used(edges.size(), 0);
  std::vector<CentreLine> lines;
  auto walk = [&](Index start, Index first)
  {
    CentreLine line;
    line.Vertices.push_back(start);
    Index v = start, e = first;
    while (true)
    {
      used[e] = 1;
      v = Other(edges[e], v);
      if (v == start)
      {
        line.Closed = true;
        break;
      }
      line.Vertices.push_back(v);
      if (incident[v].size() != 2)
      {
        break;
      }
      e = used[incident[v][0]] ? incident[v][1] : incident[v][0];
      if (used[e])
      {
        break;
      }
    }
    lines.push_back(std::move(line));
  };
  for (std::size_t v = 0; v < vertices; ++v)
  {
    if (!incident[v].empty() && incident[v].size() != 2)
    {
      for (Index e : incident[v])
      {
        if (!used[e])
        {
          walk(static_cast<Index>(v), e);
        }
      }
    }
  }
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    if (!used[e])
    {
      walk(edges[e][0], static_cast<Index>(e));
    }
  }
  return lines;
}

// Turning angle at vertex i, between the directions to the vertices at least
// one ball radius before and after it (or the ends).
double Turn(const CentreLine& line, std::size_t i, const Geometry& g)
{
  const std::size_t n = line.Vertices.size();
  const Point3& c = g.Centres[line.Vertices[i]];
  const double r = g.Radii[line.Vertices[i]];
  auto reach = [&](int step)
  {
    std::size_t j = i;
    for (std::size_t k = 1; k < n; ++k)
    {
      const std::size_t next = (i + n + step * static_cast<long>(k)) % n;
      if (!line.Closed && ((step < 0 && k > i) || (step > 0 && i + k >= n)))
      {
        break;
      }
      j = next;
      if (Norm(g.Centres[line.Vertices[j]] - c) >= r)
      {
        break;
      }
    }
    return g.Centres[line.Vertices[j]];
  };
  const Point3 before = reach(-1), after = reach(+1);
  const Point3 u = c - before, w = after - c;
  if (Norm(u) == 0.0 || Norm(w) == 0.0)
  {
    return 0.0;
  }
  return std::acos(std::clamp(Dot(Normalized(u), Normalized(w)), -1.0, 1.0));
}

// Splits a line at the sharpest vertex of every run of vertices turning by
// more than the split angle.
void SplitAtTurns(
  const CentreLine& line, const Geometry& g, double splitAngle, std::vector<CentreLine>& out)
{
  const std::size_t n = line.Vertices.size();
  std::vector<double> turn(n, 0.0);
  for (std::size_t i = line.Closed ? 0 : 1; i + (line.Closed ? 0 : 1) < n; ++i)
  {
    turn[i] = Turn(line, i, g);
  }
  // A loop is scanned from a vertex outside every run, so runs do not wrap.
  std::size_t start = 0;
  while (line.Closed && start < n && turn[start] > splitAngle)
  {
    ++start;
  }
  if (start == n)
  {
    out.push_back(line); // turns everywhere: too small to split
    return;
  }
  std::vector<std::size_t> cuts;
  bool inRun = false;
  std::size_t sharpest = 0;
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t i = (start + k) % n;
    if (turn[i] > splitAngle)
    {
      sharpest = !inRun || turn[i] > turn[sharpest] ? i : sharpest;
      inRun = true;
    }
    else if (inRun)
    {
      cuts.push_back(sharpest);
      inRun = false;
    }
  }
  if (inRun)
  {
    cuts.push_back(sharpest);
  }
  if (cuts.empty())
  {
    out.push_back(line);
    return;
  }
  std::sort(cuts.begin(), cuts.end());
  if (line.Closed)
  {
    // Open the loop at its cuts: pieces run from cut to cut, around.
    for (std::size_t c = 0; c < cuts.size(); ++c)
    {
      const std::size_t from = cuts[c], to = cuts[(c + 1) % cuts.size()];
      CentreLine piece;
      for (std::size_t i = from;; i = (i + 1) % n)
      {
        piece.Vertices.push_back(line.Vertices[i]);
        if (i == to && piece.Vertices.size() > 1)
        {
          break;
        }
      }
      out.push_back(std::move(piece));
    }
    return;
  }
  std::size_t from = 0;
  cuts.push_back(n - 1);
  for (std::size_t cut : cuts)
  {
    if (cut > from)
    {
      CentreLine piece;
      piece.Vertices.assign(line.Vertices.begin() + from, line.Vertices.begin() + cut + 1);
      out.push_back(std::move(piece));
      from = cut;
    }
  }
}
}

std::vector<CentreLine> TraceCentreLines(const std::vector<std::array<Index, 2>>& edges,
  const std::vector<Point3>& centres, const std::vector<double>& radii,
  const CentreLineGraphOptions& options)
{
  const Geometry g{ centres, radii };
  // Twice: opening cycles and pruning spurs frees ends that can then be
  // bridged, and bridges can close new small cycles.
  std::vector<Edge> cleaned = SnapToScale(edges, g, options.SnapRadii);
  for (int pass = 0; pass < 2; ++pass)
  {
    cleaned = OpenSmallCycles(cleaned, g, options.SmallCycleRadii);
    cleaned = PruneSpurs(std::move(cleaned), g, options.SpurRadii);
    cleaned = BridgeGaps(std::move(cleaned), g, options);
  }
  cleaned = OpenSmallCycles(cleaned, g, options.SmallCycleRadii);
  cleaned = PruneSpurs(std::move(cleaned), g, options.SpurRadii);
  std::vector<CentreLine> lines;
  for (const CentreLine& line : Chain(cleaned, centres.size()))
  {
    SplitAtTurns(line, g, options.SplitAngle, lines);
  }
  return lines;
}
}
