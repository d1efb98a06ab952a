// SPDX-License-Identifier: GPL-3.0-or-later
// Compact records of single primitives for the lane kernels of
// PrimitiveKernels.h, and the values of one record at many points, two points
// at a time. The envelope stores its primitives as these records; the
// simplifier's error bound tests the few primitives a collapse makes against
// the many surface points of its Atlas with them. Values only, no normals,
// bit-identical to SphereDistance, ConeDistance and SlabInteriorDistance.
#ifndef medialaxis_PrimitiveRecords_h
#define medialaxis_PrimitiveRecords_h

#include "Envelope/PrimitivePairs.h"
#include "Mesh/MedialPrimitives.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

namespace medialaxis
{
namespace records
{
/// A sphere or cone (C0, R0, axis, sin phi, cos phi, length cos phi, C1, R1)
/// and a slab interior (see PrimitiveKernels.h).
using Round = std::array<double, kernels::RoundFields>;
using Slab = std::array<double, kernels::SlabFields>;

/// A ball: a cone with a zero axis, sin 1 and cos 0, which always takes the
/// C0 cap, whose value is the ball's.
inline Round MakeRound(const SpherePrimitive& ball)
{
  const Point3& c = ball.Center;
  return { c[0], c[1], c[2], ball.Radius, 0, 0, 0, 1, 0, std::numeric_limits<double>::infinity(),
    c[0], c[1], c[2], ball.Radius };
}

/// A cone; a nested one (a ball inside the other) is its bigger ball.
inline Round MakeRound(const ConePrimitive& cone)
{
  if (cone.Nested)
  {
    return MakeRound(SpherePrimitive{ cone.C[cone.Big], cone.R[cone.Big] });
  }
  const Point3 &c0 = cone.C[0], &c1 = cone.C[1], &axis = cone.Axis;
  return { c0[0], c0[1], c0[2], cone.R[0], axis[0], axis[1], axis[2], cone.SinPhi, cone.CosPhi,
    cone.Length * cone.CosPhi, c1[0], c1[1], c1[2], cone.R[1] };
}

/// A slab's interior (between its tangent planes, inside the prism over its
/// centre triangle); false, and `out` untouched, without tangent planes,
/// where the interior is empty (its value is +infinity everywhere).
inline bool MakeSlab(const SlabPrimitive& slab, Slab& out)
{
  if (!slab.HasTangentPlanes)
  {
    return false;
  }
  double* d = out.data();
  const auto store = [](double* to, const Point3& x) { std::copy(x.begin(), x.end(), to); };
  store(d, slab.C[0]);
  store(d + 3, slab.PlaneNormal);
  store(d + 6, slab.Normals[0]);
  store(d + 9, slab.Normals[1]);
  d[12] = slab.Offsets[0];
  d[13] = slab.Offsets[1];
  d[14] = slab.Gamma;
  store(d + 15, slab.E1);
  store(d + 18, slab.E2);
  d[21] = slab.InvG11;
  d[22] = slab.InvG12;
  d[23] = slab.InvG22;
  return true;
}

/// Points by coordinate (x[i], y[i], z[i]); every array holds `count`
/// rounded up to an even number of entries.
struct PointLanes
{
  const double* X;
  const double* Y;
  const double* Z;
  std::size_t Count;
};

namespace detail
{
// Every lane gets field f of the one record.
struct SplatFields
{
  const double* Record;
  pairs::Lanes operator()(int f) const { return pairs::Splat(this->Record[f]); }
};

template <typename Kernel>
void LowerTo(const PointLanes& points, double* values, Kernel&& kernel)
{
  for (std::size_t i = 0; i < points.Count; i += 2)
  {
    double lanes[2];
    pairs::Store(
      kernel(pairs::Load(points.X + i), pairs::Load(points.Y + i), pairs::Load(points.Z + i)),
      lanes);
    values[i] = std::min(values[i], lanes[0]);
    if (i + 1 < points.Count)
    {
      values[i + 1] = std::min(values[i + 1], lanes[1]);
    }
  }
}
}

/// values[i] = min(values[i], the record's value at point i).
inline void LowerTo(const Round& record, const PointLanes& points, double* values)
{
  detail::LowerTo(points, values,
    [&](pairs::Lanes x, pairs::Lanes y, pairs::Lanes z) {
      return kernels::RoundValues(detail::SplatFields{ record.data() }, x, y, z, pairs::Splat(0.0));
    });
}

inline void LowerTo(const Slab& record, const PointLanes& points, double* values)
{
  detail::LowerTo(points, values,
    [&](pairs::Lanes x, pairs::Lanes y, pairs::Lanes z)
    {
      return kernels::SlabValues(detail::SplatFields{ record.data() }, x, y, z, pairs::Splat(0.0),
        pairs::Splat(1.0), pairs::Splat(std::numeric_limits<double>::infinity()));
    });
}
}
}

#endif
