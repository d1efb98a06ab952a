// SPDX-License-Identifier: GPL-3.0-or-later
#include "Mesh/TriangleAdjacency.h"

#include "Geometry/Vec3.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace medialaxis
{
std::vector<HalfEdge> SortedHalfEdges(const std::vector<Triangle>& triangles)
{
  std::vector<HalfEdge> halfEdges(3 * triangles.size());
  auto halfEdge = [&triangles](std::size_t t, int k)
  {
    const Index a = triangles[t][k], b = triangles[t][(k + 1) % 3];
    return HalfEdge{ std::min(a, b), std::max(a, b), static_cast<Index>(t), a < b };
  };
  Index largest = -1;
  bool negative = false;
  for (const Triangle& tri : triangles)
  {
    for (Index v : tri)
    {
      largest = std::max(largest, v);
      negative = negative || v < 0;
    }
  }
  if (negative)
  {
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        halfEdges[3 * t + k] = halfEdge(t, k);
      }
    }
    std::sort(halfEdges.begin(), halfEdges.end());
    return halfEdges;
  }
  // Bucketed by the smaller vertex (a counting sort), then each small bucket
  // sorted by (Hi, Tri), the buckets in parallel: the same order as one sort
  // of all the half-edges, which took most of the adjacency's time on
  // surfaces of 100,000s of triangles.
  const std::size_t nv = static_cast<std::size_t>(largest) + 1;
  std::vector<std::size_t> start(nv + 1, 0);
  for (const Triangle& tri : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++start[static_cast<std::size_t>(std::min(tri[k], tri[(k + 1) % 3])) + 1];
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    start[v + 1] += start[v];
  }
  {
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const HalfEdge h = halfEdge(t, k);
        halfEdges[cursor[static_cast<std::size_t>(h.Lo)]++] = h;
      }
    }
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t v = range.begin(); v != range.end(); ++v)
      {
        std::sort(halfEdges.begin() + static_cast<std::ptrdiff_t>(start[v]),
          halfEdges.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
      }
    });
  return halfEdges;
}

Point3 TriangleNormal(const TriangleMesh& mesh, Index t)
{
  const Triangle& tri = mesh.Triangles[t];
  const Point3& a = mesh.Points[tri[0]];
  return Normalized(Cross(mesh.Points[tri[1]] - a, mesh.Points[tri[2]] - a));
}

TriangleAdjacency ComputeTriangleAdjacency(const TriangleMesh& mesh, double featureAngle)
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
  // Each triangle's normal once, not once per edge.
  std::vector<Point3> normals(nt);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t t = range.begin(); t != range.end(); ++t)
      {
        normals[t] = TriangleNormal(mesh, static_cast<Index>(t));
      }
    });
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
      const Point3 &n1 = normals[t1], &n2 = normals[t2];
      // The angle between the normals is pi minus the dihedral angle for a
      // ridge and the dihedral angle minus pi for a valley.
      if (Dot(n1, n2) < cosFeature)
      {
        const Point3& onEdge = mesh.Points[halfEdges[i].Lo];
        const Point3& opposite = mesh.Points[mesh.Triangles[t2][(k2 + 2) % 3]];
        const EdgeFeature f =
          Dot(n1, opposite - onEdge) < 0.0 ? EdgeFeature::Convex : EdgeFeature::Concave;
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
