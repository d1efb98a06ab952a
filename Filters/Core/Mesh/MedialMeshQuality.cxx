// SPDX-License-Identifier: GPL-3.0-or-later
#include "Mesh/MedialMeshQuality.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

namespace medialaxis
{
namespace
{
// The angle at `p` of the triangle (p, q, r), in degrees.
double AngleAt(const Point3& p, const Point3& q, const Point3& r)
{
  const Point3 u = q - p, v = r - p;
  return std::atan2(Norm(Cross(u, v)), Dot(u, v)) * 180.0 / Pi;
}
}

std::vector<TriangleHinge> TriangleHinges(
  const MedialMesh& mesh, std::size_t* boundaryEdges, std::size_t* nonManifoldEdges)
{
  // (min, max, face, apex) per triangle edge, sorted by edge.
  std::vector<std::tuple<Index, Index, Index, Index>> halfEdges;
  halfEdges.reserve(3 * mesh.Faces.size());
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    const auto& t = mesh.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      const Index u = t[k], v = t[(k + 1) % 3];
      halfEdges.emplace_back(std::min(u, v), std::max(u, v), static_cast<Index>(f), t[(k + 2) % 3]);
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  std::vector<TriangleHinge> hinges;
  std::size_t boundary = 0, nonManifold = 0;
  for (std::size_t i = 0; i < halfEdges.size();)
  {
    std::size_t j = i;
    while (j < halfEdges.size() && std::get<0>(halfEdges[j]) == std::get<0>(halfEdges[i]) &&
      std::get<1>(halfEdges[j]) == std::get<1>(halfEdges[i]))
    {
      ++j;
    }
    boundary += j - i == 1 ? 1 : 0;
    nonManifold += j - i > 2 ? 1 : 0;
    if (j - i == 2)
    {
      const auto& [u, v, f, x] = halfEdges[i];
      hinges.push_back(
        { u, v, f, x, std::get<2>(halfEdges[i + 1]), std::get<3>(halfEdges[i + 1]) });
    }
    i = j;
  }
  if (boundaryEdges)
  {
    *boundaryEdges = boundary;
  }
  if (nonManifoldEdges)
  {
    *nonManifoldEdges = nonManifold;
  }
  return hinges;
}

MedialMeshQuality MeasureQuality(const MedialMesh& mesh)
{
  MedialMeshQuality quality;
  quality.Triangles = mesh.Faces.size();
  std::vector<char> degenerate(mesh.Faces.size(), 0);
  std::size_t measured = 0, below30 = 0;
  double angleSum = 0.0, qualitySum = 0.0;
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    const auto& t = mesh.Faces[f];
    const Point3 &a = mesh.Centers[t[0]], &b = mesh.Centers[t[1]], &c = mesh.Centers[t[2]];
    if (IsDegenerateTriangle(a, b, c))
    {
      degenerate[f] = 1;
      ++quality.DegenerateTriangles;
      continue;
    }
    const double twiceArea = Norm(Cross(b - a, c - a));
    const double la = Norm(c - b), lb = Norm(a - c), lc = Norm(b - a);
    const double longest = std::max({ la, lb, lc });
    const double minimum = std::min({ AngleAt(a, b, c), AngleAt(b, c, a), AngleAt(c, a, b) });
    angleSum += minimum;
    below30 += minimum < 30.0 ? 1 : 0;
    const double halfPerimeter = 0.5 * (la + lb + lc);
    qualitySum += 6.0 / std::sqrt(3.0) * (0.5 * twiceArea) / (longest * halfPerimeter);
    ++measured;
  }
  if (measured > 0)
  {
    quality.MeanMinimumAngle = angleSum / static_cast<double>(measured);
    quality.PercentMinimumAngleBelow30 =
      100.0 * static_cast<double>(below30) / static_cast<double>(measured);
    quality.MeanQuality = qualitySum / static_cast<double>(measured);
  }

  std::vector<char> folded(mesh.Faces.size(), 0);
  for (const TriangleHinge& h :
    TriangleHinges(mesh, &quality.BoundaryEdges, &quality.NonManifoldEdges))
  {
    if (!degenerate[h.F] && !degenerate[h.G] &&
      IsFold(mesh.Centers[h.U], mesh.Centers[h.V], mesh.Centers[h.X], mesh.Centers[h.Y]))
    {
      ++quality.FoldedEdges;
      folded[h.F] = folded[h.G] = 1;
    }
  }
  quality.FoldedTriangles = static_cast<std::size_t>(std::count(folded.begin(), folded.end(), 1));
  return quality;
}
}
