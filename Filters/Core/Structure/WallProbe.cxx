// SPDX-License-Identifier: GPL-3.0-or-later
#include "Structure/WallProbe.h"

#include "Geometry/Vec3.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
// A chord is centred only where it meets both sides at angles this close.
const double ChordAngleTolerance = 1.0 * Pi / 180.0;
// A chord is centred only between sides this close to parallel (plus the
// tessellation's angle where both sides are curved): between
// sides that converge more (a fillet's start), its middle follows their
// bisector, away from the wall's plane. Drafted walls (up to a degree a
// side) still pass.
const double ChordSidesTolerance = 2.0 * Pi / 180.0;
// A side faces a sheet whose normal is within this angle of its own.
const double SideFacingCosine = std::cos(45.0 * Pi / 180.0);
// Centring moves a vertex across its sheet, and along it by at most this
// fraction of the thickness (the noise of the discrete medial axis).
const double MaximumSlide = 0.1;
// Chords tilted further from the sides' normals are not trusted.
const double MaximumChordTilt = 30.0 * Pi / 180.0;

// Any unit vector perpendicular to the unit vector n.
Point3 Perpendicular(const Point3& n)
{
  const Point3 axis = std::fabs(n[0]) < 0.6 ? Point3{ 1, 0, 0 } : Point3{ 0, 1, 0 };
  return Normalized(Cross(n, axis));
}

// The first surface triangle along the unit `direction`. A ray through an
// edge or a vertex of the surface can slip between the triangles there; it
// is then tilted by a negligible angle and cast again.
TriangleLocator::RayHit CastRay(const TriangleLocator& locator, const Point3& origin,
  const Point3& direction, const Point3& tilt, double maximum)
{
  TriangleLocator::RayHit hit;
  for (double angle : { 0.0, 1e-6, -1e-6 })
  {
    hit = locator.FirstHit(origin, Normalized(direction + angle * tilt), 0.0, maximum);
    if (hit.Triangle >= 0)
    {
      break;
    }
  }
  return hit;
}
}

double WallProbe::SidesTolerance(Index a, Index b) const
{
  const double ta = this->FacetTurn[a], tb = this->FacetTurn[b];
  const bool bent = ta * tb < 0.0;
  return ChordSidesTolerance + (bent ? std::max(std::fabs(ta), std::fabs(tb)) : 0.0);
}

bool WallProbe::Centre(
  const Point3& x, const Point3& normal, double reach, Point3& middle, double& thickness) const
{
  // The nearest point on a side facing the sheet: the lateral faces at its
  // ends and the sides of other walls at a junction do not count.
  const auto near = this->Locator.Closest(
    x, [&](Index t) { return std::fabs(Dot(this->Normals[t], normal)) >= SideFacingCosine; },
    reach);
  if (near.Triangle < 0)
  {
    return false;
  }
  // Across from the nearest point: the side's normal inside a triangle;
  // on an edge or a corner of a tessellated curved side, the mean normal
  // of the facing triangles there (the direction towards x would carry
  // the medial axis' noise into the chord's tilt).
  if (!(Norm(x - near.Point) > 1e-9 * reach))
  {
    return false;
  }
  const Point3 towards = Normalized(x - near.Point);
  Point3 inward = towards;
  if (std::fabs(Dot(towards, this->Normals[near.Triangle])) < std::cos(1e-3))
  {
    Point3 sum{ 0, 0, 0 };
    this->Locator.ForEachWithin(near.Point, 1e-9 * reach,
      [&](Index t)
      {
        if (std::fabs(Dot(this->Normals[t], normal)) >= SideFacingCosine)
        {
          sum = sum + (Dot(this->Normals[t], towards) < 0.0 ? -1.0 : 1.0) * this->Normals[t];
        }
      });
    inward = Norm(sum) > 0.0 ? Normalized(sum) : towards;
  }
  else if (Dot(this->Normals[near.Triangle], towards) < 0.0)
  {
    inward = -1.0 * this->Normals[near.Triangle];
  }
  else
  {
    inward = this->Normals[near.Triangle];
  }
  const auto across =
    this->Locator.FirstHit(near.Point, inward, 1e-9 * reach, reach, near.Triangle);
  if (across.Triangle < 0 ||
    std::fabs(Dot(this->Normals[across.Triangle], inward)) <
      std::cos(this->SidesTolerance(near.Triangle, across.Triangle)))
  {
    return false;
  }
  // The middle must lie across the sheet from x, not along it: a point
  // near a junction is nearest to another wall's side.
  const Point3 m = near.Point + 0.5 * across.Distance * inward;
  const Point3 move = m - x;
  if (Norm(move - Dot(move, normal) * normal) > MaximumSlide * across.Distance)
  {
    return false;
  }
  middle = m;
  thickness = across.Distance;
  return true;
}

WallProbe::ChordResult WallProbe::Chord(const Point3& x, const Point3& n, double reach) const
{
  const Point3 tilt = Perpendicular(n);
  const auto up = CastRay(this->Locator, x, n, tilt, reach);
  const auto down = CastRay(this->Locator, x, -1.0 * n, tilt, reach);
  if (up.Triangle < 0 || down.Triangle < 0)
  {
    return {};
  }
  const Point3& upNormal = this->Normals[up.Triangle];
  const Point3& downNormal = this->Normals[down.Triangle];
  const double upAngle = std::acos(std::min(1.0, std::fabs(Dot(upNormal, n))));
  const double downAngle = std::acos(std::min(1.0, std::fabs(Dot(downNormal, n))));
  if (std::fabs(upAngle - downAngle) > ChordAngleTolerance || upAngle > MaximumChordTilt ||
    std::fabs(Dot(upNormal, downNormal)) <
      std::cos(this->SidesTolerance(up.Triangle, down.Triangle)))
  {
    return {};
  }
  return { (up.Distance + down.Distance) * std::cos(0.5 * (upAngle + downAngle)),
    0.5 * (up.Distance - down.Distance) };
}

void PlaneSet::Add(const Point3& p, const Point3& n)
{
  for (std::size_t k = 0; k < this->Normals.size(); ++k)
  {
    const Point3 mean = Normalized(this->Normals[k]);
    const double c = Dot(mean, n);
    if (std::fabs(c) >= SamePlaneCosine)
    {
      this->Normals[k] = this->Normals[k] + (c < 0.0 ? -1.0 : 1.0) * n;
      this->Points[k] = this->Points[k] + p;
      ++this->Count[k];
      return;
    }
  }
  this->Points.push_back(p);
  this->Normals.push_back(n);
  this->Count.push_back(1);
}

Point3 PlaneSet::Meet(const Point3& x) const
{
  Eigen::Matrix3d a = 1e-6 * Eigen::Matrix3d::Identity();
  Eigen::Vector3d b = 1e-6 * Eigen::Vector3d(x[0], x[1], x[2]);
  for (std::size_t k = 0; k < this->Normals.size(); ++k)
  {
    const Point3 n = Normalized(this->Normals[k]);
    const Point3 p = (1.0 / this->Count[k]) * this->Points[k];
    const Eigen::Vector3d ne(n[0], n[1], n[2]);
    a += ne * ne.transpose();
    b += ne * Dot(n, p);
  }
  const Eigen::Vector3d y = a.ldlt().solve(b);
  return { y[0], y[1], y[2] };
}

Point3 PlaneSet::AlongAll(Point3 d) const
{
  std::vector<Point3> basis;
  for (const Point3& raw : this->Normals)
  {
    Point3 n = Normalized(raw);
    for (const Point3& e : basis)
    {
      n = n - Dot(n, e) * e;
    }
    if (Norm(n) > 1e-6)
    {
      basis.push_back(Normalized(n));
      d = d - Dot(d, basis.back()) * basis.back();
    }
  }
  return d;
}
}
