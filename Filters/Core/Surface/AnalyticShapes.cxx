// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/AnalyticShapes.h"

#include "Surface/ShapeBuilding.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace medialaxis
{
namespace
{
// Lattice coordinates along one axis, on the surface of the enclosing box:
// the fillet band maps tan-uniformly so that arc segments are equal-angle.
std::vector<double> AxisSamples(double half, double rho, int bandSegments, double spacing)
{
  const double inner = half - rho;
  std::vector<double> band; // offsets beyond the inner half-extent, 0..rho
  if (rho > 0.0)
  {
    for (int i = 0; i <= bandSegments; ++i)
    {
      band.push_back(rho * std::tan(0.25 * Pi * i / bandSegments));
    }
  }
  else
  {
    band.push_back(0.0);
  }
  std::vector<double> samples;
  for (auto it = band.rbegin(); it != band.rend(); ++it)
  {
    samples.push_back(-inner - *it);
  }
  const int innerSegments =
    inner > 0.0 ? std::max(1, static_cast<int>(std::lround(2.0 * inner / spacing))) : 0;
  for (int i = 1; i < innerSegments; ++i)
  {
    samples.push_back(-inner + 2.0 * inner * i / innerSegments);
  }
  for (std::size_t i = (innerSegments == 0 ? 1 : 0); i < band.size(); ++i)
  {
    samples.push_back(inner + band[i]);
  }
  return samples;
}

}

void RequirePositive(double value, const char* what)
{
  if (!(value > 0.0) || !std::isfinite(value))
  {
    throw std::invalid_argument(std::string(what) + " must be positive and finite");
  }
}

TriangleMesh MakeRoundedBox(const Point3& sides, double filletRadius, int resolution)
{
  for (double s : sides)
  {
    RequirePositive(s, "box side");
  }
  const double minHalf = 0.5 * std::min({ sides[0], sides[1], sides[2] });
  if (!(filletRadius >= 0.0) || filletRadius > minHalf * (1.0 + 1e-12))
  {
    throw std::invalid_argument("fillet radius must lie in [0, smallest side / 2]");
  }
  const double rho = std::min(filletRadius, minHalf);
  resolution = std::max(resolution, 2);
  const int bandSegments = (resolution + 1) / 2;
  const double maxSide = std::max({ sides[0], sides[1], sides[2] });
  // Flat parts: edges as long as the fillet's arc segments, but no finer than
  // maxSide / (2 resolution), so that small fillets do not explode the count.
  const double spacing = rho > 0.0
    ? std::max(0.5 * Pi * rho / (2 * bandSegments), 0.5 * maxSide / resolution)
    : maxSide / resolution;

  std::vector<double> axis[3];
  double inner[3];
  for (int a = 0; a < 3; ++a)
  {
    const double half = 0.5 * sides[a];
    // Sides equal to 2 rho have no flat part: avoid a sliver from rounding.
    const double r = (half - rho) <= 1e-12 * half ? half : rho;
    axis[a] = AxisSamples(half, r, bandSegments, spacing);
    inner[a] = half - r;
  }
  const Index n[3] = { static_cast<Index>(axis[0].size()), static_cast<Index>(axis[1].size()),
    static_cast<Index>(axis[2].size()) };

  TriangleMesh mesh;
  std::vector<Index> nodeId(static_cast<std::size_t>(n[0] * n[1] * n[2]), -1);
  auto node = [&](Index i, Index j, Index k)
  {
    Index& id = nodeId[static_cast<std::size_t>((i * n[1] + j) * n[2] + k)];
    if (id < 0)
    {
      const Point3 p{ axis[0][i], axis[1][j], axis[2][k] };
      Point3 q, d;
      double length2 = 0.0;
      for (int a = 0; a < 3; ++a)
      {
        q[a] = std::clamp(p[a], -inner[a], inner[a]);
        d[a] = p[a] - q[a];
        length2 += d[a] * d[a];
      }
      Point3 x = p;
      if (length2 > 0.0 && rho > 0.0)
      {
        const double scale = rho / std::sqrt(length2);
        for (int a = 0; a < 3; ++a)
        {
          x[a] = q[a] + d[a] * scale;
        }
      }
      id = static_cast<Index>(mesh.Points.size());
      mesh.Points.push_back(x);
    }
    return id;
  };

  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      const Index fixed = side == 0 ? 0 : n[a] - 1;
      for (Index u = 0; u + 1 < n[b]; ++u)
      {
        for (Index v = 0; v + 1 < n[c]; ++v)
        {
          Index ids[4];
          const Index uu[4] = { u, u + 1, u + 1, u };
          const Index vv[4] = { v, v, v + 1, v + 1 };
          for (int corner = 0; corner < 4; ++corner)
          {
            Index ijk[3];
            ijk[a] = fixed;
            ijk[b] = uu[corner];
            ijk[c] = vv[corner];
            ids[corner] = node(ijk[0], ijk[1], ijk[2]);
          }
          if (side == 1)
          {
            AddQuad(mesh, ids[0], ids[1], ids[2], ids[3]);
          }
          else
          {
            AddQuad(mesh, ids[0], ids[3], ids[2], ids[1]);
          }
        }
      }
    }
  }
  return mesh;
}

TriangleMesh MakeSphere(double radius, int resolution)
{
  RequirePositive(radius, "sphere radius");
  return MakeRoundedBox({ 2 * radius, 2 * radius, 2 * radius }, radius, resolution);
}

TriangleMesh MakeCapsule(double radius, double axisLength, int resolution)
{
  RequirePositive(radius, "capsule radius");
  if (!(axisLength >= 0.0) || !std::isfinite(axisLength))
  {
    throw std::invalid_argument("capsule axis length must be non-negative and finite");
  }
  return MakeRoundedBox({ 2 * radius, 2 * radius, axisLength + 2 * radius }, radius, resolution);
}

TriangleMesh MakeTorus(double majorRadius, double minorRadius, int resolution)
{
  RequirePositive(majorRadius, "torus major radius");
  RequirePositive(minorRadius, "torus minor radius");
  if (!(minorRadius < majorRadius))
  {
    throw std::invalid_argument("torus minor radius must be smaller than its major radius");
  }
  resolution = std::max(resolution, 2);
  const int nv = 4 * resolution;
  const int nu = std::max(3, static_cast<int>(std::lround(nv * majorRadius / minorRadius)));
  TriangleMesh mesh;
  mesh.Points.reserve(static_cast<std::size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i)
  {
    const double u = 2.0 * Pi * i / nu;
    for (int j = 0; j < nv; ++j)
    {
      const double v = 2.0 * Pi * j / nv;
      const double ring = majorRadius + minorRadius * std::cos(v);
      mesh.Points.push_back({ ring * std::cos(u), ring * std::sin(u), minorRadius * std::sin(v) });
    }
  }
  auto id = [nu, nv](int i, int j) { return static_cast<Index>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      AddQuad(mesh, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  return mesh;
}

TriangleMesh MakeCylinder(double radius, double height, int resolution)
{
  RequirePositive(radius, "cylinder radius");
  RequirePositive(height, "cylinder height");
  resolution = std::max(resolution, 2);
  const int around = 4 * resolution;
  const double spacing = 2.0 * Pi * radius / around;
  const int rows = std::max(1, static_cast<int>(std::lround(height / spacing)));
  const int rings = std::max(1, static_cast<int>(std::lround(radius / spacing)));
  TriangleMesh mesh;
  // Side rows 0..rows (z from -h/2 to h/2), then cap rings inward, then centres.
  auto ringPoint = [&](double r, int k, double z)
  {
    const double t = 2.0 * Pi * k / around;
    return Point3{ r * std::cos(t), r * std::sin(t), z };
  };
  for (int row = 0; row <= rows; ++row)
  {
    const double z = -0.5 * height + height * row / rows;
    for (int k = 0; k < around; ++k)
    {
      mesh.Points.push_back(ringPoint(radius, k, z));
    }
  }
  auto side = [around](int row, int k) { return static_cast<Index>(row * around + k % around); };
  for (int row = 0; row < rows; ++row)
  {
    for (int k = 0; k < around; ++k)
    {
      AddQuad(mesh, side(row, k), side(row, k + 1), side(row + 1, k + 1), side(row + 1, k));
    }
  }
  // Caps: ring 0 is the rim (shared with the side), ring `rings` the centre.
  for (int top = 0; top < 2; ++top)
  {
    const double z = top ? 0.5 * height : -0.5 * height;
    std::vector<Index> previous(around);
    for (int k = 0; k < around; ++k)
    {
      previous[k] = side(top ? rows : 0, k);
    }
    for (int ring = 1; ring < rings; ++ring)
    {
      const double r = radius * (rings - ring) / rings;
      std::vector<Index> current(around);
      for (int k = 0; k < around; ++k)
      {
        current[k] = static_cast<Index>(mesh.Points.size());
        mesh.Points.push_back(ringPoint(r, k, z));
      }
      for (int k = 0; k < around; ++k)
      {
        const int k1 = (k + 1) % around;
        if (top)
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
    const Index centre = static_cast<Index>(mesh.Points.size());
    mesh.Points.push_back({ 0.0, 0.0, z });
    for (int k = 0; k < around; ++k)
    {
      const int k1 = (k + 1) % around;
      if (top)
      {
        mesh.Triangles.push_back({ previous[k], previous[k1], centre });
      }
      else
      {
        mesh.Triangles.push_back({ previous[k], centre, previous[k1] });
      }
    }
  }
  return mesh;
}

namespace
{
/// The surface of a union of grid cells: every face between a cell inside
/// and one outside (or off the grid), as two triangles over shared grid
/// nodes. coords[a] are the node coordinates along axis a (increasing);
/// inside(i, j, k) says whether cell (i, j, k) belongs to the union.
template <typename Inside>
TriangleMesh CellUnionSurface(const std::array<std::vector<double>, 3>& coords, Inside&& inside)
{
  const int cells[3] = { static_cast<int>(coords[0].size()) - 1,
    static_cast<int>(coords[1].size()) - 1, static_cast<int>(coords[2].size()) - 1 };
  auto in = [&](int i, int j, int k)
  {
    return i >= 0 && j >= 0 && k >= 0 && i < cells[0] && j < cells[1] && k < cells[2] &&
      inside(i, j, k);
  };
  TriangleMesh mesh;
  std::vector<Index> nodeId(coords[0].size() * coords[1].size() * coords[2].size(), -1);
  auto node = [&](int i, int j, int k)
  {
    Index& id = nodeId[(static_cast<std::size_t>(i) * coords[1].size() + j) * coords[2].size() + k];
    if (id < 0)
    {
      id = static_cast<Index>(mesh.Points.size());
      mesh.Points.push_back({ coords[0][i], coords[1][j], coords[2][k] });
    }
    return id;
  };
  for (int i = 0; i < cells[0]; ++i)
  {
    for (int j = 0; j < cells[1]; ++j)
    {
      for (int k = 0; k < cells[2]; ++k)
      {
        if (!in(i, j, k))
        {
          continue;
        }
        const int c[3] = { i, j, k };
        for (int a = 0; a < 3; ++a)
        {
          const int b = (a + 1) % 3, d = (a + 2) % 3;
          for (int side = 0; side < 2; ++side)
          {
            int o[3] = { i, j, k };
            o[a] += side ? 1 : -1;
            if (in(o[0], o[1], o[2]))
            {
              continue;
            }
            // Face corners in the (b, d) plane at a = c[a] + side.
            Index ids[4];
            const int du[4] = { 0, 1, 1, 0 }, dv[4] = { 0, 0, 1, 1 };
            for (int q = 0; q < 4; ++q)
            {
              int p[3];
              p[a] = c[a] + side;
              p[b] = c[b] + du[q];
              p[d] = c[d] + dv[q];
              ids[q] = node(p[0], p[1], p[2]);
            }
            // (b, d) counter-clockwise has normal +a.
            if (side)
            {
              AddQuad(mesh, ids[0], ids[1], ids[2], ids[3]);
            }
            else
            {
              AddQuad(mesh, ids[0], ids[3], ids[2], ids[1]);
            }
          }
        }
      }
    }
  }
  return mesh;
}

/// About `segments` equal steps from `from` to `to`, through every break in
/// between (sorted).
void AppendSteps(std::vector<double>& out, double from, double to, int segments,
  const std::vector<double>& breaks = {})
{
  std::vector<double> stops{ from };
  for (double b : breaks)
  {
    if (b > from && b < to)
    {
      stops.push_back(b);
    }
  }
  stops.push_back(to);
  const double step = (to - from) / std::max(segments, 1);
  if (out.empty())
  {
    out.push_back(from);
  }
  for (std::size_t s = 0; s + 1 < stops.size(); ++s)
  {
    const int n = std::max(1, static_cast<int>(std::lround((stops[s + 1] - stops[s]) / step)));
    for (int k = 1; k <= n; ++k)
    {
      out.push_back(k == n ? stops[s + 1] : stops[s] + (stops[s + 1] - stops[s]) * k / n);
    }
  }
}
}

TriangleMesh MakeLBlock(const Point3& sides, int resolution)
{
  for (double s : sides)
  {
    RequirePositive(s, "L-block side");
  }
  const int n = std::max(resolution, 1);
  std::array<std::vector<double>, 3> coords;
  for (int a = 0; a < 3; ++a)
  {
    for (int i = 0; i <= 2 * n; ++i)
    {
      coords[a].push_back(sides[a] * (double(i) / (2 * n) - 0.5));
    }
  }
  return CellUnionSurface(coords, [n](int i, int j, int) { return !(i >= n && j >= n); });
}

TriangleMesh MakeBlockWithFin(
  const Point3& sides, double finHeight, double finThickness, int resolution)
{
  for (double s : sides)
  {
    RequirePositive(s, "block side");
  }
  RequirePositive(finHeight, "fin height");
  RequirePositive(finThickness, "fin thickness");
  if (!(finThickness < 0.5 * sides[1]))
  {
    throw std::invalid_argument("the fin must be thinner than half the block's y side");
  }
  const int n = std::max(resolution, 1);
  const double spacing = std::max({ sides[0], sides[1], sides[2] }) / n;
  const double hx = 0.25 * sides[0], ht = 0.5 * finThickness, top = 0.5 * sides[2];
  std::array<std::vector<double>, 3> coords;
  AppendSteps(coords[0], -0.5 * sides[0], 0.5 * sides[0],
    static_cast<int>(std::lround(sides[0] / spacing)), { -hx, hx });
  AppendSteps(coords[1], -0.5 * sides[1], 0.5 * sides[1],
    static_cast<int>(std::lround(sides[1] / spacing)), { -ht, ht });
  AppendSteps(coords[2], -top, top, static_cast<int>(std::lround(sides[2] / spacing)));
  AppendSteps(coords[2], top, top + finHeight,
    std::max(1, static_cast<int>(std::lround(finHeight / spacing))));
  const auto centre = [&](int a, int i) { return 0.5 * (coords[a][i] + coords[a][i + 1]); };
  return CellUnionSurface(coords,
    [&](int i, int j, int k)
    { return centre(2, k) < top || (std::abs(centre(0, i)) < hx && std::abs(centre(1, j)) < ht); });
}

TriangleMesh MakeDumbbell(double length, double ballRadius, double neckRadius, int resolution)
{
  RequirePositive(length, "dumbbell length");
  RequirePositive(ballRadius, "dumbbell ball radius");
  RequirePositive(neckRadius, "dumbbell neck radius");
  const double centre = 0.5 * length - ballRadius; // of the top ball; the bottom one at -centre
  if (!(neckRadius < ballRadius) ||
    !(centre - std::sqrt(ballRadius * ballRadius - neckRadius * neckRadius) > 0.0))
  {
    throw std::invalid_argument(
      "the dumbbell's balls must not meet and its neck must be thinner than them");
  }
  resolution = std::max(resolution, 2);
  // A segment of a ball's great circle: the neck gets as many around.
  const int around = 4 * resolution;
  const double spacing = 0.5 * Pi * ballRadius / resolution;
  // The top ball from its pole down to where it meets the neck (polar angle
  // from the top), the neck, then the bottom ball mirrored.
  const double meet = Pi - std::asin(neckRadius / ballRadius);
  const int arcSegments = std::max(2, static_cast<int>(std::ceil(meet / (0.5 * Pi) * resolution)));
  std::vector<std::array<double, 2>> upper;
  for (int i = 1; i <= arcSegments; ++i)
  {
    const double angle = meet * i / arcSegments;
    upper.push_back({ ballRadius * std::sin(angle), centre + ballRadius * std::cos(angle) });
  }
  const double neckEnd = upper.back()[1];
  const int neckSegments = std::max(1, static_cast<int>(std::lround(2.0 * neckEnd / spacing)));
  std::vector<std::array<double, 2>> profile = upper;
  for (int i = 1; i < neckSegments; ++i)
  {
    profile.push_back({ neckRadius, neckEnd - 2.0 * neckEnd * i / neckSegments });
  }
  for (auto it = upper.rbegin(); it != upper.rend(); ++it)
  {
    profile.push_back({ (*it)[0], -(*it)[1] });
  }
  return Revolve(profile, 0.5 * length, -0.5 * length, around);
}

TriangleMesh MakePlateWithBoss(
  double side, double thickness, double bossRadius, double bossHeight, int resolution)
{
  RequirePositive(side, "plate side");
  RequirePositive(thickness, "plate thickness");
  RequirePositive(bossRadius, "boss radius");
  RequirePositive(bossHeight, "boss height");
  if (!(bossRadius < 0.45 * side))
  {
    throw std::invalid_argument("the boss must fit on the plate (radius below 0.45 x side)");
  }
  resolution = std::max(resolution, 2);
  // Around the axis: a multiple of 8 angles, so that the plate's corners
  // (at 45 degrees) are among them.
  const int around = 8 * ((4 * resolution + 7) / 8);
  const double spacing = 2.0 * Pi * bossRadius / around;
  const double half = 0.5 * side, top = 0.5 * thickness;
  // The top and bottom faces are annuli of rings from the boss's circle
  // (ring 0) to the square outline (last ring), each ring point blended
  // between the two along its angle.
  const int rings = std::max(2, static_cast<int>(std::lround((half - bossRadius) / spacing)));
  TriangleMesh mesh;
  auto annulus = [&](double z)
  {
    std::vector<std::vector<Index>> ids(rings + 1, std::vector<Index>(around));
    for (int j = 0; j <= rings; ++j)
    {
      const double blend = double(j) / rings;
      for (int k = 0; k < around; ++k)
      {
        const double angle = 2.0 * Pi * k / around;
        const double c = std::cos(angle), s = std::sin(angle);
        const double toSquare = half / std::max(std::fabs(c), std::fabs(s));
        const double r = (1.0 - blend) * bossRadius + blend * toSquare;
        ids[j][k] = static_cast<Index>(mesh.Points.size());
        mesh.Points.push_back({ r * c, r * s, z });
      }
    }
    return ids;
  };
  const auto upper = annulus(top), lower = annulus(-top);
  for (int j = 0; j < rings; ++j)
  {
    for (int k = 0; k < around; ++k)
    {
      const int k1 = (k + 1) % around;
      AddQuad(mesh, upper[j][k], upper[j + 1][k], upper[j + 1][k1], upper[j][k1]);
      AddQuad(mesh, lower[j][k], lower[j][k1], lower[j + 1][k1], lower[j + 1][k]);
    }
  }
  auto wall = [&](const std::vector<Index>& below, const std::vector<Index>& above)
  {
    for (int k = 0; k < around; ++k)
    {
      const int k1 = (k + 1) % around;
      AddQuad(mesh, below[k], below[k1], above[k1], above[k]);
    }
  };
  wall(lower[rings], upper[rings]); // the plate's rim
  // The boss: rows up its side from the top face, then its cap.
  const int rows = std::max(1, static_cast<int>(std::lround(bossHeight / spacing)));
  std::vector<Index> previous = upper[0];
  for (int i = 1; i <= rows; ++i)
  {
    std::vector<Index> current(around);
    for (int k = 0; k < around; ++k)
    {
      const Point3& p = mesh.Points[previous[k]];
      current[k] = static_cast<Index>(mesh.Points.size());
      mesh.Points.push_back({ p[0], p[1], top + bossHeight * i / rows });
    }
    wall(previous, current);
    previous.swap(current);
  }
  std::vector<int> unused;
  const int capRings = std::max(1, around / 8);
  AddCap(mesh, previous, { 0.0, 0.0, top + bossHeight }, capRings, true, &unused);
  AddCap(mesh, lower[0], { 0.0, 0.0, -top }, capRings, false, &unused);
  return mesh;
}

AreaVolume LBlockAreaVolume(const Point3& sides)
{
  const double x = sides[0], y = sides[1], z = sides[2];
  // Three quarters of the box; the removed quadrant takes x/2 + y/2 of the
  // outer perimeter and adds the same length of inner walls.
  return { 2 * 0.75 * x * y + 2 * (x + y) * z, 0.75 * x * y * z };
}

AreaVolume RoundedBoxAreaVolume(const Point3& sides, double r)
{
  const double a = sides[0] - 2 * r, b = sides[1] - 2 * r, c = sides[2] - 2 * r;
  return { 2 * (a * b + b * c + c * a) + 2 * Pi * r * (a + b + c) + 4 * Pi * r * r,
    a * b * c + 2 * r * (a * b + b * c + c * a) + Pi * r * r * (a + b + c) +
      4.0 / 3.0 * Pi * r * r * r };
}

AreaVolume CapsuleAreaVolume(double radius, double axisLength)
{
  return RoundedBoxAreaVolume({ 2 * radius, 2 * radius, axisLength + 2 * radius }, radius);
}

AreaVolume TorusAreaVolume(double majorRadius, double minorRadius)
{
  return { 4 * Pi * Pi * majorRadius * minorRadius,
    2 * Pi * Pi * majorRadius * minorRadius * minorRadius };
}

AreaVolume CylinderAreaVolume(double radius, double height)
{
  return { 2 * Pi * radius * height + 2 * Pi * radius * radius, Pi * radius * radius * height };
}

AreaVolume DumbbellAreaVolume(double length, double ballRadius, double neckRadius)
{
  // Each ball loses the cap inside the neck; the neck shows between the caps.
  const double inner = std::sqrt(ballRadius * ballRadius - neckRadius * neckRadius);
  const double cap = ballRadius - inner;
  const double neck = 2.0 * (0.5 * length - ballRadius - inner);
  return { 2.0 * (4.0 * Pi * ballRadius * ballRadius - 2.0 * Pi * ballRadius * cap) +
      2.0 * Pi * neckRadius * neck,
    2.0 * 4.0 / 3.0 * Pi * ballRadius * ballRadius * ballRadius +
      Pi * neckRadius * neckRadius * neck };
}

AreaVolume BlockWithFinAreaVolume(const Point3& sides, double finHeight, double finThickness)
{
  const AreaVolume block = RoundedBoxAreaVolume(sides, 0.0);
  const double finLength = 0.5 * sides[0];
  return { block.Area + 2.0 * finHeight * (finLength + finThickness),
    block.Volume + finLength * finThickness * finHeight };
}

AreaVolume PlateWithBossAreaVolume(
  double side, double thickness, double bossRadius, double bossHeight)
{
  return { 2.0 * side * side + 4.0 * side * thickness + 2.0 * Pi * bossRadius * bossHeight,
    side * side * thickness + Pi * bossRadius * bossRadius * bossHeight };
}
}
