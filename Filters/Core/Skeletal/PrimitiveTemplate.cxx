// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeletal/PrimitiveTemplate.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace medialaxis
{
namespace
{
// Two unit vectors perpendicular to unit `axis` and to each other.
void Frame(const Point3& axis, Point3& e1, Point3& e2)
{
  const Point3 helper = std::abs(axis[0]) < 0.9 ? Point3{ 1, 0, 0 } : Point3{ 0, 1, 0 };
  e1 = Normalized(Cross(axis, helper));
  e2 = Cross(axis, e1);
}
}

PrimitiveTemplate MakeVertexTemplate(const Point3& centre, int subdivisions)
{
  if (subdivisions < 0 || subdivisions > 6)
  {
    throw std::invalid_argument("vertex template: subdivisions must be in [0, 6]");
  }
  // The icosahedron, then each triangle split in four with the new points
  // pushed onto the sphere.
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point3> points = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 },
    { 0, -1, g }, { 0, 1, g }, { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 },
    { -g, 0, -1 }, { -g, 0, 1 } };
  for (Point3& p : points)
  {
    p = Normalized(p);
  }
  std::vector<Triangle> triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
    { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 },
    { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 },
    { 8, 6, 7 }, { 9, 8, 1 } };
  for (int level = 0; level < subdivisions; ++level)
  {
    std::map<std::pair<Index, Index>, Index> middle;
    auto midpoint = [&](Index a, Index b)
    {
      const auto key = std::minmax(a, b);
      const auto found = middle.find(key);
      if (found != middle.end())
      {
        return found->second;
      }
      const Index m = static_cast<Index>(points.size());
      points.push_back(Normalized(points[a] + points[b]));
      middle.emplace(key, m);
      return m;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * triangles.size());
    for (const Triangle& t : triangles)
    {
      const Index ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.push_back({ t[0], ab, ca });
      finer.push_back({ t[1], bc, ab });
      finer.push_back({ t[2], ca, bc });
      finer.push_back({ ab, bc, ca });
    }
    triangles.swap(finer);
  }
  PrimitiveTemplate shape;
  shape.Element = SkeletalElement::Vertex;
  shape.Base.assign(points.size(), centre);
  shape.Direction = std::move(points);
  shape.Triangles = std::move(triangles);
  return shape;
}

PrimitiveTemplate MakeEdgeTemplate(const Point3& a, const Point3& b, int around, double spacing)
{
  const double length = Norm(b - a);
  if (!(length > 0.0) || around < 8 || !(spacing > 0.0))
  {
    throw std::invalid_argument(
      "edge template: the edge must have a length, at least 8 directions around and a spacing");
  }
  const Point3 axis = (1.0 / length) * (b - a);
  Point3 e1, e2;
  Frame(axis, e1, e2);
  PrimitiveTemplate shape;
  shape.Element = SkeletalElement::Edge;
  auto ring = [&](const Point3& base, double latitude, double side)
  {
    const Index first = static_cast<Index>(shape.Base.size());
    for (int k = 0; k < around; ++k)
    {
      const double angle = 2.0 * Pi * k / around;
      shape.Base.push_back(base);
      shape.Direction.push_back(std::cos(latitude) * (std::cos(angle) * e1 + std::sin(angle) * e2) +
        (side * std::sin(latitude)) * axis);
    }
    return first;
  };
  // Quads between two rings of `around` vertices, outward for the ring
  // order (first towards second along the axis when forward).
  auto band = [&](Index first, Index second, bool forward)
  {
    for (int k = 0; k < around; ++k)
    {
      const Index a0 = first + k, a1 = first + (k + 1) % around;
      const Index b0 = second + k, b1 = second + (k + 1) % around;
      if (forward)
      {
        shape.Triangles.push_back({ a0, a1, b1 });
        shape.Triangles.push_back({ a0, b1, b0 });
      }
      else
      {
        shape.Triangles.push_back({ a0, b1, a1 });
        shape.Triangles.push_back({ a0, b0, b1 });
      }
    }
  };
  auto fan = [&](Index ringFirst, Index pole, bool forward)
  {
    for (int k = 0; k < around; ++k)
    {
      const Index a0 = ringFirst + k, a1 = ringFirst + (k + 1) % around;
      shape.Triangles.push_back(forward ? Triangle{ a0, a1, pole } : Triangle{ a0, pole, a1 });
    }
  };
  const int segments = std::max(1, static_cast<int>(std::ceil(length / spacing)));
  std::vector<Index> rings;
  for (int s = 0; s <= segments; ++s)
  {
    rings.push_back(ring(a + (length * s / segments) * axis, 0.0, 1.0));
  }
  for (int s = 0; s < segments; ++s)
  {
    band(rings[s], rings[s + 1], true);
  }
  // The hemispheres beyond the ends: latitude rings towards each pole.
  const int latitudes = std::max(2, around / 4);
  for (int end = 0; end < 2; ++end)
  {
    const double side = end == 0 ? -1.0 : 1.0;
    const Point3& base = end == 0 ? a : b;
    Index previous = end == 0 ? rings.front() : rings.back();
    for (int l = 1; l < latitudes; ++l)
    {
      const Index next = ring(base, 0.5 * Pi * l / latitudes, side);
      // Forward along the axis at b's end, backward at a's.
      band(previous, next, end == 1);
      previous = next;
    }
    const Index pole = static_cast<Index>(shape.Base.size());
    shape.Base.push_back(base);
    shape.Direction.push_back(side * axis);
    fan(previous, pole, end == 1);
  }
  return shape;
}

PrimitiveTemplate MakeTriangleTemplate(
  const Point3& a, const Point3& b, const Point3& c, int around, double spacing)
{
  const Point3 normal = Cross(b - a, c - a);
  const double longest = std::max({ Norm(b - a), Norm(c - b), Norm(a - c) });
  if (!(Norm(normal) > 1e-12 * longest * longest) || around < 8 || !(spacing > 0.0))
  {
    throw std::invalid_argument("triangle template: the triangle must have an area, at least 8 "
                                "directions around and a spacing");
  }
  const Point3 n = Normalized(normal);
  const std::array<Point3, 3> corner = { a, b, c };
  PrimitiveTemplate shape;
  shape.Element = SkeletalElement::Triangle;
  auto add = [&](const Point3& base, const Point3& direction)
  {
    shape.Base.push_back(base);
    shape.Direction.push_back(direction);
    return static_cast<Index>(shape.Base.size() - 1);
  };

  // The two faces: a barycentric grid of s segments per edge, +n on top
  // and -n below; grid[(i, j)] is a + i/s (b - a) + j/s (c - a).
  const int s = std::max(1, static_cast<int>(std::ceil(longest / spacing)));
  auto gridPoint = [&](int i, int j)
  { return a + (static_cast<double>(i) / s) * (b - a) + (static_cast<double>(j) / s) * (c - a); };
  std::map<std::pair<int, int>, Index> top, bottom;
  for (int i = 0; i <= s; ++i)
  {
    for (int j = 0; i + j <= s; ++j)
    {
      top[{ i, j }] = add(gridPoint(i, j), n);
      bottom[{ i, j }] = add(gridPoint(i, j), -1.0 * n);
    }
  }
  for (int i = 0; i < s; ++i)
  {
    for (int j = 0; i + j < s; ++j)
    {
      shape.Triangles.push_back({ top[{ i, j }], top[{ i + 1, j }], top[{ i, j + 1 }] });
      shape.Triangles.push_back({ bottom[{ i, j }], bottom[{ i, j + 1 }], bottom[{ i + 1, j }] });
      if (i + j + 1 < s)
      {
        shape.Triangles.push_back({ top[{ i + 1, j }], top[{ i + 1, j + 1 }], top[{ i, j + 1 }] });
        shape.Triangles.push_back(
          { bottom[{ i + 1, j }], bottom[{ i, j + 1 }], bottom[{ i + 1, j + 1 }] });
      }
    }
  }
  // The outline, counter-clockwise about n: at each corner an arc of
  // in-plane directions from the previous edge's outward normal to the
  // next one's, then the edge's inner grid points. Each outline point keeps
  // its grid position (for the faces' rims).
  struct OutlinePoint
  {
    Point3 Base, Out;
    std::pair<int, int> Grid;
  };
  auto gridOf = [&](int edge, int step) -> std::pair<int, int>
  {
    // Along edge `edge` (0: ab, 1: bc, 2: ca), `step` of s from its start.
    return edge == 0 ? std::pair<int, int>{ step, 0 }
      : edge == 1    ? std::pair<int, int>{ s - step, step }
                     : std::pair<int, int>{ 0, s - step };
  };
  auto outward = [&](int edge)
  { return Normalized(Cross(corner[(edge + 1) % 3] - corner[edge], n)); };
  const double arcStep = 2.0 * Pi / around;
  std::vector<OutlinePoint> outline;
  for (int k = 0; k < 3; ++k)
  {
    const Point3 from = outward((k + 2) % 3), to = outward(k);
    const double exterior = std::acos(std::clamp(Dot(from, to), -1.0, 1.0));
    const int steps = std::max(1, static_cast<int>(std::ceil(exterior / arcStep)));
    const Point3 turn = Cross(n, from);
    for (int t = 0; t <= steps; ++t)
    {
      const double angle = exterior * t / steps;
      outline.push_back(
        { corner[k], std::cos(angle) * from + std::sin(angle) * turn, gridOf(k, 0) });
    }
    for (int step = 1; step < s; ++step)
    {
      outline.push_back(
        { gridPoint(gridOf(k, step).first, gridOf(k, step).second), to, gridOf(k, step) });
    }
  }
  // Latitude rings from -n to +n over the outline.
  const int latitudes = std::max(2, around / 2);
  const std::size_t count = outline.size();
  std::vector<Index> rings;
  for (int l = 1; l < latitudes; ++l)
  {
    const double phi = -0.5 * Pi + Pi * l / latitudes;
    rings.push_back(static_cast<Index>(shape.Base.size()));
    for (const OutlinePoint& o : outline)
    {
      add(o.Base, std::cos(phi) * o.Out + std::sin(phi) * n);
    }
  }
  auto ringVertex = [&](int l, std::size_t k) { return rings[l] + static_cast<Index>(k % count); };
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::size_t next = (k + 1) % count;
    const bool sameBase = outline[k].Grid == outline[next].Grid;
    // The bottom face's rim to the lowest ring.
    const Index b0 = bottom[outline[k].Grid], b1 = bottom[outline[next].Grid];
    if (!sameBase)
    {
      shape.Triangles.push_back({ b0, b1, ringVertex(0, next) });
    }
    shape.Triangles.push_back({ b0, ringVertex(0, next), ringVertex(0, k) });
    for (int l = 0; l + 1 < static_cast<int>(rings.size()); ++l)
    {
      shape.Triangles.push_back({ ringVertex(l, k), ringVertex(l, next), ringVertex(l + 1, next) });
      shape.Triangles.push_back(
        { ringVertex(l, k), ringVertex(l + 1, next), ringVertex(l + 1, k) });
    }
    // The highest ring to the top face's rim.
    const int last = static_cast<int>(rings.size()) - 1;
    const Index t0 = top[outline[k].Grid], t1 = top[outline[next].Grid];
    shape.Triangles.push_back({ ringVertex(last, k), ringVertex(last, next), t1 });
    if (!sameBase)
    {
      shape.Triangles.push_back({ ringVertex(last, k), t1, t0 });
    }
  }
  return shape;
}

PrimitiveTemplate MakeElementTemplate(SkeletalElement element, const std::array<Point3, 3>& corners,
  int vertexSubdivisions, int around, double spacing)
{
  switch (element)
  {
    case SkeletalElement::Vertex:
      return MakeVertexTemplate(corners[0], vertexSubdivisions);
    case SkeletalElement::Edge:
      return MakeEdgeTemplate(corners[0], corners[1], around, spacing);
    default:
      return MakeTriangleTemplate(corners[0], corners[1], corners[2], around, spacing);
  }
}

std::vector<Point3> PrimitivePoints(
  const PrimitiveTemplate& shape, const std::vector<double>& radius)
{
  std::vector<Point3> points(shape.Base.size());
  for (std::size_t j = 0; j < points.size(); ++j)
  {
    points[j] = shape.Base[j] + radius[j] * shape.Direction[j];
  }
  return points;
}
}
