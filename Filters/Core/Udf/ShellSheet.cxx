// SPDX-License-Identifier: GPL-3.0-or-later
#include "Udf/ShellSheet.h"

#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace medialaxis
{
namespace
{
// Per undirected edge (sorted half-edges): the triangles using it.
struct EdgeUses
{
  std::vector<HalfEdge> HalfEdges;
  std::vector<std::size_t> Starts; // edge e: HalfEdges[Starts[e], Starts[e + 1])
};

EdgeUses GroupEdges(const std::vector<Triangle>& triangles)
{
  EdgeUses uses;
  uses.HalfEdges = SortedHalfEdges(triangles);
  for (std::size_t i = 0; i < uses.HalfEdges.size(); ++i)
  {
    if (i == 0 || uses.HalfEdges[i].Lo != uses.HalfEdges[i - 1].Lo ||
      uses.HalfEdges[i].Hi != uses.HalfEdges[i - 1].Hi)
    {
      uses.Starts.push_back(i);
    }
  }
  uses.Starts.push_back(uses.HalfEdges.size());
  return uses;
}

double TriangleArea(const std::vector<Point3>& points, const Triangle& t)
{
  return 0.5 * Norm(Cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]));
}

// Where a point p of the sheet with unit normal n lands on the field's
// zero set: from the points epsilon away on both sides, where a distance
// field is smooth (and a sampled one's trilinear interpolant accurate), one
// step back along the gradient by the distance read there gives a foot on
// the zero set; p moves to the mean of the two feet. (Right at the zero set
// the interpolant of a sampled distance has its minimum on the nearest grid
// plane, not on the surface: a descent there would pull p off.) q holds
// the two points, value and gradient what the probe read there.
Point3 Snap(const Point3& p, const Point3 q[2], const double value[2], const Point3 gradient[2],
  double epsilon)
{
  Point3 feet[2];
  for (int side = 0; side < 2; ++side)
  {
    const double length = Norm(gradient[side]);
    if (length < 1e-12)
    {
      return p;
    }
    feet[side] = q[side] - (value[side] / length) * ((1.0 / length) * gradient[side]);
  }
  const Point3 foot = 0.5 * (feet[0] + feet[1]);
  // Feet apart, or a foot farther than epsilon, are not this point's: the
  // sides' closest points differ (a rim, a junction, another sheet).
  if (Norm(feet[0] - feet[1]) >= 0.5 * epsilon)
  {
    return p;
  }
  return Norm(foot - p) < 0.5 * epsilon ? foot : p;
}
}

// Per point of the sheet: how many edges of other than two triangles
// (boundary or junction edges) it is on, 0 where the sheet is one manifold
// layer around it; and whether one of them is a junction edge.
struct PointKinds
{
  std::vector<char> OnBoundaryOrJunction;
  std::vector<char> OnJunction;
};

PointKinds ClassifyPoints(const TriangleMesh& surface)
{
  PointKinds kinds;
  kinds.OnBoundaryOrJunction.assign(surface.Points.size(), 0);
  kinds.OnJunction.assign(surface.Points.size(), 0);
  const EdgeUses edges = GroupEdges(surface.Triangles);
  for (std::size_t e = 0; e + 1 < edges.Starts.size(); ++e)
  {
    const std::size_t count = edges.Starts[e + 1] - edges.Starts[e];
    const HalfEdge& h = edges.HalfEdges[edges.Starts[e]];
    if (count != 2)
    {
      kinds.OnBoundaryOrJunction[h.Lo] = kinds.OnBoundaryOrJunction[h.Hi] = 1;
    }
    if (count > 2)
    {
      kinds.OnJunction[h.Lo] = kinds.OnJunction[h.Hi] = 1;
    }
  }
  return kinds;
}

// A sampled field: each point where the sheet is one manifold layer moves
// to the mean of the feet from its two sides (see Snap); points on
// junctions and free boundaries stay where the medial axis put them.
std::string SnapFromBothSides(
  ShellSheet& sheet, const DistanceProbe& probe, const ShellSheetOptions& options)
{
  const TriangleMesh& surface = sheet.Surface;
  std::vector<Point3> normal(surface.Points.size(), Point3{ 0, 0, 0 });
  for (const Triangle& t : surface.Triangles)
  {
    const Point3 n = Cross(
      surface.Points[t[1]] - surface.Points[t[0]], surface.Points[t[2]] - surface.Points[t[0]]);
    for (Index v : t)
    {
      // Neighbouring medial triangles need not be oriented alike.
      normal[v] = Dot(normal[v], n) < 0.0 ? normal[v] - n : normal[v] + n;
    }
  }
  const PointKinds kinds = ClassifyPoints(surface);
  std::vector<std::size_t> moving;
  std::vector<Point3> unit;
  for (std::size_t v = 0; v < surface.Points.size(); ++v)
  {
    const double length = Norm(normal[v]);
    if (!kinds.OnBoundaryOrJunction[v] && length > 0.0)
    {
      moving.push_back(v);
      unit.push_back((1.0 / length) * normal[v]);
    }
  }
  // Both sides of every moving point in one probe per step.
  double moved = 0.0;
  std::vector<Point3> sides(2 * moving.size());
  const std::vector<double> steps(sides.size(), 0.0); // unused by a field
  std::vector<double> values;
  std::vector<Point3> gradients;
  for (int step = 0; step < options.SnapSteps; ++step)
  {
    for (std::size_t m = 0; m < moving.size(); ++m)
    {
      const Point3& p = sheet.Surface.Points[moving[m]];
      sides[2 * m] = p + options.Epsilon * unit[m];
      sides[2 * m + 1] = p - options.Epsilon * unit[m];
    }
    std::string problem = probe.Values(sides, values);
    if (problem.empty())
    {
      problem = probe.Gradients(sides, steps, gradients);
    }
    if (!problem.empty())
    {
      return problem;
    }
    for (std::size_t m = 0; m < moving.size(); ++m)
    {
      Point3& p = sheet.Surface.Points[moving[m]];
      const Point3 snapped =
        Snap(p, &sides[2 * m], &values[2 * m], &gradients[2 * m], options.Epsilon);
      moved += Norm(snapped - p);
      p = snapped;
    }
  }
  sheet.MeanSnapDistance = moved / static_cast<double>(surface.Points.size());
  return {};
}

// An exact distance: every point but those on junctions moves to its
// closest point on the zero set, p - d(p) g / |g|^2 with g the gradient over
// a step within the distance (where it is smooth). Along a sharp fold of the
// surface the shell's medial axis passes inside the fold, through points
// whose distance has a ridge (two closest points): there |g| < 1 and the
// step lands on the fold. Points closer than 1e-9 epsilon stay; so do points
// on a ridge of three or more closest points (|g| < 1/2), and junctions,
// whose closest point is on one of their sheets.
std::string ProjectOntoZeroSet(
  ShellSheet& sheet, const DistanceProbe& probe, const ShellSheetOptions& options)
{
  std::vector<Point3>& points = sheet.Surface.Points;
  const PointKinds kinds = ClassifyPoints(sheet.Surface);
  std::vector<std::size_t> moving;
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    if (!kinds.OnJunction[v])
    {
      moving.push_back(v);
    }
  }
  double moved = 0.0;
  std::vector<Point3> at, near;
  std::vector<double> values, steps;
  std::vector<std::size_t> far;
  std::vector<Point3> gradients;
  for (int step = 0; step < options.SnapSteps; ++step)
  {
    at.clear();
    for (std::size_t v : moving)
    {
      at.push_back(points[v]);
    }
    std::string problem = probe.Values(at, values);
    if (!problem.empty())
    {
      return problem;
    }
    near.clear();
    steps.clear();
    far.clear();
    for (std::size_t m = 0; m < moving.size(); ++m)
    {
      if (values[m] > 1e-9 * options.Epsilon)
      {
        far.push_back(m);
        near.push_back(at[m]);
        steps.push_back(std::min(0.125 * options.Epsilon, 0.5 * values[m]));
      }
    }
    problem = probe.Gradients(near, steps, gradients);
    if (!problem.empty())
    {
      return problem;
    }
    for (std::size_t f = 0; f < far.size(); ++f)
    {
      const double length = Norm(gradients[f]);
      const double d = values[far[f]];
      if (length < 0.5 || d > options.Epsilon)
      {
        continue;
      }
      Point3& p = points[moving[far[f]]];
      const Point3 target = p - (d / (length * length)) * gradients[f];
      moved += Norm(target - p);
      p = target;
    }
  }
  sheet.MeanSnapDistance = moved / static_cast<double>(points.size());
  return {};
}

// Drops the flaps on junction edges: triangles with a free edge that are
// folded back onto another triangle of the junction edge (within 30 degrees
// on the same side of it) or are slivers (height over the edge under a
// tenth of their longest side). The shell's medial axis grows them where it is sampled coarsely
// along a rim; a real junction's sheets part at wide angles with
// well-shaped triangles. Flaps go, those with more free edges and then the
// smaller first, until two triangles are left on the edge. Returns how many
// it dropped.
std::size_t DropFlaps(TriangleMesh& mesh)
{
  const EdgeUses uses = GroupEdges(mesh.Triangles);
  std::vector<int> freeEdges(mesh.Triangles.size(), 0);
  for (std::size_t e = 0; e + 1 < uses.Starts.size(); ++e)
  {
    if (uses.Starts[e + 1] - uses.Starts[e] == 1)
    {
      ++freeEdges[uses.HalfEdges[uses.Starts[e]].Tri];
    }
  }
  std::vector<char> drop(mesh.Triangles.size(), 0);
  const double folded = std::cos(30.0 * 3.14159265358979323846 / 180.0);
  for (std::size_t e = 0; e + 1 < uses.Starts.size(); ++e)
  {
    const std::size_t begin = uses.Starts[e], end = uses.Starts[e + 1];
    if (end - begin < 3)
    {
      continue;
    }
    const Point3& a = mesh.Points[uses.HalfEdges[begin].Lo];
    const Point3 along = mesh.Points[uses.HalfEdges[begin].Hi] - a;
    const double length2 = Dot(along, along);
    // Each triangle's height over the edge (over its longest side) and
    // direction away from the edge.
    std::vector<Point3> away;
    std::vector<double> height;
    for (std::size_t u = begin; u < end; ++u)
    {
      const Triangle& t = mesh.Triangles[uses.HalfEdges[u].Tri];
      Index third = t[0];
      for (Index v : t)
      {
        third = v != uses.HalfEdges[u].Lo && v != uses.HalfEdges[u].Hi ? v : third;
      }
      const Point3 w = mesh.Points[third] - a;
      const Point3 perpendicular = w - (Dot(w, along) / length2) * along;
      const double longest = std::max({ std::sqrt(length2), Norm(w), Norm(w - along) });
      height.push_back(Norm(perpendicular) / longest);
      away.push_back(
        height.back() > 0.0 ? (1.0 / height.back()) * perpendicular : Point3{ 0, 0, 0 });
    }
    std::vector<std::size_t> flaps;
    for (std::size_t i = 0; i < away.size(); ++i)
    {
      const Index ti = uses.HalfEdges[begin + i].Tri;
      bool flap = height[i] < 0.1;
      for (std::size_t j = 0; j < away.size() && !flap; ++j)
      {
        flap = j != i && Dot(away[i], away[j]) >= folded;
      }
      if (flap && freeEdges[ti] > 0)
      {
        flaps.push_back(i);
      }
    }
    std::sort(flaps.begin(), flaps.end(),
      [&](std::size_t i, std::size_t j)
      {
        const Index ti = uses.HalfEdges[begin + i].Tri, tj = uses.HalfEdges[begin + j].Tri;
        const double ai = TriangleArea(mesh.Points, mesh.Triangles[ti]);
        const double aj = TriangleArea(mesh.Points, mesh.Triangles[tj]);
        return freeEdges[ti] != freeEdges[tj] ? freeEdges[ti] > freeEdges[tj]
                                              : (ai != aj ? ai < aj : ti < tj);
      });
    std::size_t left = end - begin;
    for (std::size_t f = 0; f < flaps.size() && left > 2; ++f, --left)
    {
      drop[uses.HalfEdges[begin + flaps[f]].Tri] = 1;
    }
  }
  std::size_t dropped = 0;
  std::vector<Triangle> kept;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    if (drop[t])
    {
      ++dropped;
    }
    else
    {
      kept.push_back(mesh.Triangles[t]);
    }
  }
  mesh.Triangles = std::move(kept);
  return dropped;
}

// Closes the holes of `mesh` whose boundary loops are simple cycles spanning
// less than `span` (the largest distance between two of their points), with
// a fan from the loop's first point, oriented like the triangle across the
// loop's first edge. Returns how many it closed.
std::size_t FillNarrowHoles(TriangleMesh& mesh, double span)
{
  // Boundary edges, directed as their one triangle's opposite would run.
  const EdgeUses uses = GroupEdges(mesh.Triangles);
  std::map<Index, std::vector<Index>> next; // boundary successors of each point
  for (std::size_t e = 0; e + 1 < uses.Starts.size(); ++e)
  {
    if (uses.Starts[e + 1] - uses.Starts[e] == 1)
    {
      const HalfEdge& h = uses.HalfEdges[uses.Starts[e]];
      const auto [from, to] = h.Forward ? std::pair(h.Hi, h.Lo) : std::pair(h.Lo, h.Hi);
      next[from].push_back(to);
    }
  }
  std::map<Index, bool> visited;
  std::size_t filled = 0;
  for (const auto& [start, successors] : next)
  {
    if (visited[start])
    {
      continue;
    }
    // Walk the loop; a point with other than one successor ends the walk
    // (the loop is not a simple cycle, e.g. the sheet's orientation flips
    // along it).
    std::vector<Index> loop{ start };
    visited[start] = true;
    bool simple = successors.size() == 1;
    for (Index v = start; simple;)
    {
      const auto found = next.find(v);
      simple = found != next.end() && found->second.size() == 1;
      if (!simple)
      {
        break;
      }
      v = found->second.front();
      if (v == start)
      {
        break;
      }
      simple = !visited[v];
      visited[v] = true;
      loop.push_back(v);
    }
    if (!simple || loop.size() < 3)
    {
      continue;
    }
    double widest = 0.0;
    for (std::size_t a = 0; a < loop.size(); ++a)
    {
      for (std::size_t b = a + 1; b < loop.size(); ++b)
      {
        widest = std::max(widest, Norm(mesh.Points[loop[a]] - mesh.Points[loop[b]]));
      }
    }
    if (widest >= span)
    {
      continue;
    }
    for (std::size_t k = 1; k + 1 < loop.size(); ++k)
    {
      mesh.Triangles.push_back({ loop[0], loop[k], loop[k + 1] });
    }
    ++filled;
  }
  return filled;
}

ShellSheet ExtractShellSheet(
  const MedialMesh& medial, const ShellSheetOptions& options, const DistanceProbe* probe)
{
  ShellSheet sheet;
  const double minimumRadius = options.MinimumRadiusFraction * options.Epsilon;
  std::vector<Triangle> kept;
  for (const auto& f : medial.Faces)
  {
    if (std::min({ medial.Radii[f[0]], medial.Radii[f[1]], medial.Radii[f[2]] }) >= minimumRadius)
    {
      kept.push_back({ f[0], f[1], f[2] });
    }
    else
    {
      ++sheet.ShrunkTriangles;
    }
  }

  // Pieces: triangles joined across edges of exactly two triangles.
  const EdgeUses uses = GroupEdges(kept);
  DisjointSets pieces(kept.size());
  std::vector<char> onJunction(kept.size(), 0);
  for (std::size_t e = 0; e + 1 < uses.Starts.size(); ++e)
  {
    const std::size_t begin = uses.Starts[e], count = uses.Starts[e + 1] - begin;
    if (count == 2)
    {
      pieces.Union(uses.HalfEdges[begin].Tri, uses.HalfEdges[begin + 1].Tri);
    }
    else if (count > 2)
    {
      for (std::size_t u = begin; u < begin + count; ++u)
      {
        onJunction[uses.HalfEdges[u].Tri] = 1;
      }
    }
  }
  std::map<Index, double> pieceArea;
  std::map<Index, bool> pieceOnJunction;
  for (std::size_t t = 0; t < kept.size(); ++t)
  {
    const Index root = pieces.Find(static_cast<Index>(t));
    pieceArea[root] += TriangleArea(medial.Centers, kept[t]);
    pieceOnJunction[root] = pieceOnJunction[root] || onJunction[t];
  }
  const double finArea = options.MinimumFinArea * options.Epsilon * options.Epsilon;
  std::vector<Index> newIndex(medial.Centers.size(), -1);
  for (std::size_t t = 0; t < kept.size(); ++t)
  {
    const Index root = pieces.Find(static_cast<Index>(t));
    if (pieceOnJunction[root] && pieceArea[root] < finArea)
    {
      ++sheet.FinTriangles;
      continue;
    }
    Triangle out{};
    for (int k = 0; k < 3; ++k)
    {
      const Index v = kept[t][k];
      if (newIndex[v] < 0)
      {
        newIndex[v] = static_cast<Index>(sheet.Surface.Points.size());
        sheet.Surface.Points.push_back(medial.Centers[v]);
        sheet.ShellRadius.push_back(medial.Radii[v]);
        sheet.MedialVertex.push_back(v);
      }
      out[k] = newIndex[v];
    }
    sheet.Surface.Triangles.push_back(out);
  }

  sheet.FlapTriangles = DropFlaps(sheet.Surface);
  sheet.FilledHoles = FillNarrowHoles(sheet.Surface, options.MaximumHoleSpan * options.Epsilon);

  if (probe && options.SnapSteps > 0 && !sheet.Surface.Points.empty())
  {
    sheet.Error = probe->Exact() ? ProjectOntoZeroSet(sheet, *probe, options)
                                 : SnapFromBothSides(sheet, *probe, options);
  }
  return sheet;
}

std::size_t CountBoundaryLoops(const TriangleMesh& mesh)
{
  const EdgeUses uses = GroupEdges(mesh.Triangles);
  DisjointSets loops(mesh.Points.size());
  std::vector<char> onBoundary(mesh.Points.size(), 0);
  for (std::size_t e = 0; e + 1 < uses.Starts.size(); ++e)
  {
    if (uses.Starts[e + 1] - uses.Starts[e] == 1)
    {
      const HalfEdge& h = uses.HalfEdges[uses.Starts[e]];
      loops.Union(h.Lo, h.Hi);
      onBoundary[h.Lo] = onBoundary[h.Hi] = 1;
    }
  }
  std::size_t count = 0;
  for (std::size_t v = 0; v < mesh.Points.size(); ++v)
  {
    count += onBoundary[v] && loops.Find(static_cast<Index>(v)) == static_cast<Index>(v);
  }
  return count;
}

std::size_t CountJunctionEdges(const TriangleMesh& mesh)
{
  const EdgeUses uses = GroupEdges(mesh.Triangles);
  std::size_t count = 0;
  for (std::size_t e = 0; e + 1 < uses.Starts.size(); ++e)
  {
    count += uses.Starts[e + 1] - uses.Starts[e] > 2;
  }
  return count;
}
}
