// SPDX-License-Identifier: GPL-3.0-or-later
// Signed distances of two envelope primitives at once, for the leaf scans of
// the envelope searches (EnvelopeDistance.cxx), which evaluate most of their
// primitives in runs; and their hull bounds, two axes at a time. The primitives of a leaf are
// stored in blocks of two, field by field (block[2 f + lane]), so that one SSE2 step (baseline
// x86-64) serves both. Every lane takes the same operations in the same order as the scalar
// CompactValue, branch-free: the values are bit-identical to it (the kernels, shared with the AVX2
// lanes of PrimitiveQuads.cxx, are in PrimitiveKernels.h). Written by hand because no library we
// use vectorises a mixed distance-function loop like this one; without SSE2 two scalar lanes.
#ifndef medialaxis_PrimitivePairs_h
#define medialaxis_PrimitivePairs_h

#include <algorithm>
#include <cmath>
#include <limits>

#include "Envelope/PrimitiveKernels.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace medialaxis
{
namespace pairs
{
/// Fields of a round block and of a slab block (see PrimitiveKernels.h).
constexpr int RoundFields = kernels::RoundFields, SlabFields = kernels::SlabFields;

#if defined(__SSE2__)
struct Lanes
{
  __m128d V;
};
struct Mask
{
  __m128d M;
};
inline Lanes Load(const double* d)
{
  return { _mm_loadu_pd(d) };
}
inline Lanes Splat(double x)
{
  return { _mm_set1_pd(x) };
}
inline Lanes operator+(Lanes a, Lanes b)
{
  return { _mm_add_pd(a.V, b.V) };
}
inline Lanes operator-(Lanes a, Lanes b)
{
  return { _mm_sub_pd(a.V, b.V) };
}
inline Lanes operator*(Lanes a, Lanes b)
{
  return { _mm_mul_pd(a.V, b.V) };
}
inline Lanes operator/(Lanes a, Lanes b)
{
  return { _mm_div_pd(a.V, b.V) };
}
inline Lanes Sqrt(Lanes a)
{
  return { _mm_sqrt_pd(a.V) };
}
inline Lanes Abs(Lanes a)
{
  return { _mm_andnot_pd(_mm_set1_pd(-0.0), a.V) };
}
inline Mask LessEqual(Lanes a, Lanes b)
{
  return { _mm_cmple_pd(a.V, b.V) };
}
inline Mask Less(Lanes a, Lanes b)
{
  return { _mm_cmplt_pd(a.V, b.V) };
}
inline Mask GreaterEqual(Lanes a, Lanes b)
{
  return { _mm_cmpge_pd(a.V, b.V) };
}
inline Mask Greater(Lanes a, Lanes b)
{
  return { _mm_cmpgt_pd(a.V, b.V) };
}
inline Mask operator|(Mask a, Mask b)
{
  return { _mm_or_pd(a.M, b.M) };
}
inline Lanes Select(Mask m, Lanes yes, Lanes no)
{
  return { _mm_or_pd(_mm_and_pd(m.M, yes.V), _mm_andnot_pd(m.M, no.V)) };
}
inline void Store(Lanes a, double out[2])
{
  _mm_storeu_pd(out, a.V);
}
inline Lanes Max(Lanes a, Lanes b)
{
  return { _mm_max_pd(a.V, b.V) };
}
inline double Largest(Lanes a)
{
  return std::max(_mm_cvtsd_f64(a.V), _mm_cvtsd_f64(_mm_unpackhi_pd(a.V, a.V)));
}
#else
struct Lanes
{
  double V[2];
};
struct Mask
{
  bool M[2];
};
inline Lanes Load(const double* d)
{
  return { { d[0], d[1] } };
}
inline Lanes Splat(double x)
{
  return { { x, x } };
}
#define MEDIALAXIS_PAIRS_OP(op)                                                                    \
  inline Lanes operator op(Lanes a, Lanes b)                                                       \
  {                                                                                                \
    return { { a.V[0] op b.V[0], a.V[1] op b.V[1] } };                                             \
  }
MEDIALAXIS_PAIRS_OP(+)
MEDIALAXIS_PAIRS_OP(-)
MEDIALAXIS_PAIRS_OP(*)
MEDIALAXIS_PAIRS_OP(/)
#undef MEDIALAXIS_PAIRS_OP
#define MEDIALAXIS_PAIRS_CMP(name, op)                                                             \
  inline Mask name(Lanes a, Lanes b)                                                               \
  {                                                                                                \
    return { { a.V[0] op b.V[0], a.V[1] op b.V[1] } };                                             \
  }
MEDIALAXIS_PAIRS_CMP(LessEqual, <=)
MEDIALAXIS_PAIRS_CMP(Less, <)
MEDIALAXIS_PAIRS_CMP(GreaterEqual, >=)
MEDIALAXIS_PAIRS_CMP(Greater, >)
#undef MEDIALAXIS_PAIRS_CMP
inline Lanes Sqrt(Lanes a)
{
  return { { std::sqrt(a.V[0]), std::sqrt(a.V[1]) } };
}
inline Lanes Abs(Lanes a)
{
  return { { std::abs(a.V[0]), std::abs(a.V[1]) } };
}
inline Mask operator|(Mask a, Mask b)
{
  return { { a.M[0] || b.M[0], a.M[1] || b.M[1] } };
}
inline Lanes Select(Mask m, Lanes yes, Lanes no)
{
  return { { m.M[0] ? yes.V[0] : no.V[0], m.M[1] ? yes.V[1] : no.V[1] } };
}
inline void Store(Lanes a, double out[2])
{
  out[0] = a.V[0];
  out[1] = a.V[1];
}
inline Lanes Max(Lanes a, Lanes b)
{
  return { { std::max(a.V[0], b.V[0]), std::max(a.V[1], b.V[1]) } };
}
inline double Largest(Lanes a)
{
  return std::max(a.V[0], a.V[1]);
}
#endif

/// The signed distance bound of a k-DOP (slabs lo[i] <= u_i . x <= hi[i]) at
/// a point with projections t: max over i of t[i] - hi[i] and lo[i] - t[i],
/// as two lanes whose Largest is the bound (max is exact: any grouping gives
/// the scalar loop's value). The hottest bound of every envelope search.
template <int K>
inline Lanes HullBound(const double* t, const double* lo, const double* hi)
{
  const double last = std::max(t[K - 1] - hi[K - 1], lo[K - 1] - t[K - 1]);
  Lanes b = Splat(last);
  for (int k = 0; k + 1 < K; k += 2)
  {
    const Lanes tk = Load(t + k);
    b = Max(b, Max(tk - Load(hi + k), Load(lo + k) - tk));
  }
  return b;
}

/// Point p, splatted once per query (and as it is, for other kernels).
struct Query
{
  Lanes X, Y, Z;
  const double* Point;
  explicit Query(const double p[3])
    : X(Splat(p[0]))
    , Y(Splat(p[1]))
    , Z(Splat(p[2]))
    , Point(p)
  {
  }
};

/// Field f of a block, both lanes.
inline Lanes Field(const double* block, int f)
{
  return Load(block + 2 * f);
}

/// Field f of one block of two, for the kernels of PrimitiveKernels.h.
struct BlockFields
{
  const double* Block;
  Lanes operator()(int f) const { return Field(this->Block, f); }
};

/// The values of the two spheres or cones of a round block at p.
inline void RoundValues(const double* b, const Query& p, double out[2])
{
  Store(kernels::RoundValues(BlockFields{ b }, p.X, p.Y, p.Z, Splat(0.0)), out);
}

/// The values of the two slab interiors of a slab block at p.
inline void SlabValues(const double* b, const Query& p, double out[2])
{
  Store(kernels::SlabValues(BlockFields{ b }, p.X, p.Y, p.Z, Splat(0.0), Splat(1.0),
          Splat(std::numeric_limits<double>::infinity())),
    out);
}
}
}

#endif
