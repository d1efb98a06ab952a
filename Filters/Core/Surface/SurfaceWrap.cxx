// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/SurfaceWrap.h"

#include "Surface/CgalTriangleMesh.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <array>
#include <cmath>
#include <exception>
#include <vector>

namespace medialaxis
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using KPoint = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<KPoint>;
using KTriangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<KTriangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
}

SurfaceWrapResult WrapSurface(const TriangleMesh& input, double alpha, double offset)
{
  SurfaceWrapResult result;
  result.Alpha = alpha;
  result.Offset = offset;
  if (!(alpha > 0.0) || !(offset > 0.0) || !std::isfinite(alpha) || !std::isfinite(offset))
  {
    result.Error = "the wrap needs a positive alpha and offset";
    return result;
  }
  if (input.Triangles.empty())
  {
    result.Error = "there is no triangle to wrap";
    return result;
  }
  std::vector<KPoint> points;
  points.reserve(input.Points.size());
  for (const Point3& p : input.Points)
  {
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::array<std::size_t, 3>> faces;
  std::vector<KTriangle> triangles;
  faces.reserve(input.Triangles.size());
  for (const Triangle& t : input.Triangles)
  {
    faces.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
      static_cast<std::size_t>(t[2]) });
    triangles.emplace_back(points[t[0]], points[t[1]], points[t[2]]);
  }
  Mesh wrap;
  try
  {
    CGAL::alpha_wrap_3(points, faces, alpha, offset, wrap);
  }
  catch (const std::exception& e)
  {
    result.Error = std::string("the wrap failed (") + e.what() + ")";
    return result;
  }
  if (wrap.number_of_faces() == 0)
  {
    result.Error = "the wrap is empty";
    return result;
  }

  if (!ToTriangleMesh(wrap, result.Surface))
  {
    result.Error = "the wrap has a face that is not a triangle";
    return result;
  }

  // How far the wrap strays from the input: at its vertices and the
  // centroids of its triangles (it bridges concave parts narrower than
  // alpha, farther from the input than the offset).
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  double largest2 = 0.0;
  for (const Point3& p : result.Surface.Points)
  {
    largest2 = std::max(largest2, tree.squared_distance(KPoint(p[0], p[1], p[2])));
  }
  for (const Triangle& t : result.Surface.Triangles)
  {
    const Point3& a = result.Surface.Points[t[0]];
    const Point3& b = result.Surface.Points[t[1]];
    const Point3& c = result.Surface.Points[t[2]];
    const KPoint centroid(
      (a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0, (a[2] + b[2] + c[2]) / 3.0);
    largest2 = std::max(largest2, tree.squared_distance(centroid));
  }
  result.LargestDeviation = std::sqrt(largest2);
  return result;
}
}
