// SPDX-License-Identifier: GPL-3.0-or-later
// A scalar field sampled on a regular grid, read between the samples by
// trilinear interpolation: an unsigned distance field as users give it.
#ifndef medialaxis_RegularField_h
#define medialaxis_RegularField_h

#include "Geometry/Types.h"

#include <array>
#include <vector>

namespace medialaxis
{
struct RegularField
{
  Point3 Origin{ 0, 0, 0 };
  std::array<double, 3> Spacing{ 1, 1, 1 };
  std::array<int, 3> Dimensions{ 0, 0, 0 };
  std::vector<double> Values; // x fastest, then y, then z

  std::size_t Index(int i, int j, int k) const
  {
    return (static_cast<std::size_t>(k) * this->Dimensions[1] + j) * this->Dimensions[0] + i;
  }
  Point3 PointAt(int i, int j, int k) const
  {
    return { this->Origin[0] + i * this->Spacing[0], this->Origin[1] + j * this->Spacing[1],
      this->Origin[2] + k * this->Spacing[2] };
  }
  /// The trilinear interpolant at p (p clamped into the grid).
  double Value(const Point3& p) const;
  /// The interpolant's gradient at p (p clamped into the grid).
  Point3 Gradient(const Point3& p) const;
  double LargestSpacing() const;
};

/// Where a sampled field cannot be a distance: a distance changes by no
/// more than the distance between two points, so neighbouring grid points
/// (along an axis) whose values differ by more than `slack` times their
/// spacing were sampled wrongly.
struct DistanceCheck
{
  std::size_t Violations = 0; // neighbouring pairs that break the bound
  double Worst = 0.0;         // the largest difference, in spacings
  Point3 First{ 0, 0, 0 };    // a grid point of the first such pair
};
DistanceCheck CheckDistanceBound(const RegularField& field, double slack);
}

#endif
