// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/FilletedShapes.h"

#include "Geometry/Vec3.h"
#include "Surface/AnalyticShapes.h"
#include "Surface/ShapeBuilding.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace medialaxis
{
namespace
{
void RequireFilletRadius(double r)
{
  if (!(r >= 0.0) || !std::isfinite(r))
  {
    throw std::invalid_argument("fillet radii must be non-negative and finite");
  }
}
}

LabelledTriangleMesh MakeFilletedPrism(const Point3& sides,
  const std::array<double, 4>& bottomRadii, const std::array<double, 4>& topRadii, int resolution)
{
  for (double s : sides)
  {
    RequirePositive(s, "prism side");
  }
  const double halfX = 0.5 * sides[0], halfY = 0.5 * sides[1], height = sides[2];
  for (int k = 0; k < 4; ++k)
  {
    RequireFilletRadius(bottomRadii[k]);
    RequireFilletRadius(topRadii[k]);
    if ((bottomRadii[k] > 0.0) != (topRadii[k] > 0.0))
    {
      throw std::invalid_argument("a prism edge must be rounded at both ends or at neither");
    }
    // Neighbouring arcs must not overlap along the side between them.
    const int next = (k + 1) % 4;
    const double side = (k % 2 == 0) ? sides[0] : sides[1];
    if (std::max(bottomRadii[k] + bottomRadii[next], topRadii[k] + topRadii[next]) > side)
    {
      throw std::invalid_argument("the fillets of two neighbouring prism edges overlap");
    }
  }
  resolution = std::max(resolution, 2);
  const double spacing = std::max({ sides[0], sides[1], height }) / (2.0 * resolution);
  const int layers = std::max(1, static_cast<int>(std::lround(height / spacing)));
  // Corners counter-clockwise seen from +z; the arc of corner k turns from
  // angle k pi/2 to (k + 1) pi/2 around its centre.
  const double cornerX[4] = { halfX, -halfX, -halfX, halfX };
  const double cornerY[4] = { halfY, halfY, -halfY, -halfY };
  int sideSegments[4];
  for (int k = 0; k < 4; ++k)
  {
    const double side = (k % 2 == 0) ? sides[0] : sides[1];
    sideSegments[k] = std::max(1, static_cast<int>(std::lround(side / spacing)));
  }

  LabelledTriangleMesh part;
  TriangleMesh& mesh = part.Mesh;
  std::vector<int> segmentLabel; // of profile segment i (from point i to i + 1)
  std::vector<std::vector<Index>> rows(layers + 1);
  for (int layer = 0; layer <= layers; ++layer)
  {
    const double t = double(layer) / layers;
    const double z = -0.5 * height + height * t;
    std::vector<Point3> profile;
    segmentLabel.clear();
    for (int k = 0; k < 4; ++k)
    {
      const double r = (1.0 - t) * bottomRadii[k] + t * topRadii[k];
      const double sx = cornerX[k] > 0 ? 1.0 : -1.0, sy = cornerY[k] > 0 ? 1.0 : -1.0;
      if (r > 0.0)
      {
        // The section at height z of the envelope of the rolling ball whose
        // centre c(h) = corner - r(h) (sx, sy) and radius r(h) vary linearly
        // with its height h. A ball touches the envelope along the circle of
        // unit normals n with n . u = alpha = -r' / |c'| (u the unit tangent
        // of the centre line); the fillet is the arc of it from the contact
        // normal of one face to the other's, and normal n meets height z on
        // the ball whose h solves h + r(h) n_z = z. Constant radius: a
        // horizontal quarter circle.
        const double slope = (topRadii[k] - bottomRadii[k]) / height;
        const Point3 u = Normalized(Point3{ -sx * slope, -sy * slope, 1.0 });
        const double alpha = -slope / std::sqrt(1.0 + 2.0 * slope * slope);
        const double from = 0.5 * Pi * k, to = 0.5 * Pi * (k + 1);
        const Point3 first{ std::cos(from), std::sin(from), 0.0 },
          last{ std::cos(to), std::sin(to), 0.0 };
        const Point3 e1 = Normalized(first - alpha * u);
        const Point3 lastAcross = last - alpha * u;
        const Point3 e2 = Normalized(lastAcross - Dot(lastAcross, e1) * e1);
        const double sweep = std::atan2(Dot(lastAcross, e2), Dot(lastAcross, e1));
        const double beta = std::sqrt(1.0 - alpha * alpha);
        const double bottom = -0.5 * height;
        for (int i = 0; i <= resolution; ++i)
        {
          const double phi = sweep * i / resolution;
          const Point3 n = alpha * u + beta * (std::cos(phi) * e1 + std::sin(phi) * e2);
          // h + (r0 + slope (h - bottom)) n_z = z
          const double h = (z - (bottomRadii[k] - slope * bottom) * n[2]) / (1.0 + slope * n[2]);
          const double rh = bottomRadii[k] + slope * (h - bottom);
          profile.push_back(
            { cornerX[k] - sx * rh + rh * n[0], cornerY[k] - sy * rh + rh * n[1], z });
          segmentLabel.push_back(i < resolution ? k : -1);
        }
      }
      else
      {
        profile.push_back({ cornerX[k], cornerY[k], z });
        segmentLabel.push_back(-1);
      }
      // The straight side to the next corner's arc: interior points only.
      const int next = (k + 1) % 4;
      const double rn = (1.0 - t) * bottomRadii[next] + t * topRadii[next];
      const Point3 from = profile.back();
      const double nx = cornerX[next] > 0 ? 1.0 : -1.0, ny = cornerY[next] > 0 ? 1.0 : -1.0;
      // Start of the next arc (angle (k + 1) pi/2 around its centre).
      const double angle = 0.5 * Pi * (k + 1);
      const Point3 to{ cornerX[next] - nx * rn + rn * std::cos(angle),
        cornerY[next] - ny * rn + rn * std::sin(angle), z };
      for (int i = 1; i < sideSegments[k]; ++i)
      {
        const double u = double(i) / sideSegments[k];
        profile.push_back({ from[0] + u * (to[0] - from[0]), from[1] + u * (to[1] - from[1]), z });
        segmentLabel.push_back(-1);
      }
    }
    for (const Point3& p : profile)
    {
      rows[layer].push_back(static_cast<Index>(mesh.Points.size()));
      mesh.Points.push_back(p);
    }
  }
  const std::size_t n = rows[0].size();
  for (int layer = 0; layer < layers; ++layer)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::size_t j = (i + 1) % n;
      AddQuad(mesh, rows[layer][i], rows[layer][j], rows[layer + 1][j], rows[layer + 1][i]);
      part.FilletId.resize(mesh.Triangles.size(), segmentLabel[i]);
    }
  }
  const int rings = std::max(1, static_cast<int>(std::lround(std::min(halfX, halfY) / spacing)));
  AddCap(mesh, rows[layers], { 0.0, 0.0, 0.5 * height }, rings, true, &part.FilletId);
  AddCap(mesh, rows[0], { 0.0, 0.0, -0.5 * height }, rings, false, &part.FilletId);
  return part;
}

LabelledTriangleMesh MakeRoundedCylinder(
  double radius, double height, double topFilletRadius, double bottomFilletRadius, int resolution)
{
  RequirePositive(radius, "cylinder radius");
  RequirePositive(height, "cylinder height");
  RequireFilletRadius(topFilletRadius);
  RequireFilletRadius(bottomFilletRadius);
  if (std::max(topFilletRadius, bottomFilletRadius) > radius ||
    topFilletRadius + bottomFilletRadius > height)
  {
    throw std::invalid_argument("the rim fillets do not fit the cylinder");
  }
  resolution = std::max(resolution, 2);
  const int around = 16 * resolution;
  const double spacing = 2.0 * Pi * radius / around;
  // The profile in (distance from the axis, z), from the top pole to the
  // bottom pole (both excluded), with the label of the segment before each point.
  std::vector<std::array<double, 2>> profile;
  std::vector<int> labelBefore;
  auto straight = [&](double r0, double z0, double r1, double z1, bool includeEnd)
  {
    const double length = std::hypot(r1 - r0, z1 - z0);
    const int segments = std::max(1, static_cast<int>(std::lround(length / spacing)));
    for (int i = 1; i <= segments; ++i)
    {
      if (i == segments && !includeEnd)
      {
        break;
      }
      const double u = double(i) / segments;
      profile.push_back({ r0 + u * (r1 - r0), z0 + u * (z1 - z0) });
      labelBefore.push_back(-1);
    }
  };
  auto arc = [&](double cr, double cz, double rho, double from, double to, int label)
  {
    for (int i = 1; i <= resolution; ++i)
    {
      const double angle = from + (to - from) * i / resolution;
      profile.push_back({ cr + rho * std::cos(angle), cz + rho * std::sin(angle) });
      labelBefore.push_back(label);
    }
  };
  const double top = 0.5 * height, bottom = -0.5 * height;
  const double rt = topFilletRadius, rb = bottomFilletRadius;
  straight(0.0, top, radius - rt, top, true);
  if (rt > 0.0)
  {
    arc(radius - rt, top - rt, rt, 0.5 * Pi, 0.0, 0);
  }
  straight(radius, top - rt, radius, bottom + rb, true);
  if (rb > 0.0)
  {
    arc(radius - rb, bottom + rb, rb, 0.0, -0.5 * Pi, 1);
  }
  straight(radius - rb, bottom, 0.0, bottom, false);

  LabelledTriangleMesh part;
  part.Mesh = Revolve(profile, top, bottom, around, &labelBefore, &part.FilletId);
  return part;
}
}
