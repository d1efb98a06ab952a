// SPDX-License-Identifier: GPL-3.0-or-later
// The kernels of PrimitiveKernels.h on four lanes (see PrimitiveQuads.h):
// only <immintrin.h> is included, and every function is internal to this
// file. (No FMA: "avx2" alone does not let the compiler fuse a multiply and
// an add, which would change the values.)
#include "Envelope/PrimitiveQuads.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#define MEDIALAXIS_AVX2 __attribute__((target("avx2"), always_inline)) inline
// The shared kernels, compiled for AVX2 here (their L4 instances are
// internal to this file).
#define MEDIALAXIS_LANE_KERNEL MEDIALAXIS_AVX2
#include "Envelope/PrimitiveKernels.h"

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

// Field f of two blocks of two: lanes 0-1 from `A`, 2-3 from `B`.
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

MEDIALAXIS_AVX2 void Round4(
  const TwoBlocks<kernels::RoundFields>& field, L4 px, L4 py, L4 pz, double* out)
{
  _mm256_storeu_pd(out, kernels::RoundValues(field, px, py, pz, Splat(0.0)).V);
}

MEDIALAXIS_AVX2 void Slab4(
  const TwoBlocks<kernels::SlabFields>& field, L4 px, L4 py, L4 pz, double* out)
{
  _mm256_storeu_pd(
    out, kernels::SlabValues(field, px, py, pz, Splat(0.0), Splat(1.0), Splat(__builtin_inf())).V);
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
  return HasAvx2() ? &AllBlocks<kernels::RoundFields, Round4> : nullptr;
}

BlockValues SlabBlockValues()
{
  return HasAvx2() ? &AllBlocks<kernels::SlabFields, Slab4> : nullptr;
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
