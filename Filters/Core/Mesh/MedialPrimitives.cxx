// SPDX-License-Identifier: GPL-3.0-or-later
#include "Mesh/MedialPrimitives.h"

#include "Geometry/Vec3.h"

#include <cmath>
#include <limits>

namespace medialaxis
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

// A unit vector perpendicular to the unit vector a.
Point3 AnyPerpendicular(const Point3& a)
{
  const Point3 t = std::abs(a[0]) < 0.6 ? Point3{ 1, 0, 0 } : Point3{ 0, 1, 0 };
  return Normalized(Cross(a, t));
}
}

PrimitiveDistance SphereDistance(const SpherePrimitive& s, const Point3& p)
{
  const Point3 v = p - s.Center;
  const double d = Norm(v);
  return { d - s.Radius, d > 0.0 ? (1.0 / d) * v : Point3{ 0, 0, 1 } };
}

ConePrimitive MakeCone(const Point3& c0, double r0, const Point3& c1, double r1)
{
  ConePrimitive cone;
  cone.C = { c0, c1 };
  cone.R = { r0, r1 };
  const Point3 d = c1 - c0;
  cone.Length = Norm(d);
  cone.Axis = cone.Length > 0.0 ? (1.0 / cone.Length) * d : Point3{ 0, 0, 1 };
  cone.Perp1 = AnyPerpendicular(cone.Axis);
  cone.Perp2 = Cross(cone.Axis, cone.Perp1);
  // One ball inside the other (a zero-length edge included): no tangent cone.
  // The relative margin keeps SinPhi away from +-1, where the lateral
  // surface shrinks to nothing anyway.
  const double dr = r0 - r1;
  const double scale = std::max({ cone.Length, std::abs(r0), std::abs(r1) });
  cone.Nested = cone.Length <= std::abs(dr) + 1e-12 * scale;
  cone.Big = r1 > r0 ? 1 : 0;
  if (cone.Nested)
  {
    cone.SinPhi = dr >= 0.0 ? 1.0 : -1.0;
    cone.CosPhi = 0.0;
  }
  else
  {
    cone.SinPhi = dr / cone.Length;
    cone.CosPhi = std::sqrt(std::max(0.0, 1.0 - cone.SinPhi * cone.SinPhi));
  }
  return cone;
}

PrimitiveDistance ConeDistance(const ConePrimitive& cone, const Point3& p)
{
  if (cone.Nested)
  {
    return SphereDistance({ cone.C[cone.Big], cone.R[cone.Big] }, p);
  }
  // In the half plane through the axis and p: a along the axis from C[0],
  // b >= 0 away from it. The tangent line is at signed distance
  // a SinPhi + b CosPhi - R[0]; s is the position of p's foot along it,
  // 0 at the tangent point of ball 0 and Length CosPhi at ball 1.
  const Point3 v = p - cone.C[0];
  const double a = Dot(v, cone.Axis);
  const Point3 w = v - a * cone.Axis;
  const double b = Norm(w);
  const double s = a * cone.CosPhi - b * cone.SinPhi;
  if (s <= 0.0)
  {
    return SphereDistance({ cone.C[0], cone.R[0] }, p);
  }
  if (s >= cone.Length * cone.CosPhi)
  {
    return SphereDistance({ cone.C[1], cone.R[1] }, p);
  }
  const Point3 radial = b > 0.0 ? (1.0 / b) * w : cone.Perp1;
  return { a * cone.SinPhi + b * cone.CosPhi - cone.R[0],
    cone.SinPhi * cone.Axis + cone.CosPhi * radial };
}

Circle3 ConeTangentCircle(const ConePrimitive& cone, int end)
{
  return { cone.C[end] + (cone.R[end] * cone.SinPhi) * cone.Axis, cone.R[end] * cone.CosPhi };
}

Point3 ConeTangentPoint(const ConePrimitive& cone, int end, double angle)
{
  const Point3 radial = std::cos(angle) * cone.Perp1 + std::sin(angle) * cone.Perp2;
  return cone.C[end] + cone.R[end] * (cone.SinPhi * cone.Axis + cone.CosPhi * radial);
}

double ConeLateralArea(const ConePrimitive& cone)
{
  if (cone.Nested)
  {
    return 0.0;
  }
  // Frustum: pi (rho0 + rho1) x slant, slant = Length CosPhi.
  const double pi = 3.14159265358979323846;
  return pi * (cone.R[0] + cone.R[1]) * cone.CosPhi * cone.Length * cone.CosPhi;
}

SlabPrimitive MakeSlab(const std::array<Point3, 3>& c, const std::array<double, 3>& r)
{
  SlabPrimitive slab = MakeSlabInterior(c, r);
  for (int e = 0; e < 3; ++e)
  {
    slab.Edges[e] = MakeCone(c[e], r[e], c[(e + 1) % 3], r[(e + 1) % 3]);
  }
  return slab;
}

SlabPrimitive MakeSlabInterior(const std::array<Point3, 3>& c, const std::array<double, 3>& r)
{
  SlabPrimitive slab;
  slab.C = c;
  slab.R = r;
  slab.HasTangentPlanes = false;
  slab.E1 = c[1] - c[0];
  slab.E2 = c[2] - c[0];
  const Point3 n = Cross(slab.E1, slab.E2);
  const double area2 = Norm(n);
  const double g11 = Dot(slab.E1, slab.E1), g12 = Dot(slab.E1, slab.E2),
               g22 = Dot(slab.E2, slab.E2);
  const double det = g11 * g22 - g12 * g12;
  // Collinear centres (or a repeated centre): the slab is its edge cones.
  if (!(area2 > 1e-12 * std::sqrt(g11 * g22)) || !(det > 0.0))
  {
    slab.PlaneNormal = { 0, 0, 1 };
    slab.InvG11 = slab.InvG12 = slab.InvG22 = 0.0;
    slab.Gamma = 0.0;
    return slab;
  }
  slab.PlaneNormal = (1.0 / area2) * n;
  slab.InvG11 = g22 / det;
  slab.InvG12 = -g12 / det;
  slab.InvG22 = g11 / det;
  // Tangent planes n . x = h with n . c_i + r_i = h: the in-plane part m of n
  // solves m . E1 = r0 - r1, m . E2 = r0 - r2; then n = m +- gamma N.
  const double s1 = r[0] - r[1], s2 = r[0] - r[2];
  const double alpha = slab.InvG11 * s1 + slab.InvG12 * s2;
  const double beta = slab.InvG12 * s1 + slab.InvG22 * s2;
  const Point3 m = alpha * slab.E1 + beta * slab.E2;
  const double m2 = Dot(m, m);
  // |grad r| = |m| >= 1: the interpolated balls are nested along the
  // gradient and no plane touches all three balls.
  if (!(m2 < 1.0 - 1e-12))
  {
    slab.Gamma = 0.0;
    return slab;
  }
  slab.HasTangentPlanes = true;
  slab.Gamma = std::sqrt(1.0 - m2);
  slab.Normals[0] = m + slab.Gamma * slab.PlaneNormal;
  slab.Normals[1] = m - slab.Gamma * slab.PlaneNormal;
  for (int s = 0; s < 2; ++s)
  {
    slab.Offsets[s] = Dot(slab.Normals[s], c[0]) + r[0];
  }
  return slab;
}

PrimitiveDistance SlabInteriorDistance(const SlabPrimitive& slab, const Point3& p)
{
  if (!slab.HasTangentPlanes)
  {
    return { Infinity, slab.PlaneNormal };
  }
  // The closest interpolated ball for p's side s has its centre where the
  // line p - t Normals[s] meets the centre plane.
  const double height = Dot(p - slab.C[0], slab.PlaneNormal);
  const int side = height >= 0.0 ? 0 : 1;
  const Point3& n = slab.Normals[side];
  const double t = std::abs(height) / slab.Gamma;
  const Point3 v = (p - t * n) - slab.C[0];
  const double d1 = Dot(v, slab.E1), d2 = Dot(v, slab.E2);
  const double b1 = slab.InvG11 * d1 + slab.InvG12 * d2;
  const double b2 = slab.InvG12 * d1 + slab.InvG22 * d2;
  if (b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0)
  {
    return { Infinity, n };
  }
  return { Dot(n, p) - slab.Offsets[side], n };
}

PrimitiveDistance SlabDistance(const SlabPrimitive& slab, const Point3& p)
{
  PrimitiveDistance best = SlabInteriorDistance(slab, p);
  for (const ConePrimitive& e : slab.Edges)
  {
    const PrimitiveDistance d = ConeDistance(e, p);
    if (d.Distance < best.Distance)
    {
      best = d;
    }
  }
  return best;
}

std::array<Point3, 3> SlabTangentTriangle(const SlabPrimitive& slab, int side)
{
  const Point3& n = slab.Normals[side];
  std::array<Point3, 3> t;
  for (int i = 0; i < 3; ++i)
  {
    t[i] = slab.C[i] + slab.R[i] * n;
  }
  if (Dot(Cross(t[1] - t[0], t[2] - t[0]), n) < 0.0)
  {
    std::swap(t[1], t[2]);
  }
  return t;
}
}
