// SPDX-License-Identifier: GPL-3.0-or-later
// Pi, and small vector helpers on Point3 for the geometry code.
#ifndef medialaxis_Vec3_h
#define medialaxis_Vec3_h

#include "Geometry/Types.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace medialaxis
{
constexpr double Pi = 3.14159265358979323846;

inline Point3 operator+(const Point3& a, const Point3& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
inline Point3 operator-(const Point3& a, const Point3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Point3 operator*(double s, const Point3& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
inline double Dot(const Point3& a, const Point3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Point3 Cross(const Point3& a, const Point3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double Norm(const Point3& a)
{
  return std::sqrt(Dot(a, a));
}
inline double Distance2(const Point3& a, const Point3& b)
{
  const Point3 d = a - b;
  return Dot(d, d);
}
/// Unit vector, or zero for a zero vector.
inline Point3 Normalized(const Point3& a)
{
  const double n = Norm(a);
  return n > 0.0 ? (1.0 / n) * a : Point3{ 0.0, 0.0, 0.0 };
}

/// Stability ratio of the medial edge between balls (ca, ra) and (cb, rb)
/// (Q-MAT's Gamma): 0 for a pure spike (one ball internally tangent to the
/// other, or coincident centres), 1 for equal radii.
inline double StabilityRatio(const Point3& ca, double ra, const Point3& cb, double rb)
{
  const double d = Norm(cb - ca);
  return d > 0.0 ? std::max(0.0, d - std::fabs(ra - rb)) / d : 0.0;
}

/// Axis-aligned bounding box (lowest and highest corner) of non-empty points.
inline std::pair<Point3, Point3> BoundingBox(const std::vector<Point3>& points)
{
  Point3 lo = points[0], hi = points[0];
  for (const Point3& p : points)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  return { lo, hi };
}
}

#endif
