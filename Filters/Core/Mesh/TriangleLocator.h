// SPDX-License-Identifier: GPL-3.0-or-later
// Closest point on a triangle mesh through a bounding-box hierarchy over its
// triangles (BoxTree.h). Queries are const and thread-safe.
#ifndef medialaxis_TriangleLocator_h
#define medialaxis_TriangleLocator_h

#include "Geometry/BoxTree.h"
#include "Geometry/ClosestPoint.h"
#include "Mesh/PolygonMesh.h"

#include <cmath>
#include <limits>

namespace medialaxis
{
class TriangleLocator
{
public:
  /// Keeps a reference to `mesh`: it must outlive the locator.
  explicit TriangleLocator(const TriangleMesh& mesh)
    : Mesh(mesh)
  {
    std::vector<Box> boxes(mesh.Triangles.size());
    for (std::size_t t = 0; t < boxes.size(); ++t)
    {
      for (Index v : mesh.Triangles[t])
      {
        boxes[t].Extend(mesh.Points[v]);
      }
    }
    this->Tree.Build(boxes);
  }

  /// Distance from p to the nearest triangle (infinity for an empty mesh).
  double Distance(const Point3& p) const
  {
    double best2 = std::numeric_limits<double>::infinity();
    this->Tree.Search([&](const BoxTree::Node& n) { return SquaredDistanceToBox(p, n.Bounds); },
      [&](std::uint32_t t)
      {
        const Triangle& tri = this->Mesh.Triangles[t];
        const Point3 q = ClosestPointOnTriangle(
          p, this->Mesh.Points[tri[0]], this->Mesh.Points[tri[1]], this->Mesh.Points[tri[2]]);
        best2 = std::min(best2, Distance2(p, q));
        return false;
      },
      best2);
    return std::sqrt(best2);
  }

private:
  const TriangleMesh& Mesh;
  BoxTree Tree;
};
}

#endif
