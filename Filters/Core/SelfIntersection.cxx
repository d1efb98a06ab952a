// SPDX-License-Identifier: GPL-3.0-or-later
#include "SelfIntersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <iterator>

namespace medialaxis
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

template <class Object>
CGAL::Bbox_3 BoxOf(const Object& object)
{
  return object.bbox();
}
CGAL::Bbox_3 BoxOf(const std::vector<Kernel::Point_3>& polygon)
{
  return CGAL::bbox_3(polygon.begin(), polygon.end());
}
}

std::vector<TriangleCrossing> FindSelfIntersections(
  const std::vector<Point3>& points, const std::vector<Triangle>& triangles)
{
  // Only the points the triangles use, renumbered in first-use order.
  std::vector<Index> newId(points.size(), -1);
  std::vector<Kernel::Point_3> used;
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(triangles.size());
  for (const Triangle& t : triangles)
  {
    std::array<std::size_t, 3> face;
    for (int k = 0; k < 3; ++k)
    {
      Index& id = newId[t[k]];
      if (id < 0)
      {
        id = static_cast<Index>(used.size());
        const Point3& p = points[t[k]];
        used.emplace_back(p[0], p[1], p[2]);
      }
      face[k] = static_cast<std::size_t>(id);
    }
    faces.push_back(face);
  }
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(used, faces, mesh);

  // The soup's faces become the mesh's faces in the same order. Sequential:
  // CGAL's parallel version was twice as slow on two busy cores.
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> crossing;
  CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(crossing));
  std::vector<TriangleCrossing> pairs;
  pairs.reserve(crossing.size());
  auto triangleOf = [&](Mesh::Face_index f)
  {
    const auto& t = faces[f.idx()];
    return Kernel::Triangle_3(used[t[0]], used[t[1]], used[t[2]]);
  };
  for (const auto& [f, g] : crossing)
  {
    TriangleCrossing c;
    c.A = static_cast<Index>(std::min(f.idx(), g.idx()));
    c.B = static_cast<Index>(std::max(f.idx(), g.idx()));
    // Where they meet: a point, segment, triangle or polygon (inexact
    // constructions suffice for its extent). Crossings the construction
    // misses (rounding) fall back to the two triangles' common box.
    CGAL::Bbox_3 box;
    const auto meet = CGAL::intersection(triangleOf(f), triangleOf(g));
    if (meet)
    {
      box = boost::apply_visitor([](const auto& x) { return BoxOf(x); }, *meet);
    }
    else
    {
      box = triangleOf(f).bbox() + triangleOf(g).bbox();
    }
    c.Lo = { box.xmin(), box.ymin(), box.zmin() };
    c.Hi = { box.xmax(), box.ymax(), box.zmax() };
    pairs.push_back(c);
  }
  std::sort(pairs.begin(), pairs.end(),
    [](const TriangleCrossing& x, const TriangleCrossing& y)
    { return x.A != y.A ? x.A < y.A : x.B < y.B; });
  return pairs;
}
}
