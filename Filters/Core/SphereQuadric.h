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

#include <array>

namespace medialaxis
{
struct SphereQuadric
{
  std::array<double, 16> A{}; // 4 x 4, row-major, symmetric
  std::array<double, 4> B{};  // energy = x^T A x - 2 B^T x + C
  double C = 0.0;

  void AddFacet(const Point3& n, double offset, double area)
  {
    const double w[4] = { n[0], n[1], n[2], 1.0 };
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        this->A[4 * i + j] += area * w[i] * w[j];
      }
      this->B[i] += area * offset * w[i];
    }
    this->C += area * offset * offset;
  }

  SphereQuadric& operator+=(const SphereQuadric& o)
  {
    for (int k = 0; k < 16; ++k)
    {
      this->A[k] += o.A[k];
    }
    for (int k = 0; k < 4; ++k)
    {
      this->B[k] += o.B[k];
    }
    this->C += o.C;
    return *this;
  }

  SphereQuadric& operator-=(const SphereQuadric& o)
  {
    for (int k = 0; k < 16; ++k)
    {
      this->A[k] -= o.A[k];
    }
    for (int k = 0; k < 4; ++k)
    {
      this->B[k] -= o.B[k];
    }
    this->C -= o.C;
    return *this;
  }

  double Evaluate(const std::array<double, 4>& x) const
  {
    double e = this->C;
    for (int i = 0; i < 4; ++i)
    {
      double row = 0.0;
      for (int j = 0; j < 4; ++j)
      {
        row += this->A[4 * i + j] * x[j];
      }
      e += x[i] * row - 2.0 * this->B[i] * x[i];
    }
    return e;
  }
};
}

#endif
