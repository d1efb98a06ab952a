// SPDX-License-Identifier: GPL-3.0-or-later
#include "Mesh/MedialSheets.h"

#include "Geometry/Vec3.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <tuple>

namespace medialaxis
{
namespace
{
// (min, max, face) per triangle edge, sorted by edge: the runs of equal
// edges are the triangles around each edge.
std::vector<std::tuple<Index, Index, Index>> SortedTriangleEdges(const MedialMesh& mesh)
{
  std::vector<std::tuple<Index, Index, Index>> halfEdges;
  halfEdges.reserve(3 * mesh.Faces.size());
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    const auto& t = mesh.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      const Index u = t[k], v = t[(k + 1) % 3];
      halfEdges.emplace_back(std::min(u, v), std::max(u, v), static_cast<Index>(f));
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  return halfEdges;
}

// Calls visit(u, v, first, last) for each run [first, last) of one edge.
void ForEachEdgeRun(const std::vector<std::tuple<Index, Index, Index>>& halfEdges,
  const std::function<void(Index, Index, std::size_t, std::size_t)>& visit)
{
  for (std::size_t i = 0; i < halfEdges.size();)
  {
    std::size_t j = i + 1;
    while (j < halfEdges.size() && std::get<0>(halfEdges[j]) == std::get<0>(halfEdges[i]) &&
      std::get<1>(halfEdges[j]) == std::get<1>(halfEdges[i]))
    {
      ++j;
    }
    visit(std::get<0>(halfEdges[i]), std::get<1>(halfEdges[i]), i, j);
    i = j;
  }
}

Index Apex(const std::array<Index, 3>& t, Index u, Index v)
{
  for (Index w : t)
  {
    if (w != u && w != v)
    {
      return w;
    }
  }
  return t[0];
}

// The angle (degrees) between the half-planes from the edge (u, v) through
// x and through y.
double HingeAngle(const Point3& u, const Point3& v, const Point3& x, const Point3& y)
{
  const Point3 e = v - u;
  const double e2 = Dot(e, e);
  if (!(e2 > 0.0))
  {
    return 180.0;
  }
  const Point3 px = (x - u) - (Dot(x - u, e) / e2) * e;
  const Point3 py = (y - u) - (Dot(y - u, e) / e2) * e;
  return std::atan2(Norm(Cross(px, py)), Dot(px, py)) * 180.0 / Pi;
}
}

SheetDecomposition DecomposeIntoSheets(const MedialMesh& mesh)
{
  SheetDecomposition sheets;
  DisjointSets sets(mesh.Faces.size());
  const auto halfEdges = SortedTriangleEdges(mesh);
  ForEachEdgeRun(halfEdges,
    [&](Index, Index, std::size_t first, std::size_t last)
    {
      if (last - first == 2)
      {
        sets.Union(std::get<2>(halfEdges[first]), std::get<2>(halfEdges[first + 1]));
      }
    });
  sheets.SheetOfTriangle.assign(mesh.Faces.size(), -1);
  std::vector<Index> idOfRoot(mesh.Faces.size(), -1);
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    const Index root = sets.Find(static_cast<Index>(f));
    if (idOfRoot[root] < 0)
    {
      idOfRoot[root] = static_cast<Index>(sheets.NumberOfSheets++);
    }
    sheets.SheetOfTriangle[f] = idOfRoot[root];
  }
  return sheets;
}

MedialCleanliness MeasureCleanliness(const MedialMesh& mesh, double diagonal)
{
  MedialCleanliness result;
  if (mesh.Faces.empty())
  {
    return result;
  }
  const auto halfEdges = SortedTriangleEdges(mesh);
  // Sheets: triangles joined across two-triangle edges.
  DisjointSets sets(mesh.Faces.size());
  std::vector<char> onJunction(mesh.Faces.size(), 0);
  std::size_t hinges = 0, pleats = 0;
  double boundary = 0.0, junction = 0.0;
  ForEachEdgeRun(halfEdges,
    [&](Index u, Index v, std::size_t first, std::size_t last)
    {
      const std::size_t count = last - first;
      const double length = Norm(mesh.Centers[v] - mesh.Centers[u]);
      if (count == 1)
      {
        boundary += length;
      }
      else if (count == 2)
      {
        const Index f = std::get<2>(halfEdges[first]), g = std::get<2>(halfEdges[first + 1]);
        sets.Union(f, g);
        ++hinges;
        const Point3& x = mesh.Centers[Apex(mesh.Faces[f], u, v)];
        const Point3& y = mesh.Centers[Apex(mesh.Faces[g], u, v)];
        pleats += HingeAngle(mesh.Centers[u], mesh.Centers[v], x, y) < PleatAngleDegrees ? 1 : 0;
      }
      else
      {
        ++result.JunctionEdges;
        junction += length;
        for (std::size_t i = first; i < last; ++i)
        {
          onJunction[std::get<2>(halfEdges[i])] = 1;
        }
      }
    });
  std::vector<double> sheetArea(mesh.Faces.size(), 0.0);
  std::vector<char> sheetOnJunction(mesh.Faces.size(), 0);
  double total = 0.0;
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    const auto& t = mesh.Faces[f];
    const double area = 0.5 *
      Norm(Cross(mesh.Centers[t[1]] - mesh.Centers[t[0]], mesh.Centers[t[2]] - mesh.Centers[t[0]]));
    const Index root = sets.Find(static_cast<Index>(f));
    sheetArea[root] += area;
    sheetOnJunction[root] |= onJunction[f];
    total += area;
  }
  std::vector<double> areas;
  double finArea = 0.0;
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    if (sets.Find(static_cast<Index>(f)) != static_cast<Index>(f))
    {
      continue;
    }
    areas.push_back(sheetArea[f]);
    if (sheetOnJunction[f] && sheetArea[f] < FinAreaShare * total)
    {
      finArea += sheetArea[f];
    }
  }
  result.Sheets = areas.size();
  std::sort(areas.begin(), areas.end(), std::greater<double>());
  if (total > 0.0)
  {
    double held = 0.0;
    for (double a : areas)
    {
      held += a;
      ++result.SheetsFor80PercentArea;
      if (held >= 0.8 * total)
      {
        break;
      }
    }
    result.LargestSheetAreaFraction = areas.front() / total;
    result.FinAreaFraction = finArea / total;
  }
  result.FoldedEdgeFraction =
    hinges > 0 ? static_cast<double>(pleats) / static_cast<double>(hinges) : 0.0;
  const double scale = diagonal > 0.0 ? 1.0 / diagonal : 1.0;
  result.BoundaryLength = boundary * scale;
  result.JunctionLength = junction * scale;
  return result;
}
}
