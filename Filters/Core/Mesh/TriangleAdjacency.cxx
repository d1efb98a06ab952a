// SPDX-License-Identifier: GPL-3.0-or-later
#include "Mesh/TriangleAdjacency.h"

#include "Geometry/Vec3.h"

#include <algorithm>

namespace medialaxis
{
std::vector<HalfEdge> SortedHalfEdges(const std::vector<Triangle>& triangles)
{
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      halfEdges.push_back({ std::min(a, b), std::max(a, b), static_cast<Index>(t), a < b });
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  return halfEdges;
}

Point3 TriangleNormal(const TriangleMesh& mesh, Index t)
{
  const Triangle& tri = mesh.Triangles[t];
  const Point3& a = mesh.Points[tri[0]];
  return Normalized(Cross(mesh.Points[tri[1]] - a, mesh.Points[tri[2]] - a));
}

TriangleAdjacency ComputeTriangleAdjacency(
  const TriangleMesh& mesh, double featureAngle, const std::vector<Point3>* filteredNormals)
{
  const std::size_t nt = mesh.Triangles.size();
  TriangleAdjacency adjacency;
  adjacency.Neighbour.assign(nt, { -1, -1, -1 });
  adjacency.Feature.assign(nt, { EdgeFeature::None, EdgeFeature::None, EdgeFeature::None });
  auto localEdge = [&mesh](Index t, Index lo, Index hi)
  {
    const Triangle& tri = mesh.Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      const Index a = tri[k], b = tri[(k + 1) % 3];
      if (std::min(a, b) == lo && std::max(a, b) == hi)
      {
        return k;
      }
    }
    return 0;
  };
  const double cosFeature = std::cos(featureAngle);
  const auto halfEdges = SortedHalfEdges(mesh.Triangles);
  for (std::size_t i = 0; i + 1 < halfEdges.size();)
  {
    std::size_t j = i + 1;
    while (j < halfEdges.size() && halfEdges[j].Lo == halfEdges[i].Lo &&
      halfEdges[j].Hi == halfEdges[i].Hi)
    {
      ++j;
    }
    if (j - i == 2)
    {
      const Index t1 = halfEdges[i].Tri, t2 = halfEdges[i + 1].Tri;
      const int k1 = localEdge(t1, halfEdges[i].Lo, halfEdges[i].Hi);
      const int k2 = localEdge(t2, halfEdges[i].Lo, halfEdges[i].Hi);
      adjacency.Neighbour[t1][k1] = t2;
      adjacency.Neighbour[t2][k2] = t1;
      const Point3 n1 = TriangleNormal(mesh, t1), n2 = TriangleNormal(mesh, t2);
      // The angle between the normals is pi minus the dihedral angle for a
      // ridge and the dihedral angle minus pi for a valley.
      if (Dot(n1, n2) < cosFeature)
      {
        const Point3& onEdge = mesh.Points[halfEdges[i].Lo];
        const Point3& opposite = mesh.Points[mesh.Triangles[t2][(k2 + 2) % 3]];
        EdgeFeature f =
          Dot(n1, opposite - onEdge) < 0.0 ? EdgeFeature::Convex : EdgeFeature::Concave;
        if (f == EdgeFeature::Convex && filteredNormals &&
          Dot((*filteredNormals)[t1], (*filteredNormals)[t2]) >= cosFeature)
        {
          f = EdgeFeature::None;
        }
        adjacency.Feature[t1][k1] = f;
        adjacency.Feature[t2][k2] = f;
      }
    }
    i = j;
  }
  return adjacency;
}

void OrientOutward(TriangleMesh& mesh)
{
  double volume = 0.0;
  for (const Triangle& t : mesh.Triangles)
  {
    volume += Dot(mesh.Points[t[0]], Cross(mesh.Points[t[1]], mesh.Points[t[2]]));
  }
  if (volume < 0.0)
  {
    for (Triangle& t : mesh.Triangles)
    {
      std::swap(t[1], t[2]);
    }
  }
}
}
