// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/WallShapes.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace medialaxis
{
namespace
{
using Point2 = std::array<double, 2>;

void Require(bool condition, const char* message)
{
  if (!condition)
  {
    throw std::invalid_argument(message);
  }
}

int Steps(double length, double spacing)
{
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

// Outlines are built by walking: each step appends the points after the
// current last one, up to and including its end.
struct Walk
{
  std::vector<Point2> Points;
  double Spacing;
  int Resolution;

  void LineTo(const Point2& to)
  {
    const Point2 from = this->Points.back();
    const int n = Steps(std::hypot(to[0] - from[0], to[1] - from[1]), this->Spacing);
    for (int i = 1; i < n; ++i)
    {
      const double s = static_cast<double>(i) / n;
      this->Points.push_back({ from[0] + s * (to[0] - from[0]), from[1] + s * (to[1] - from[1]) });
    }
    this->Points.push_back(to);
  }
  // A quarter circle (or less) around `centre` from angle `start` to `end`,
  // ending exactly at `to` (the point at `end`, without its rounding).
  void ArcTo(const Point2& centre, double radius, double start, double end, const Point2& to)
  {
    const int n = std::max(
      1, static_cast<int>(std::lround(this->Resolution * std::abs(end - start) / (0.5 * Pi))));
    for (int i = 1; i < n; ++i)
    {
      const double a = start + (end - start) * i / n;
      this->Points.push_back(
        { centre[0] + radius * std::cos(a), centre[1] + radius * std::sin(a) });
    }
    this->Points.push_back(to);
  }
  // Back to the first point, which is not repeated.
  std::vector<Point2> Close()
  {
    if (this->Points.back() != this->Points.front())
    {
      this->LineTo(this->Points.front());
    }
    this->Points.pop_back();
    return this->Points;
  }
};

double Cross(const Point2& o, const Point2& a, const Point2& b)
{
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}
}

WallSection TPlateSection(double width, double ribHeight, double thickness, double filletRadius,
  double spacing, int resolution)
{
  RequirePositive(width, "plate width");
  RequirePositive(ribHeight, "rib height");
  RequirePositive(thickness, "wall thickness");
  RequirePositive(spacing, "spacing");
  Require(filletRadius >= 0.0, "the fillet radius must not be negative");
  const double w = 0.5 * width, t = 0.5 * thickness, rho = filletRadius;
  Require(w > t + rho, "the plate must be wider than the rib and its fillets");
  Require(ribHeight > rho, "the rib must be higher than its fillets");
  Walk walk{ { { -w, -t } }, spacing, std::max(resolution, 1) };
  walk.LineTo({ w, -t });
  walk.LineTo({ w, t });
  walk.LineTo({ t + rho, t });
  if (rho > 0.0)
  {
    walk.ArcTo({ t + rho, t + rho }, rho, -0.5 * Pi, -Pi, { t, t + rho });
  }
  walk.LineTo({ t, t + ribHeight });
  walk.LineTo({ -t, t + ribHeight });
  walk.LineTo({ -t, t + rho });
  if (rho > 0.0)
  {
    walk.ArcTo({ -t - rho, t + rho }, rho, 0.0, -0.5 * Pi, { -t - rho, t });
  }
  walk.LineTo({ -w, t });
  WallSection out;
  out.Outline = walk.Close();
  const double corner = rho * rho * (1.0 - 0.25 * Pi);
  out.Area = width * thickness + thickness * ribHeight + 2.0 * corner;
  out.Perimeter = 2.0 * width + 2.0 * thickness + 2.0 * ribHeight + (Pi - 4.0) * rho;
  return out;
}

WallSection LBracketSection(double width, double height, double thickness, double filletRadius,
  double spacing, int resolution)
{
  RequirePositive(width, "plate width");
  RequirePositive(height, "wall height");
  RequirePositive(thickness, "wall thickness");
  RequirePositive(spacing, "spacing");
  Require(filletRadius >= 0.0, "the fillet radius must not be negative");
  const double t = thickness, rho = filletRadius, outer = rho > 0.0 ? rho + t : 0.0;
  Require(
    width > t + rho && height > t + rho, "the plate and the wall must be longer than the bend");
  Walk walk{ { { outer, 0.0 } }, spacing, std::max(resolution, 1) };
  walk.LineTo({ width, 0.0 });
  walk.LineTo({ width, t });
  walk.LineTo({ t + rho, t });
  if (rho > 0.0)
  {
    walk.ArcTo({ t + rho, t + rho }, rho, -0.5 * Pi, -Pi, { t, t + rho });
  }
  walk.LineTo({ t, height });
  walk.LineTo({ 0.0, height });
  walk.LineTo({ 0.0, outer });
  if (rho > 0.0)
  {
    walk.ArcTo({ outer, outer }, outer, Pi, 1.5 * Pi, { outer, 0.0 });
  }
  WallSection out;
  out.Outline = walk.Close();
  const double cut = 1.0 - 0.25 * Pi;
  out.Area = width * t + t * (height - t) + (rho * rho - outer * outer) * cut;
  out.Perimeter = 2.0 * width + 2.0 * height + (0.5 * Pi - 2.0) * (rho + outer);
  return out;
}

WallSection WedgePlateSection(
  double width, double startThickness, double endThickness, double spacing)
{
  RequirePositive(width, "plate width");
  RequirePositive(startThickness, "start thickness");
  RequirePositive(endThickness, "end thickness");
  RequirePositive(spacing, "spacing");
  const double w = 0.5 * width, a = 0.5 * startThickness, b = 0.5 * endThickness;
  Walk walk{ { { -w, -a } }, spacing, 1 };
  walk.LineTo({ w, -b });
  walk.LineTo({ w, b });
  walk.LineTo({ -w, a });
  WallSection out;
  out.Outline = walk.Close();
  out.Area = width * (a + b);
  out.Perimeter = 2.0 * std::hypot(width, b - a) + 2.0 * (a + b);
  return out;
}

// Ear clipping, the best-shaped ear first: the caps are small simple
// polygons, for which a constrained Delaunay triangulation (CGAL) would cost
// a translation unit of its own.
std::vector<std::array<Index, 3>> TriangulatePolygon(const std::vector<Point2>& polygon)
{
  std::vector<Index> left(polygon.size());
  for (std::size_t i = 0; i < left.size(); ++i)
  {
    left[i] = static_cast<Index>(i);
  }
  double scale = 0.0;
  for (const Point2& p : polygon)
  {
    scale = std::max({ scale, std::abs(p[0]), std::abs(p[1]) });
  }
  const double tiny = 1e-12 * scale * scale;
  std::vector<std::array<Index, 3>> out;
  while (left.size() > 3)
  {
    const std::size_t n = left.size();
    std::size_t best = n;
    double bestQuality = -1.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const Point2 &a = polygon[left[(i + n - 1) % n]], &b = polygon[left[i]],
                   &c = polygon[left[(i + 1) % n]];
      const double area = Cross(a, b, c);
      if (area <= tiny)
      {
        continue; // reflex or flat
      }
      bool empty = true;
      for (std::size_t j = 0; j < n && empty; ++j)
      {
        if (j == i || j == (i + 1) % n || j == (i + n - 1) % n)
        {
          continue;
        }
        const Point2& p = polygon[left[j]];
        // (closed: a vertex on the diagonal blocks the ear too)
        empty = !(Cross(a, b, p) >= -tiny && Cross(b, c, p) >= -tiny && Cross(c, a, p) >= -tiny);
      }
      if (!empty)
      {
        continue;
      }
      const double edges = std::hypot(b[0] - a[0], b[1] - a[1]) +
        std::hypot(c[0] - b[0], c[1] - b[1]) + std::hypot(a[0] - c[0], a[1] - c[1]);
      const double quality = area / (edges * edges);
      if (quality > bestQuality)
      {
        bestQuality = quality;
        best = i;
      }
    }
    if (best == n)
    {
      throw std::logic_error("polygon triangulation found no ear: the outline is not simple");
    }
    out.push_back({ left[(best + n - 1) % n], left[best], left[(best + 1) % n] });
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
  }
  out.push_back({ left[0], left[1], left[2] });
  return out;
}

TriangleMesh ExtrudeSection(const WallSection& section, double length, double spacing)
{
  RequirePositive(length, "extrusion length");
  RequirePositive(spacing, "spacing");
  const std::vector<Point2>& outline = section.Outline;
  const std::size_t m = outline.size();
  Require(m >= 3, "a section needs three points or more");
  const int steps = Steps(length, spacing);
  TriangleMesh mesh;
  for (int k = 0; k <= steps; ++k)
  {
    const double x = -0.5 * length + length * k / steps;
    for (const Point2& p : outline)
    {
      mesh.Points.push_back({ x, p[0], p[1] });
    }
  }
  auto id = [m](int k, std::size_t i) { return static_cast<Index>(k * m + i % m); };
  for (int k = 0; k < steps; ++k)
  {
    for (std::size_t i = 0; i < m; ++i)
    {
      // Outward for a counter-clockwise outline (see WallShapes.h).
      mesh.Triangles.push_back({ id(k, i), id(k, i + 1), id(k + 1, i + 1) });
      mesh.Triangles.push_back({ id(k, i), id(k + 1, i + 1), id(k + 1, i) });
    }
  }
  for (const auto& t : TriangulatePolygon(outline))
  {
    mesh.Triangles.push_back({ id(steps, t[0]), id(steps, t[1]), id(steps, t[2]) }); // +x
    mesh.Triangles.push_back({ id(0, t[0]), id(0, t[2]), id(0, t[1]) });             // -x
  }
  return mesh;
}

AreaVolume ExtrudedAreaVolume(const WallSection& section, double length)
{
  return { 2.0 * section.Area + section.Perimeter * length, section.Area * length };
}
}
