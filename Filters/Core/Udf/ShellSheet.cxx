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

// Moves p, a point of the sheet with unit normal n, onto the field's zero
// set: from the points epsilon away on both sides, where a sampled distance
// field is smooth and its trilinear interpolant accurate, one step back
// along the gradient by the distance read there gives a foot on the zero
// set; p becomes the mean of the two feet. (Right at the zero set the
// interpolant of a sampled distance has its minimum on the nearest grid
// plane, not on the surface: a descent there would pull p off.)
Point3 Snap(const RegularField& field, const Point3& p, const Point3& n, double epsilon)
{
  Point3 sum{ 0, 0, 0 };
  for (const double side : { 1.0, -1.0 })
  {
    const Point3 q = p + (side * epsilon) * n;
    const Point3 g = field.Gradient(q);
    const double length = Norm(g);
    if (length < 1e-12)
    {
      return p;
    }
    sum = sum + (q - (field.Value(q) / length) * ((1.0 / length) * g));
  }
  const Point3 foot = 0.5 * sum;
  // A foot farther than epsilon is not this point's: the sides' closest
  // points differ (a rim, a junction).
  return Norm(foot - p) < 0.5 * epsilon ? foot : p;
}
}

ShellSheet ExtractShellSheet(
  const MedialMesh& medial, const ShellSheetOptions& options, const RegularField* field)
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

  if (field && options.SnapSteps > 0 && !sheet.Surface.Points.empty())
  {
    // Normals at points where the sheet is one manifold layer; points on
    // junctions and free boundaries stay where the medial axis put them.
    const TriangleMesh& surface = sheet.Surface;
    std::vector<Point3> normal(surface.Points.size(), Point3{ 0, 0, 0 });
    std::vector<char> fixed(surface.Points.size(), 0);
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
    const EdgeUses sheetEdges = GroupEdges(surface.Triangles);
    for (std::size_t e = 0; e + 1 < sheetEdges.Starts.size(); ++e)
    {
      if (sheetEdges.Starts[e + 1] - sheetEdges.Starts[e] != 2)
      {
        const HalfEdge& h = sheetEdges.HalfEdges[sheetEdges.Starts[e]];
        fixed[h.Lo] = fixed[h.Hi] = 1;
      }
    }
    double moved = 0.0;
    for (int step = 0; step < options.SnapSteps; ++step)
    {
      for (std::size_t v = 0; v < surface.Points.size(); ++v)
      {
        const double length = Norm(normal[v]);
        if (fixed[v] || length == 0.0)
        {
          continue;
        }
        Point3& p = sheet.Surface.Points[v];
        const Point3 snapped = Snap(*field, p, (1.0 / length) * normal[v], options.Epsilon);
        moved += Norm(snapped - p);
        p = snapped;
      }
    }
    sheet.MeanSnapDistance = moved / static_cast<double>(surface.Points.size());
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
