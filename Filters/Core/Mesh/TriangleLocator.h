// SPDX-License-Identifier: GPL-3.0-or-later
// Closest point on, and first hit of a ray with, a triangle mesh through a
// bounding-box hierarchy over its triangles (BoxTree.h). Queries are const
// and thread-safe.
#ifndef medialaxis_TriangleLocator_h
#define medialaxis_TriangleLocator_h

#include "Geometry/BoxTree.h"
#include "Geometry/ClosestPoint.h"
#include "Mesh/PolygonMesh.h"

#include <algorithm>
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

  /// Distance from p to the nearest triangle (infinity for an empty mesh),
  /// or `limit` when it is farther: the search prunes what lies beyond.
  double Distance(const Point3& p, double limit = std::numeric_limits<double>::infinity()) const
  {
    return std::min(limit,
      std::sqrt(this
                  ->Closest(
                    p, [](Index) { return true; }, limit)
                  .Distance2));
  }

  struct ClosestHit
  {
    Point3 Point{ 0, 0, 0 };
    double Distance2 = std::numeric_limits<double>::infinity();
    Index Triangle = -1; // -1: no triangle accepted within the limit
  };

  /// The closest point to p on the triangles t with accept(t), nearer than
  /// `limit`.
  template <typename Accept>
  ClosestHit Closest(
    const Point3& p, Accept&& accept, double limit = std::numeric_limits<double>::infinity()) const
  {
    ClosestHit best;
    best.Distance2 = limit * limit;
    this->Tree.Search([&](const BoxTree::Node& n) { return SquaredDistanceToBox(p, n.Bounds); },
      [&](std::uint32_t t)
      {
        if (!accept(static_cast<Index>(t)))
        {
          return false;
        }
        const Triangle& tri = this->Mesh.Triangles[t];
        const Point3 q = ClosestPointOnTriangle(
          p, this->Mesh.Points[tri[0]], this->Mesh.Points[tri[1]], this->Mesh.Points[tri[2]]);
        const double d2 = Distance2(p, q);
        if (d2 < best.Distance2)
        {
          best = { q, d2, static_cast<Index>(t) };
        }
        return false;
      },
      best.Distance2);
    return best;
  }

  /// Calls visit(t) for every triangle t within `radius` of p.
  template <typename Visit>
  void ForEachWithin(const Point3& p, double radius, Visit&& visit) const
  {
    const double radius2 = radius * radius;
    this->Tree.Search([&](const BoxTree::Node& n) { return SquaredDistanceToBox(p, n.Bounds); },
      [&](std::uint32_t t)
      {
        const Triangle& tri = this->Mesh.Triangles[t];
        if (Distance2(p,
              ClosestPointOnTriangle(p, this->Mesh.Points[tri[0]], this->Mesh.Points[tri[1]],
                this->Mesh.Points[tri[2]])) <= radius2)
        {
          visit(static_cast<Index>(t));
        }
        return false;
      },
      std::nextafter(radius2, std::numeric_limits<double>::infinity()));
  }

  /// Whether p lies inside the mesh, which must be closed, outward and free
  /// of self-intersections: the first triangle a ray from p meets faces
  /// away from p. A ray that decides nothing is not used: one that grazes
  /// the triangle it meets, or meets another triangle facing the other way
  /// within 1% further (through an edge where the surface folds back, as a
  /// thin fin or a slightly self-intersecting fold does); the next of three
  /// fixed directions is tried, and if all are undecided they vote. The
  /// directions line up with no axis or common template direction.
  bool Inside(const Point3& p) const
  {
    static const Point3 directions[3] = { Normalized(Point3{ 0.5773, 0.6042, 0.5497 }),
      Normalized(Point3{ -0.6627, 0.2139, 0.7177 }),
      Normalized(Point3{ 0.1453, -0.8919, 0.4283 }) };
    auto cosine = [this](Index triangle, const Point3& direction)
    {
      const Triangle& t = this->Mesh.Triangles[triangle];
      const Point3 normal = Cross(this->Mesh.Points[t[1]] - this->Mesh.Points[t[0]],
        this->Mesh.Points[t[2]] - this->Mesh.Points[t[0]]);
      return Dot(normal, direction) / std::max(Norm(normal), 1e-300);
    };
    int votes = 0;
    for (const Point3& direction : directions)
    {
      const RayHit hit = this->FirstHit(p, direction, 0.0, std::numeric_limits<double>::infinity());
      if (hit.Triangle < 0)
      {
        return false; // a ray that leaves without a hit: outside a closed mesh
      }
      const double first = cosine(hit.Triangle, direction);
      const double slack = 0.01 * hit.Distance;
      const RayHit next = this->FirstHitIf(
        p, direction, 0.0, hit.Distance + slack, [&](Index t) { return t != hit.Triangle; });
      const bool fold =
        next.Triangle >= 0 && (cosine(next.Triangle, direction) > 0.0) != (first > 0.0);
      if (std::abs(first) > 0.01 && !fold)
      {
        return first > 0.0;
      }
      votes += first > 0.0 ? 1 : -1;
    }
    return votes > 0;
  }

  /// Distance from p to the mesh, negative inside (as Inside decides). When
  /// the closest point lies inside a triangle's face, that face's side
  /// decides, which is exact for a closed mesh free of self-intersections
  /// and costs no ray; on an edge or a corner, whose side the adjoining
  /// faces may disagree on, Inside does.
  /// With a `limit`, a farther distance is returned as the limit (its sign
  /// as Inside decides).
  double SignedDistance(
    const Point3& p, double limit = std::numeric_limits<double>::infinity()) const
  {
    const ClosestHit hit = this->Closest(
      p, [](Index) { return true; }, limit);
    if (hit.Triangle < 0)
    {
      return this->Inside(p) ? -limit : limit;
    }
    const double distance = std::sqrt(hit.Distance2);
    const Triangle& t = this->Mesh.Triangles[hit.Triangle];
    const Point3 &a = this->Mesh.Points[t[0]], &b = this->Mesh.Points[t[1]],
                 &c = this->Mesh.Points[t[2]];
    const Point3 normal = Cross(b - a, c - a);
    const double area2 = Dot(normal, normal);
    if (area2 > 0.0)
    {
      // Barycentric coordinates of the closest point: all clearly positive
      // on the face's inside.
      const double u = Dot(Cross(c - b, hit.Point - b), normal) / area2;
      const double v = Dot(Cross(a - c, hit.Point - c), normal) / area2;
      const double side = Dot(p - hit.Point, normal) / std::sqrt(area2);
      if (std::min({ u, v, 1.0 - u - v }) > 1e-6 && std::abs(side) > 1e-9 * distance)
      {
        return side < 0.0 ? -distance : distance;
      }
    }
    return this->Inside(p) ? -distance : distance;
  }

  struct RayHit
  {
    double Distance = std::numeric_limits<double>::infinity(); // along the unit direction
    Index Triangle = -1;                                       // -1: no hit
  };

  /// The nearest triangle crossed by the ray origin + s * direction,
  /// minimumDistance < s < maximumDistance, other than `skipTriangle` (the
  /// one the origin lies on). `direction` must have unit length.
  RayHit FirstHit(const Point3& origin, const Point3& direction, double minimumDistance,
    double maximumDistance, Index skipTriangle = -1) const
  {
    return this->FirstHitIf(origin, direction, minimumDistance, maximumDistance,
      [skipTriangle](Index t) { return t != skipTriangle; });
  }

  /// The same, among the triangles t with accept(t).
  template <typename Accept>
  RayHit FirstHitIf(const Point3& origin, const Point3& direction, double minimumDistance,
    double maximumDistance, Accept&& accept) const
  {
    Point3 inverse;
    for (int k = 0; k < 3; ++k)
    {
      inverse[k] = 1.0 / direction[k]; // +-infinity on axis-parallel rays: the slabs still work
    }
    RayHit hit;
    double best = maximumDistance;
    this->Tree.Search([&](const BoxTree::Node& n)
      { return RayEntry(origin, inverse, n.Bounds, best); },
      [&](std::uint32_t t)
      {
        if (!accept(static_cast<Index>(t)))
        {
          return false;
        }
        const Triangle& tri = this->Mesh.Triangles[t];
        const double s = RayTriangle(origin, direction, this->Mesh.Points[tri[0]],
          this->Mesh.Points[tri[1]], this->Mesh.Points[tri[2]]);
        if (s > minimumDistance && s < best)
        {
          best = s;
          hit = { s, static_cast<Index>(t) };
        }
        return false;
      },
      best);
    return hit;
  }

private:
  // Where the ray enters the box (0 if it starts inside), or infinity if it
  // misses it before `limit` (slab test).
  static double RayEntry(const Point3& origin, const Point3& inverse, const Box& b, double limit)
  {
    double enter = 0.0, leave = limit;
    for (int k = 0; k < 3; ++k)
    {
      if (std::isinf(inverse[k]))
      {
        // A ray parallel to the slab: inside it all along, or never (the
        // products below would be 0 * infinity on its bounding planes).
        if (origin[k] < b.Lo[k] || origin[k] > b.Hi[k])
        {
          return std::numeric_limits<double>::infinity();
        }
        continue;
      }
      double t0 = (b.Lo[k] - origin[k]) * inverse[k], t1 = (b.Hi[k] - origin[k]) * inverse[k];
      if (t0 > t1)
      {
        std::swap(t0, t1);
      }
      enter = t0 > enter ? t0 : enter;
      leave = t1 < leave ? t1 : leave;
    }
    return enter <= leave ? enter : std::numeric_limits<double>::infinity();
  }

  // Ray parameter of the crossing with triangle abc (Moller-Trumbore), or
  // -1 if the ray misses it or runs parallel to it.
  static double RayTriangle(const Point3& origin, const Point3& direction, const Point3& a,
    const Point3& b, const Point3& c)
  {
    const Point3 e1 = b - a, e2 = c - a;
    const Point3 p = Cross(direction, e2);
    const double det = Dot(e1, p);
    if (det == 0.0)
    {
      return -1.0;
    }
    const double inv = 1.0 / det;
    const Point3 s = origin - a;
    // Barycentric tests with a little slack: a ray through a shared edge or
    // vertex must not slip between the triangles by rounding.
    constexpr double Slack = 1e-12;
    const double u = Dot(s, p) * inv;
    if (u < -Slack || u > 1.0 + Slack)
    {
      return -1.0;
    }
    const Point3 q = Cross(s, e1);
    const double v = Dot(direction, q) * inv;
    if (v < -Slack || u + v > 1.0 + Slack)
    {
      return -1.0;
    }
    return Dot(e2, q) * inv;
  }

  const TriangleMesh& Mesh;
  BoxTree Tree;
};
}

#endif
