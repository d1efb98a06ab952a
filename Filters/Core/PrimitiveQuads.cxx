// SPDX-License-Identifier: GPL-3.0-or-later
// AVX2 versions of the kernels of PrimitivePairs.h (see PrimitiveQuads.h):
// only <immintrin.h> is included, and every function is internal to this
// file. Keep each expression in the order of PrimitivePairs.h: the results
// must stay bit-identical to it. (No FMA: "avx2" alone does not let the
// compiler fuse a multiply and an add.)
#include "PrimitiveQuads.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#define MEDIALAXIS_AVX2 __attribute__((target("avx2"), always_inline)) inline

namespace medialaxis
{
namespace quads
{
namespace
{
struct L4
{
  __m256d V;
};
struct M4
{
  __m256d M;
};
MEDIALAXIS_AVX2 L4 operator+(L4 a, L4 b)
{
  return { _mm256_add_pd(a.V, b.V) };
}
MEDIALAXIS_AVX2 L4 operator-(L4 a, L4 b)
{
  return { _mm256_sub_pd(a.V, b.V) };
}
MEDIALAXIS_AVX2 L4 operator*(L4 a, L4 b)
{
  return { _mm256_mul_pd(a.V, b.V) };
}
MEDIALAXIS_AVX2 L4 operator/(L4 a, L4 b)
{
  return { _mm256_div_pd(a.V, b.V) };
}
MEDIALAXIS_AVX2 L4 Sqrt(L4 a)
{
  return { _mm256_sqrt_pd(a.V) };
}
MEDIALAXIS_AVX2 L4 Abs(L4 a)
{
  return { _mm256_andnot_pd(_mm256_set1_pd(-0.0), a.V) };
}
MEDIALAXIS_AVX2 L4 Splat(double x)
{
  return { _mm256_set1_pd(x) };
}
// The SSE2 comparisons are false when an operand is NaN: ordered ones here.
MEDIALAXIS_AVX2 M4 LessEqual(L4 a, L4 b)
{
  return { _mm256_cmp_pd(a.V, b.V, _CMP_LE_OQ) };
}
MEDIALAXIS_AVX2 M4 Less(L4 a, L4 b)
{
  return { _mm256_cmp_pd(a.V, b.V, _CMP_LT_OQ) };
}
MEDIALAXIS_AVX2 M4 GreaterEqual(L4 a, L4 b)
{
  return { _mm256_cmp_pd(a.V, b.V, _CMP_GE_OQ) };
}
MEDIALAXIS_AVX2 M4 Greater(L4 a, L4 b)
{
  return { _mm256_cmp_pd(a.V, b.V, _CMP_GT_OQ) };
}
MEDIALAXIS_AVX2 M4 operator|(M4 a, M4 b)
{
  return { _mm256_or_pd(a.M, b.M) };
}
MEDIALAXIS_AVX2 L4 Select(M4 m, L4 yes, L4 no)
{
  return { _mm256_blendv_pd(no.V, yes.V, m.M) };
}

// Field f of two blocks of two: lanes 0-1 from `a`, 2-3 from `b`.
template <int Fields>
struct TwoBlocks
{
  const double* A;
  const double* B;
  MEDIALAXIS_AVX2 L4 operator()(int f) const
  {
    return { _mm256_insertf128_pd(
      _mm256_castpd128_pd256(_mm_loadu_pd(this->A + 2 * f)), _mm_loadu_pd(this->B + 2 * f), 1) };
  }
};

// pairs::RoundValues, four lanes.
MEDIALAXIS_AVX2 void Round4(const TwoBlocks<14>& field, L4 px, L4 py, L4 pz, double* out)
{
  const L4 vx = px - field(0), vy = py - field(1), vz = pz - field(2);
  const L4 ax = field(4), ay = field(5), az = field(6);
  const L4 a = vx * ax + vy * ay + vz * az;
  const L4 wx = vx - a * ax, wy = vy - a * ay, wz = vz - a * az;
  const L4 w = Sqrt(wx * wx + wy * wy + wz * wz);
  const L4 sinPhi = field(7), cosPhi = field(8);
  const L4 s = a * cosPhi - w * sinPhi;
  const L4 r0 = field(3);
  const L4 cap0 = Sqrt(vx * vx + vy * vy + vz * vz) - r0;
  const L4 ux = px - field(10), uy = py - field(11), uz = pz - field(12);
  const L4 cap1 = Sqrt(ux * ux + uy * uy + uz * uz) - field(13);
  const L4 side = a * sinPhi + w * cosPhi - r0;
  _mm256_storeu_pd(
    out, Select(LessEqual(s, Splat(0.0)), cap0, Select(GreaterEqual(s, field(9)), cap1, side)).V);
}

// pairs::SlabValues, four lanes.
MEDIALAXIS_AVX2 void Slab4(const TwoBlocks<24>& field, L4 px, L4 py, L4 pz, double* out)
{
  const L4 cx = field(0), cy = field(1), cz = field(2);
  const L4 dx = px - cx, dy = py - cy, dz = pz - cz;
  const L4 height = dx * field(3) + dy * field(4) + dz * field(5);
  const M4 upper = GreaterEqual(height, Splat(0.0));
  const L4 nx = Select(upper, field(6), field(9));
  const L4 ny = Select(upper, field(7), field(10));
  const L4 nz = Select(upper, field(8), field(11));
  const L4 offset = Select(upper, field(12), field(13));
  const L4 t = Abs(height) / field(14);
  const L4 vx = (px - t * nx) - cx, vy = (py - t * ny) - cy, vz = (pz - t * nz) - cz;
  const L4 d1 = vx * field(15) + vy * field(16) + vz * field(17);
  const L4 d2 = vx * field(18) + vy * field(19) + vz * field(20);
  const L4 g12 = field(22);
  const L4 b1 = field(21) * d1 + g12 * d2;
  const L4 b2 = g12 * d1 + field(23) * d2;
  const L4 zero = Splat(0.0);
  const M4 outside = Less(b1, zero) | Less(b2, zero) | Greater(b1 + b2, Splat(1.0));
  const L4 plane = nx * px + ny * py + nz * pz - offset;
  _mm256_storeu_pd(out, Select(outside, Splat(__builtin_inf()), plane).V);
}

// All blocks, two at a time; an odd last block is paired with itself.
template <int Fields, void (*Kernel)(const TwoBlocks<Fields>&, L4, L4, L4, double*)>
__attribute__((target("avx2"))) void AllBlocks(
  const double* block, int blocks, const double* p, double* out)
{
  const L4 px = Splat(p[0]), py = Splat(p[1]), pz = Splat(p[2]);
  int i = 0;
  for (; i + 1 < blocks; i += 2)
  {
    const double* a = block + 2 * Fields * i;
    Kernel(TwoBlocks<Fields>{ a, a + 2 * Fields }, px, py, pz, out + 2 * i);
  }
  if (i < blocks)
  {
    const double* a = block + 2 * Fields * i;
    double last[4];
    Kernel(TwoBlocks<Fields>{ a, a }, px, py, pz, last);
    out[2 * i] = last[0];
    out[2 * i + 1] = last[1];
  }
}

bool HasAvx2()
{
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}
}

BlockValues RoundBlockValues()
{
  return HasAvx2() ? &AllBlocks<14, Round4> : nullptr;
}

BlockValues SlabBlockValues()
{
  return HasAvx2() ? &AllBlocks<24, Slab4> : nullptr;
}
}
}

#else

namespace medialaxis
{
namespace quads
{
BlockValues RoundBlockValues()
{
  return nullptr;
}
BlockValues SlabBlockValues()
{
  return nullptr;
}
}
}

#endif
