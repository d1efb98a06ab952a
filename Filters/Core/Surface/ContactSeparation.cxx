// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/ContactSeparation.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace medialaxis
{
ContactSeparation SeparatePiercingVertices(const std::vector<Point3>& points,
  const std::vector<Triangle>& triangles, const std::vector<signed char>& outward,
  const std::vector<TriangleCrossing>& crossings, double gap)
{
  ContactSeparation result;
  result.Points = points;
  std::map<Index, Point3> moves; // ordered: the same result in any order of crossings
  for (const TriangleCrossing& crossing : crossings)
  {
    bool handled = false;
    for (const auto& [x, y] :
      { std::pair(crossing.A, crossing.B), std::pair(crossing.B, crossing.A) })
    {
      const Triangle& wall = triangles[y];
      const Point3& a = points[wall[0]];
      const Point3 ab = points[wall[1]] - a, ac = points[wall[2]] - a;
      Point3 normal = Cross(ab, ac);
      const double area2 = Dot(normal, normal);
      if (!(area2 > 0.0))
      {
        continue;
      }
      normal = (outward[y] / std::sqrt(area2)) * normal;
      double height[3];
      for (int k = 0; k < 3; ++k)
      {
        height[k] = Dot(points[triangles[x][k]] - a, normal);
      }
      for (int k = 0; k < 3; ++k)
      {
        const Index v = triangles[x][k];
        const bool reachesBehind = height[(k + 1) % 3] < 0.0 || height[(k + 2) % 3] < 0.0;
        if (!(height[k] > 0.0) || !reachesBehind ||
          std::find(wall.begin(), wall.end(), v) != wall.end())
        {
          continue;
        }
        // Over the wall: the foot of the perpendicular inside the triangle.
        const Point3 foot = points[v] - height[k] * normal - a;
        const double d00 = Dot(ab, ab), d01 = Dot(ab, ac), d11 = Dot(ac, ac);
        const double d20 = Dot(foot, ab), d21 = Dot(foot, ac);
        const double det = d00 * d11 - d01 * d01;
        const double s = (d11 * d20 - d01 * d21) / det, t = (d00 * d21 - d01 * d20) / det;
        if (!(s >= 0.0 && t >= 0.0 && s + t <= 1.0))
        {
          continue;
        }
        const Point3 move = (-(height[k] + gap)) * normal;
        auto [it, inserted] = moves.emplace(v, move);
        if (!inserted && Dot(move, move) > Dot(it->second, it->second))
        {
          it->second = move;
        }
        handled = true;
      }
    }
    if (!handled)
    {
      result.Error = "two triangles far apart cross without a vertex poking through either";
      return result;
    }
  }
  if (moves.empty())
  {
    result.Error = "no crossing to pull apart";
    return result;
  }
  std::map<Index, double> shortestEdge;
  for (const Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double length = Norm(points[t[(k + 1) % 3]] - points[t[k]]);
      for (Index v : { t[k], t[(k + 1) % 3] })
      {
        if (moves.count(v))
        {
          auto [it, inserted] = shortestEdge.emplace(v, length);
          it->second = std::min(it->second, length);
        }
      }
    }
  }
  for (const auto& [v, move] : moves)
  {
    const double length = Norm(move);
    if (!(length <= 0.5 * shortestEdge[v]))
    {
      result.Error = "a vertex pokes through a wall by more than half its shortest edge";
      return result;
    }
    result.Points[v] = result.Points[v] + move;
    result.LargestMove = std::max(result.LargestMove, length);
  }
  result.MovedVertices = moves.size();
  return result;
}
}
