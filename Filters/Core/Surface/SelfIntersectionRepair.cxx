// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/SelfIntersectionRepair.h"

#include "Surface/CgalTriangleMesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>

namespace medialaxis
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Face = Mesh::Face_index;
using OriginMap = Mesh::Property_map<Face, Index>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Passes each face's input triangle on to the pieces it is split into.
struct OriginVisitor : PMP::Corefinement::Default_visitor<Mesh>
{
  OriginMap* Origin = nullptr;
  Index Splitting = -1;

  void before_subface_creations(Face split, const Mesh&)
  {
    this->Splitting = (*this->Origin)[split];
  }
  void after_subface_created(Face created, const Mesh&)
  {
    (*this->Origin)[created] = this->Splitting;
  }
  void after_face_copy(Face from, const Mesh&, Face to, const Mesh&)
  {
    (*this->Origin)[to] = (*this->Origin)[from];
  }
};
}

SelfIntersectionRepairResult RepairSelfIntersections(
  const TriangleMesh& input, const std::vector<TriangleCrossing>& crossings)
{
  SelfIntersectionRepairResult result;
  auto point = [&](Index v)
  {
    const Point3& p = input.Points[v];
    return Kernel::Point_3(p[0], p[1], p[2]);
  };
  for (const TriangleCrossing& c : crossings)
  {
    const Triangle& a = input.Triangles[c.A];
    const Triangle& b = input.Triangles[c.B];
    bool coplanar = true;
    for (int k = 0; coplanar && k < 3; ++k)
    {
      coplanar = CGAL::coplanar(point(a[0]), point(a[1]), point(a[2]), point(b[k]));
    }
    if (coplanar)
    {
      result.Error = "triangles overlap in a common plane, which the exact resolution of the "
                     "crossings does not handle";
      return result;
    }
  }
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertex(input.Points.size());
  std::vector<char> used(input.Points.size(), 0);
  for (const Triangle& t : input.Triangles)
  {
    for (Index v : t)
    {
      used[v] = 1;
    }
  }
  for (std::size_t v = 0; v < input.Points.size(); ++v)
  {
    if (used[v])
    {
      const Point3& p = input.Points[v];
      vertex[v] = mesh.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
    }
  }
  OriginMap origin = mesh.add_property_map<Face, Index>("f:origin", -1).first;
  double inputArea = 0.0;
  for (std::size_t t = 0; t < input.Triangles.size(); ++t)
  {
    const Triangle& tri = input.Triangles[t];
    const Face f = mesh.add_face(vertex[tri[0]], vertex[tri[1]], vertex[tri[2]]);
    if (f == Mesh::null_face())
    {
      result.Error = "the surface is not manifold where the repair needs it";
      return result;
    }
    origin[f] = static_cast<Index>(t);
  }
  inputArea = PMP::area(mesh);

  OriginVisitor visitor;
  visitor.Origin = &origin;
  bool fixed = false;
  try
  {
    fixed = PMP::experimental::autorefine_and_remove_self_intersections(
      mesh, CGAL::parameters::visitor(visitor));
  }
  catch (const std::exception& e)
  {
    result.Error = std::string("the crossing parts could not be resolved (") + e.what() + ")";
    return result;
  }
  if (!fixed)
  {
    result.Error = "the crossing parts could not be resolved into one closed surface";
    return result;
  }
  if (PMP::does_self_intersect(mesh))
  {
    result.Error = "resolving the crossings left triangles that still cross (rounding)";
    return result;
  }

  // Back to our mesh, points in the order CGAL keeps them.
  std::vector<Face> faces;
  if (!ToTriangleMesh(mesh, result.Surface, &faces))
  {
    result.Error = "resolving the crossings left a face that is not a triangle";
    return result;
  }
  for (Face f : faces)
  {
    result.InputTriangle.push_back(origin[f]);
  }
  result.RemovedArea = inputArea - PMP::area(mesh);

  // The outer boundary of the solid holds the input's extreme points: a
  // result inside a smaller box kept inner parts and dropped outer ones:
  // the patches were misclassified, as where neighbouring triangles fold
  // over each other or a part turned inside out pokes through the rest.
  Point3 inLo{ HUGE_VAL, HUGE_VAL, HUGE_VAL }, inHi{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  Point3 outLo = inLo, outHi = inHi;
  for (const Triangle& t : input.Triangles)
  {
    for (Index v : t)
    {
      for (int k = 0; k < 3; ++k)
      {
        inLo[k] = std::min(inLo[k], input.Points[v][k]);
        inHi[k] = std::max(inHi[k], input.Points[v][k]);
      }
    }
  }
  for (const Point3& p : result.Surface.Points)
  {
    for (int k = 0; k < 3; ++k)
    {
      outLo[k] = std::min(outLo[k], p[k]);
      outHi[k] = std::max(outHi[k], p[k]);
    }
  }
  double diagonal2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    diagonal2 += (inHi[k] - inLo[k]) * (inHi[k] - inLo[k]);
  }
  const double tolerance = 1e-9 * std::sqrt(diagonal2);
  for (int k = 0; k < 3; ++k)
  {
    if (std::abs(outLo[k] - inLo[k]) > tolerance || std::abs(outHi[k] - inHi[k]) > tolerance)
    {
      result.Error = "the crossings do not resolve into the boundary of one solid (the result "
                     "lost the input's outermost points)";
      result.InsideInDoubt = true;
      return result;
    }
  }
  return result;
}
}
