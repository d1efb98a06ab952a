// SPDX-License-Identifier: GPL-3.0-or-later
#include "DelaunayBaseline.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace medialaxis
{
std::size_t DelaunayCellCount(const std::vector<Point3>& points)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> input;
  input.reserve(points.size());
  for (const Point3& p : points)
  {
    input.emplace_back(p[0], p[1], p[2]);
  }
  // Built from the whole range, as the library does: CGAL sorts it spatially.
  const CGAL::Delaunay_triangulation_3<K> delaunay(input.begin(), input.end());
  return delaunay.number_of_finite_cells();
}
}
