// SPDX-License-Identifier: GPL-3.0-or-later
// Queries on the closed surface for the Voronoi stage (inside tests, distance,
// segment crossings, nearest triangle) over one CGAL AABB tree. Included by
// VoronoiMedialAxis.cxx alone: CGAL's AABB tree is slow to compile, so it
// stays in that one translation unit.
#ifndef medialaxis_SurfaceQueries_h
#define medialaxis_SurfaceQueries_h

#include "Geometry/Vec3.h"
#include "Mesh/PolygonMesh.h"
#include "Mesh/TriangleAdjacency.h"

#include <CGAL/AABB_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/internal/Side_of_triangle_mesh/Point_inside_vertical_ray_cast.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace medialaxis
{
namespace cgal_surface
{
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using KPoint = K::Point_3;

Point3 ToPoint(const KPoint& p)
{
  return { p.x(), p.y(), p.z() };
}
KPoint ToKernel(const Point3& p)
{
  return { p[0], p[1], p[2] };
}

// The AABB tree's primitives are the surface's triangle numbers, read from
// the TriangleMesh itself (no CGAL copy of the mesh: 30 MB less on a
// 268,686-triangle surface). Corners and reference points are those CGAL's
// face-graph primitive gives a face added as (a, b, c), so the tree, and
// every answer, is the same as over a Surface_mesh.
struct TriangleOfIndex
{
  using key_type = Index;
  using value_type = K::Triangle_3;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const TriangleMesh* Surface = nullptr;
  friend value_type get(const TriangleOfIndex& map, Index t)
  {
    const Triangle& tri = map.Surface->Triangles[t];
    const auto& p = map.Surface->Points;
    return value_type(KPoint(p[tri[0]][0], p[tri[0]][1], p[tri[0]][2]),
      KPoint(p[tri[1]][0], p[tri[1]][1], p[tri[1]][2]),
      KPoint(p[tri[2]][0], p[tri[2]][1], p[tri[2]][2]));
  }
};
struct FirstCornerOfIndex
{
  using key_type = Index;
  using value_type = KPoint;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const TriangleMesh* Surface = nullptr;
  friend value_type get(const FirstCornerOfIndex& map, Index t)
  {
    const Point3& p = map.Surface->Points[map.Surface->Triangles[t][0]];
    return value_type(p[0], p[1], p[2]);
  }
};
using Primitive =
  CGAL::AABB_primitive<Index, TriangleOfIndex, FirstCornerOfIndex, CGAL::Tag_true, CGAL::Tag_false>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
using SideOfTree = CGAL::internal::Point_inside_vertical_ray_cast<K, Tree>;

// Surface queries: inside test by ray casting and distance to the surface,
// over one AABB tree built on first use.
class SurfaceQueries
{
public:
  explicit SurfaceQueries(const TriangleMesh& surface)
    : Surface(surface)
  {
  }

  void Build()
  {
    if (this->TreePtr)
    {
      return;
    }
    const Index triangles = static_cast<Index>(this->Surface.Triangles.size());
    this->TreePtr = std::make_unique<Tree>(boost::counting_iterator<Index>(0),
      boost::counting_iterator<Index>(triangles), TriangleOfIndex{ &this->Surface },
      FirstCornerOfIndex{ &this->Surface });
    this->TreePtr->build();
    this->TreePtr->accelerate_distance_queries();

    // Pseudo-normals: faces, and angle-weighted at vertices.
    const std::size_t nt = this->Surface.Triangles.size();
    this->Adjacency = ComputeTriangleAdjacency(this->Surface, 3.14159265358979);
    this->FaceNormals.resize(nt);
    this->VertexNormals.assign(this->Surface.Points.size(), Point3{ 0.0, 0.0, 0.0 });
    for (std::size_t f = 0; f < nt; ++f)
    {
      const Triangle& t = this->Surface.Triangles[f];
      this->FaceNormals[f] = TriangleNormal(this->Surface, static_cast<Index>(f));
      for (int k = 0; k < 3; ++k)
      {
        const Point3& p = this->Surface.Points[t[k]];
        const Point3 e1 = Normalized(this->Surface.Points[t[(k + 1) % 3]] - p);
        const Point3 e2 = Normalized(this->Surface.Points[t[(k + 2) % 3]] - p);
        const double angle = std::acos(std::clamp(Dot(e1, e2), -1.0, 1.0));
        this->VertexNormals[t[k]] = this->VertexNormals[t[k]] + angle * this->FaceNormals[f];
      }
    }
  }

  bool Inside(const Point3& p) const
  {
    return SideOfTree()(ToKernel(p), *this->TreePtr) == CGAL::ON_BOUNDED_SIDE;
  }

  /// Inside test by the closest surface point and the angle-weighted
  /// pseudo-normal of the face, edge or vertex it lies on (Baerentzen and
  /// Aanaes 2005): exact for a closed manifold, and fast for points near
  /// the surface, where the AABB search is short.
  /// `nearPoint` on triangle `nearTriangle` bounds the search.
  bool InsideByPseudoNormal(const Point3& p, const Point3& nearPoint, Index nearTriangle) const
  {
    const Tree::Point_and_primitive_id hint(ToKernel(nearPoint), nearTriangle);
    const auto hit = this->TreePtr->closest_point_and_primitive(ToKernel(p), hint);
    const Point3 q = ToPoint(hit.first);
    const Index f = hit.second;
    const Triangle& t = this->Surface.Triangles[f];
    const Point3 &a = this->Surface.Points[t[0]], &b = this->Surface.Points[t[1]],
                 &c = this->Surface.Points[t[2]];
    // Barycentric coordinates of q.
    const Point3 n = Cross(b - a, c - a);
    const double area2 = Dot(n, n);
    const double w[3] = { Dot(Cross(c - b, q - b), n) / area2, Dot(Cross(a - c, q - c), n) / area2,
      Dot(Cross(b - a, q - a), n) / area2 };
    constexpr double eps = 1e-9;
    const int zeros = (w[0] < eps) + (w[1] < eps) + (w[2] < eps);
    Point3 normal;
    if (zeros == 0)
    {
      normal = this->FaceNormals[f];
    }
    else if (zeros == 1)
    {
      // On the edge opposite the vertex with weight ~0: edge k runs from
      // vertex k to vertex k + 1, so it is opposite vertex k + 2.
      const int opposite = w[0] < eps ? 0 : (w[1] < eps ? 1 : 2);
      const int k = (opposite + 1) % 3;
      const Index across = this->Adjacency.Neighbour[f][k];
      normal =
        this->FaceNormals[f] + (across >= 0 ? this->FaceNormals[across] : this->FaceNormals[f]);
    }
    else
    {
      const int vertex = w[0] >= eps ? 0 : (w[1] >= eps ? 1 : 2);
      normal = this->VertexNormals[t[vertex]];
    }
    return Dot(p - q, normal) < 0.0;
  }

  double Distance(const Point3& p) const
  {
    return std::sqrt(this->TreePtr->squared_distance(ToKernel(p)));
  }

  /// True when the segment from a to b crosses or touches the surface.
  bool Crosses(const Point3& a, const Point3& b) const
  {
    return this->TreePtr->do_intersect(K::Segment_3(ToKernel(a), ToKernel(b)));
  }

  Index NearestTriangle(const Point3& p) const
  {
    return this->TreePtr->closest_point_and_primitive(ToKernel(p)).second;
  }

private:
  const TriangleMesh& Surface;
  std::unique_ptr<Tree> TreePtr;
  TriangleAdjacency Adjacency;
  std::vector<Point3> FaceNormals, VertexNormals;
};
}
}

#endif
