// SPDX-License-Identifier: GPL-3.0-or-later
// The envelope primitives' values over several lanes at once, written once
// for every lane type: two lanes (PrimitivePairs.h, SSE2) and four
// (PrimitiveQuads.cxx, AVX2). Each expression keeps the order of operations
// of the scalar CompactValue (EnvelopeDistance.cxx), so every lane's value is
// bit-identical to it. A lane type L provides + - * /, Sqrt, Abs, the
// comparisons LessEqual, Less, GreaterEqual and Greater (giving a mask with
// |), and Select(mask, yes, no), found by argument-dependent lookup;
// field(f) gives field f of the records for every lane.
//
// No includes, on purpose: the AVX2 translation unit includes this header
// and no C++ library header (see PrimitiveQuads.h). It may define
// MEDIALAXIS_LANE_KERNEL (the functions' attributes) before including it.
#ifndef medialaxis_PrimitiveKernels_h
#define medialaxis_PrimitiveKernels_h

#ifndef MEDIALAXIS_LANE_KERNEL
#define MEDIALAXIS_LANE_KERNEL inline
#endif

namespace medialaxis
{
namespace kernels
{
/// Fields of a round record (spheres and cones, CompactValue kinds 0 and 1):
/// C0 (3), R0, axis (3), sin phi, cos phi, length cos phi, C1 (3), R1. A
/// sphere is a cone with a zero axis, sin 1 and cos 0, which always takes the
/// C0 cap. Slab records: the 24 fields of a slab interior's compact record.
constexpr int RoundFields = 14, SlabFields = 24;

/// Values of spheres or cones at p = (px, py, pz); zero: 0 in every lane.
template <typename L, typename Field>
MEDIALAXIS_LANE_KERNEL L RoundValues(const Field& field, L px, L py, L pz, L zero)
{
  const L vx = px - field(0), vy = py - field(1), vz = pz - field(2);
  const L ax = field(4), ay = field(5), az = field(6);
  const L a = vx * ax + vy * ay + vz * az;
  const L wx = vx - a * ax, wy = vy - a * ay, wz = vz - a * az;
  const L w = Sqrt(wx * wx + wy * wy + wz * wz);
  const L sinPhi = field(7), cosPhi = field(8);
  const L s = a * cosPhi - w * sinPhi;
  const L r0 = field(3);
  const L cap0 = Sqrt(vx * vx + vy * vy + vz * vz) - r0;
  const L ux = px - field(10), uy = py - field(11), uz = pz - field(12);
  const L cap1 = Sqrt(ux * ux + uy * uy + uz * uz) - field(13);
  const L side = a * sinPhi + w * cosPhi - r0;
  return Select(LessEqual(s, zero), cap0, Select(GreaterEqual(s, field(9)), cap1, side));
}

/// Values of slab interiors at p (infinity outside their regions); zero,
/// one and infinity in every lane.
template <typename L, typename Field>
MEDIALAXIS_LANE_KERNEL L SlabValues(const Field& field, L px, L py, L pz, L zero, L one, L infinity)
{
  const L cx = field(0), cy = field(1), cz = field(2);
  const L dx = px - cx, dy = py - cy, dz = pz - cz;
  const L height = dx * field(3) + dy * field(4) + dz * field(5);
  const auto upper = GreaterEqual(height, zero);
  const L nx = Select(upper, field(6), field(9));
  const L ny = Select(upper, field(7), field(10));
  const L nz = Select(upper, field(8), field(11));
  const L offset = Select(upper, field(12), field(13));
  const L t = Abs(height) / field(14);
  const L vx = (px - t * nx) - cx, vy = (py - t * ny) - cy, vz = (pz - t * nz) - cz;
  const L d1 = vx * field(15) + vy * field(16) + vz * field(17);
  const L d2 = vx * field(18) + vy * field(19) + vz * field(20);
  const L g12 = field(22);
  const L b1 = field(21) * d1 + g12 * d2;
  const L b2 = g12 * d1 + field(23) * d2;
  const auto outside = Less(b1, zero) | Less(b2, zero) | Greater(b1 + b2, one);
  const L plane = nx * px + ny * py + nz * pz - offset;
  return Select(outside, infinity, plane);
}
}
}

#endif
