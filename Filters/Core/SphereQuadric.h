// SPDX-License-Identifier: GPL-3.0-or-later
// Spherical quadric error metric (SQEM, Thiery et al. 2013) over surface
// patches: for a sphere s = (v, r) written as the 4-vector x = (v, r), the
// squared signed distance to the plane of a surface facet (point a, unit
// outward normal n) is d = n.(a - v) - r = n.a - w.x with w = (n, 1), so
// d^2 = x^T (w w^T) x - 2 (n.a) w^T x + (n.a)^2. Integrated over a planar
// facet the distance is constant, so a facet contributes area x that.
#ifndef medialaxis_SphereQuadric_h
#define medialaxis_SphereQuadric_h

#include "MedialMesh.h" // Point3

#include <Eigen/Dense>

#include <array>

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
/// symmetric positive semi-definite, so LDL^T, refusing nearly singular
/// systems (false).
template <int N>
bool SolveQuadric(const SphereQuadric& q, Eigen::Matrix<double, N, 1>& x)
{
  Eigen::Matrix<double, N, N> A;
  Eigen::Matrix<double, N, 1> B;
  for (int i = 0; i < N; ++i)
  {
    for (int j = 0; j < N; ++j)
    {
      A(i, j) = q.A(i, j);
    }
    B[i] = q.B(i);
  }
  const Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(A);
  const Eigen::Matrix<double, N, 1> pivots = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff()))
  {
    return false;
  }
  x = ldlt.solve(B);
  return x.allFinite();
}
}

#endif
