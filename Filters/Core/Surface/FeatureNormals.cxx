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
// The triangles of each vertex, in increasing order, as compressed rows.
struct VertexStars
{
  std::vector<Index> First, Triangles;

  explicit VertexStars(const TriangleMesh& mesh)
  {
    const std::size_t nv = mesh.Points.size(), nt = mesh.Triangles.size();
    this->First.assign(nv + 1, 0);
    for (const Triangle& tri : mesh.Triangles)
    {
      for (Index v : tri)
      {
        ++this->First[v + 1];
      }
    }
    for (std::size_t v = 0; v < nv; ++v)
    {
      this->First[v + 1] += this->First[v];
    }
    this->Triangles.resize(static_cast<std::size_t>(this->First[nv]));
    std::vector<Index> fill(this->First.begin(), this->First.end() - 1);
    for (std::size_t t = 0; t < nt; ++t)
    {
      for (Index v : mesh.Triangles[t])
      {
        this->Triangles[fill[v]++] = static_cast<Index>(t);
      }
    }
  }

  // Calls visit(u) once for every triangle u sharing a vertex with `tri`
  // (itself included), in increasing order: a merge of the three rows.
  template <typename Visit>
  void ForEachInRing(const Triangle& tri, Visit&& visit) const
  {
    const Index* at[3];
    const Index* end[3];
    for (int k = 0; k < 3; ++k)
    {
      at[k] = this->Triangles.data() + this->First[tri[k]];
      end[k] = this->Triangles.data() + this->First[tri[k] + 1];
    }
    while (true)
    {
      bool any = false;
      Index next = 0;
      for (int k = 0; k < 3; ++k)
      {
        if (at[k] != end[k] && (!any || *at[k] < next))
        {
          next = *at[k];
          any = true;
        }
      }
      if (!any)
      {
        return;
      }
      visit(next);
      for (int k = 0; k < 3; ++k)
      {
        while (at[k] != end[k] && *at[k] == next)
        {
          ++at[k];
        }
      }
    }
  }
};
}

std::vector<Point3> BilateralFaceNormals(const TriangleMesh& mesh, int iterations,
  double rangeSigma, const std::vector<std::uint8_t>* needed)
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
  const VertexStars stars(mesh);

  // levels[j]: the triangles iteration j filters. A triangle's normal after
  // the last iteration depends only on the triangles within `iterations`
  // rings of it, so with `needed` iteration j filters those within
  // iterations - 1 - j rings of a needed one; beside a few feature edges,
  // a small part of a large surface.
  std::vector<std::vector<Index>> levels(needed ? iterations : 0);
  if (needed)
  {
    std::vector<std::uint8_t> reached(nt, 0);
    for (std::size_t t = 0; t < nt; ++t)
    {
      if ((*needed)[t])
      {
        levels.back().push_back(static_cast<Index>(t));
        reached[t] = 1;
      }
    }
    for (int j = iterations - 2; j >= 0; --j)
    {
      levels[j] = levels[j + 1];
      for (Index t : levels[j + 1])
      {
        stars.ForEachInRing(mesh.Triangles[t],
          [&](Index u)
          {
            if (!reached[u])
            {
              reached[u] = 1;
              levels[j].push_back(u);
            }
          });
      }
      std::sort(levels[j].begin(), levels[j].end());
    }
  }
  const std::vector<Point3> own = needed ? normals : std::vector<Point3>();
  std::vector<Point3> next(nt);
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    const std::size_t count = needed ? levels[iteration].size() : nt;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024),
      [&](const tbb::blocked_range<std::size_t>& range)
      {
        for (std::size_t i = range.begin(); i < range.end(); ++i)
        {
          const std::size_t t = needed ? static_cast<std::size_t>(levels[iteration][i]) : i;
          Point3 sum{ 0.0, 0.0, 0.0 };
          stars.ForEachInRing(mesh.Triangles[t],
            [&](Index u)
            {
              const Point3& n = normals[u];
              const double spatial =
                area[u] * std::exp(spatialScale * Distance2(centroid[t], centroid[u]));
              sum = sum + spatial * std::exp(rangeScale * Distance2(normals[t], n)) * n;
            });
          const double length = Norm(sum);
          next[t] = length > 0.0 ? (1.0 / length) * sum : normals[t];
        }
      });
    if (needed)
    {
      for (Index t : levels[iteration])
      {
        normals[t] = next[t];
      }
    }
    else
    {
      normals.swap(next);
    }
  }
  if (needed)
  {
    for (std::size_t t = 0; t < nt; ++t)
    {
      if (!(*needed)[t])
      {
        normals[t] = own[t];
      }
    }
  }
  return normals;
}

TriangleAdjacency FeatureAdjacency(const TriangleMesh& mesh, double featureAngle,
  int normalFiltering, std::vector<Point3>* filteredNormals)
{
  TriangleAdjacency adjacency = ComputeTriangleAdjacency(mesh, featureAngle);
  if (normalFiltering <= 0)
  {
    return adjacency;
  }
  const std::size_t nt = mesh.Triangles.size();
  std::vector<std::uint8_t> beside(nt, 0);
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (EdgeFeature f : adjacency.Feature[t])
    {
      if (f != EdgeFeature::None)
      {
        beside[t] = 1;
      }
    }
  }
  std::vector<Point3> filtered = BilateralFaceNormals(mesh, normalFiltering, 0.35, &beside);
  const double cosFeature = std::cos(featureAngle);
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      EdgeFeature& f = adjacency.Feature[t][k];
      if (f == EdgeFeature::Convex &&
        Dot(filtered[t], filtered[adjacency.Neighbour[t][k]]) >= cosFeature)
      {
        f = EdgeFeature::None;
      }
    }
  }
  if (filteredNormals)
  {
    *filteredNormals = std::move(filtered);
  }
  return adjacency;
}
}
