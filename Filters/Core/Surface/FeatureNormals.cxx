// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/FeatureNormals.h"

#include "Geometry/Vec3.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
// For every triangle, the triangles sharing at least one vertex with it
// (itself included), in increasing order, as offsets into one list.
void VertexRingTriangles(
  const TriangleMesh& mesh, std::vector<Index>& offsets, std::vector<Index>& ring)
{
  const std::size_t nv = mesh.Points.size(), nt = mesh.Triangles.size();
  std::vector<Index> firstOfVertex(nv + 1, 0);
  for (const Triangle& tri : mesh.Triangles)
  {
    for (Index v : tri)
    {
      ++firstOfVertex[v + 1];
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    firstOfVertex[v + 1] += firstOfVertex[v];
  }
  std::vector<Index> trianglesOfVertex(firstOfVertex[nv]);
  std::vector<Index> fill(firstOfVertex.begin(), firstOfVertex.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (Index v : mesh.Triangles[t])
    {
      trianglesOfVertex[fill[v]++] = static_cast<Index>(t);
    }
  }
  offsets.assign(1, 0);
  offsets.reserve(nt + 1);
  ring.clear();
  std::vector<Index> scratch;
  for (std::size_t t = 0; t < nt; ++t)
  {
    scratch.clear();
    for (Index v : mesh.Triangles[t])
    {
      scratch.insert(scratch.end(), trianglesOfVertex.begin() + firstOfVertex[v],
        trianglesOfVertex.begin() + firstOfVertex[v + 1]);
    }
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    ring.insert(ring.end(), scratch.begin(), scratch.end());
    offsets.push_back(static_cast<Index>(ring.size()));
  }
}
}

std::vector<Point3> BilateralFaceNormals(
  const TriangleMesh& mesh, int iterations, double rangeSigma)
{
  const std::size_t nt = mesh.Triangles.size();
  std::vector<Point3> normals(nt);
  std::vector<double> area(nt);
  std::vector<Point3> centroid(nt);
  double edgeLengthSum = 0.0;
  for (std::size_t t = 0; t < nt; ++t)
  {
    const Triangle& tri = mesh.Triangles[t];
    const Point3 &a = mesh.Points[tri[0]], &b = mesh.Points[tri[1]], &c = mesh.Points[tri[2]];
    const Point3 cross = Cross(b - a, c - a);
    area[t] = 0.5 * Norm(cross);
    normals[t] = area[t] > 0.0 ? (0.5 / area[t]) * cross : Point3{ 0.0, 0.0, 0.0 };
    centroid[t] = (1.0 / 3.0) * (a + b + c);
    edgeLengthSum += Norm(b - a) + Norm(c - b) + Norm(a - c);
  }
  if (iterations <= 0 || nt == 0)
  {
    return normals;
  }
  // Every interior edge is counted twice, like every boundary edge's
  // neighbours: the mean over half-edges is the mean edge length.
  const double spatialSigma = edgeLengthSum / (3.0 * static_cast<double>(nt));
  const double spatialScale = -0.5 / (spatialSigma * spatialSigma);
  const double rangeScale = -0.5 / (rangeSigma * rangeSigma);

  std::vector<Index> offsets, ring;
  VertexRingTriangles(mesh, offsets, ring);
  // The spatial and area factors do not change between iterations.
  std::vector<double> fixedWeight(ring.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, 1024),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t t = range.begin(); t < range.end(); ++t)
      {
        for (Index i = offsets[t]; i < offsets[t + 1]; ++i)
        {
          const Index u = ring[i];
          fixedWeight[i] = area[u] * std::exp(spatialScale * Distance2(centroid[t], centroid[u]));
        }
      }
    });
  std::vector<Point3> next(nt);
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, 1024),
      [&](const tbb::blocked_range<std::size_t>& range)
      {
        for (std::size_t t = range.begin(); t < range.end(); ++t)
        {
          Point3 sum{ 0.0, 0.0, 0.0 };
          for (Index i = offsets[t]; i < offsets[t + 1]; ++i)
          {
            const Point3& n = normals[ring[i]];
            sum = sum + fixedWeight[i] * std::exp(rangeScale * Distance2(normals[t], n)) * n;
          }
          const double length = Norm(sum);
          next[t] = length > 0.0 ? (1.0 / length) * sum : normals[t];
        }
      });
    normals.swap(next);
  }
  return normals;
}
}
