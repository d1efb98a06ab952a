// SPDX-License-Identifier: GPL-3.0-or-later
// Spherical quadric error metric (SQEM, Thiery et al. 2013) over surface
// patches: for a sphere s = (v, r) written as the 4-vector x = (v, r), the
// squared signed distance to the plane of a surface facet (point a, unit
// outward normal n) is d = n.(a - v) - r = n.a - w.x with w = (n, 1), so
// d^2 = x^T (w w^T) x - 2 (n.a) w^T x + (n.a)^2. Integrated over a planar
// facet the distance is constant, so a facet contributes area x that.
#ifndef medialaxis_SphereQuadric_h
#define medialaxis_SphereQuadric_h

#include "Geometry/Types.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace medialaxis
{
/// Stored packed: the 10 distinct entries of the symmetric A, then B and C,
/// 15 doubles padded to 16 and aligned so that one quadric spans exactly two
/// cache lines (the simplifier adds and subtracts millions of them).
struct alignas(64) SphereQuadric
{
  // energy = x^T A x - 2 B^T x + C, A symmetric 4 x 4.
  std::array<double, 16> Data{};

  static constexpr int Packed(int i, int j)
  {
    return i <= j ? i * 4 - i * (i + 1) / 2 + j : j * 4 - j * (j + 1) / 2 + i;
  }
  double A(int i, int j) const { return this->Data[Packed(i, j)]; }
  double& A(int i, int j) { return this->Data[Packed(i, j)]; }
  double B(int i) const { return this->Data[10 + i]; }
  double& B(int i) { return this->Data[10 + i]; }
  double C() const { return this->Data[14]; }
  double& C() { return this->Data[14]; }

  void AddFacet(const Point3& n, double offset, double area)
  {
    const double w[4] = { n[0], n[1], n[2], 1.0 };
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i; j < 4; ++j)
      {
        this->A(i, j) += area * w[i] * w[j];
      }
      this->B(i) += area * offset * w[i];
    }
    this->C() += area * offset * offset;
  }

  SphereQuadric& operator+=(const SphereQuadric& o)
  {
    for (int k = 0; k < 15; ++k)
    {
      this->Data[k] += o.Data[k];
    }
    return *this;
  }

  SphereQuadric& operator-=(const SphereQuadric& o)
  {
    for (int k = 0; k < 15; ++k)
    {
      this->Data[k] -= o.Data[k];
    }
    return *this;
  }

  /// The gradient of the energy is 2 (A x - B).
  std::array<double, 4> Times(const std::array<double, 4>& x) const
  {
    std::array<double, 4> y{};
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        y[i] += this->A(i, j) * x[j];
      }
    }
    return y;
  }

  double Evaluate(const std::array<double, 4>& x) const
  {
    const std::array<double, 4> ax = this->Times(x);
    double e = this->C();
    for (int i = 0; i < 4; ++i)
    {
      e += x[i] * ax[i] - 2.0 * this->B(i) * x[i];
    }
    return e;
  }
};

/// Solves the top-left N x N block of the quadric's system A x = B (the
/// minimiser over the first N coordinates). A is a sum of outer products:
/// symmetric positive semi-definite, so LDL^T with symmetric pivoting on the
/// largest remaining diagonal entry, refusing nearly singular systems
/// (false). Written out for a fixed N <= 4 because Eigen's LDLT runs on
/// dynamic-size blocks internally, which made these tiny solves a sixth of
/// the simplifiers' time.
template <int N>
bool SolveQuadric(const SphereQuadric& q, Eigen::Matrix<double, N, 1>& x)
{
  static_assert(N >= 1 && N <= 4, "a sphere has four coordinates");
  // Full symmetric copy, eliminated in place in pivot order: order[k] is the
  // k-th pivot's coordinate; below the diagonal (in that order) L, on it D.
  double a[N][N];
  double b[N];
  int order[N];
  for (int i = 0; i < N; ++i)
  {
    for (int j = 0; j < N; ++j)
    {
      a[i][j] = q.A(i, j);
    }
    b[i] = q.B(i);
    order[i] = i;
  }
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < N; ++k)
  {
    int pivot = k; // the largest remaining diagonal entry
    for (int i = k + 1; i < N; ++i)
    {
      if (std::abs(a[order[i]][order[i]]) > std::abs(a[order[pivot]][order[pivot]]))
      {
        pivot = i;
      }
    }
    std::swap(order[k], order[pivot]);
    const int pk = order[k];
    const double d = a[pk][pk];
    largest = std::max(largest, std::abs(d));
    smallest = std::min(smallest, std::abs(d));
    if (d == 0.0)
    {
      return false;
    }
    for (int i = k + 1; i < N; ++i)
    {
      const int pi = order[i];
      const double l = a[pi][pk] / d;
      for (int j = k + 1; j <= i; ++j)
      {
        const int pj = order[j];
        a[pi][pj] -= l * a[pj][pk];
        a[pj][pi] = a[pi][pj];
      }
    }
    for (int i = k + 1; i < N; ++i)
    {
      a[order[i]][pk] /= d;
    }
  }
  if (!(smallest > 1e-12 * largest))
  {
    return false;
  }
  // L z = b, D w = z, L^T u = w, in pivot order.
  double u[N];
  for (int i = 0; i < N; ++i)
  {
    u[i] = b[order[i]];
    for (int j = 0; j < i; ++j)
    {
      u[i] -= a[order[i]][order[j]] * u[j];
    }
  }
  for (int i = 0; i < N; ++i)
  {
    u[i] /= a[order[i]][order[i]];
  }
  for (int i = N - 1; i >= 0; --i)
  {
    for (int j = i + 1; j < N; ++j)
    {
      u[i] -= a[order[j]][order[i]] * u[j];
    }
    x[order[i]] = u[i];
  }
  return x.allFinite();
}
}

#endif
