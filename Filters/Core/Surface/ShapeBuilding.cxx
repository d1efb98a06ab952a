// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/ShapeBuilding.h"

#include "Geometry/Vec3.h"

#include <cmath>

namespace medialaxis
{
// Splits quad (a, b, c, d), given counter-clockwise seen from outside, along
// its shorter diagonal.
void AddQuad(TriangleMesh& mesh, Index a, Index b, Index c, Index d)
{
  if (Distance2(mesh.Points[a], mesh.Points[c]) <= Distance2(mesh.Points[b], mesh.Points[d]))
  {
    mesh.Triangles.push_back({ a, b, c });
    mesh.Triangles.push_back({ a, c, d });
  }
  else
  {
    mesh.Triangles.push_back({ a, b, d });
    mesh.Triangles.push_back({ b, c, d });
  }
}

// Rings of a star-shaped planar cap at height z, from its outline (ring 0,
// whose point ids are given) inward to the centre `centre`: quads between
// rings, a fan at the centre. `up` orients the cap's normal to +z.
void AddCap(TriangleMesh& mesh, const std::vector<Index>& outline, const Point3& centre, int rings,
  bool up, std::vector<int>* labels)
{
  const std::size_t n = outline.size();
  std::vector<Index> previous = outline;
  const std::size_t before = mesh.Triangles.size();
  for (int ring = 1; ring < rings; ++ring)
  {
    const double scale = double(rings - ring) / rings;
    std::vector<Index> current(n);
    for (std::size_t k = 0; k < n; ++k)
    {
      const Point3& p = mesh.Points[outline[k]];
      current[k] = static_cast<Index>(mesh.Points.size());
      mesh.Points.push_back(
        { centre[0] + scale * (p[0] - centre[0]), centre[1] + scale * (p[1] - centre[1]), p[2] });
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      const std::size_t k1 = (k + 1) % n;
      if (up)
      {
        AddQuad(mesh, previous[k], previous[k1], current[k1], current[k]);
      }
      else
      {
        AddQuad(mesh, previous[k], current[k], current[k1], previous[k1]);
      }
    }
    previous.swap(current);
  }
  const Index middle = static_cast<Index>(mesh.Points.size());
  mesh.Points.push_back(centre);
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t k1 = (k + 1) % n;
    if (up)
    {
      mesh.Triangles.push_back({ previous[k], previous[k1], middle });
    }
    else
    {
      mesh.Triangles.push_back({ previous[k], middle, previous[k1] });
    }
  }
  labels->resize(labels->size() + (mesh.Triangles.size() - before), -1);
}

// The surface of revolution around z of `profile` (distance from the axis,
// z), given from the top pole (0, top) to the bottom pole (0, bottom), both
// excluded, with `around` segments per circle. With labels, triangle labels
// follow: -1 at the poles, labelBefore[i + 1] between profile points i and i + 1.
TriangleMesh Revolve(const std::vector<std::array<double, 2>>& profile, double top, double bottom,
  int around, const std::vector<int>* labelBefore, std::vector<int>* labels)
{
  TriangleMesh mesh;
  auto ring = [around](std::size_t i, int k)
  { return static_cast<Index>(i * around + k % around); };
  for (const auto& p : profile)
  {
    for (int k = 0; k < around; ++k)
    {
      const double angle = 2.0 * Pi * k / around;
      mesh.Points.push_back({ p[0] * std::cos(angle), p[0] * std::sin(angle), p[1] });
    }
  }
  auto label = [&](int value)
  {
    if (labels)
    {
      labels->resize(mesh.Triangles.size(), value);
    }
  };
  const Index topPole = static_cast<Index>(mesh.Points.size());
  mesh.Points.push_back({ 0.0, 0.0, top });
  const Index bottomPole = topPole + 1;
  mesh.Points.push_back({ 0.0, 0.0, bottom });
  for (int k = 0; k < around; ++k)
  {
    mesh.Triangles.push_back({ topPole, ring(0, k), ring(0, k + 1) });
  }
  label(-1);
  for (std::size_t i = 0; i + 1 < profile.size(); ++i)
  {
    for (int k = 0; k < around; ++k)
    {
      AddQuad(mesh, ring(i, k), ring(i + 1, k), ring(i + 1, k + 1), ring(i, k + 1));
    }
    label(labelBefore ? (*labelBefore)[i + 1] : -1);
  }
  const std::size_t last = profile.size() - 1;
  for (int k = 0; k < around; ++k)
  {
    mesh.Triangles.push_back({ bottomPole, ring(last, k + 1), ring(last, k) });
  }
  label(-1);
  return mesh;
}
}
