// SPDX-License-Identifier: GPL-3.0-or-later
#include "Udf/RegularField.h"

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
// The cell holding p and p's local coordinates in it, in [0, 1].
struct CellCoordinates
{
  std::array<int, 3> Cell;
  std::array<double, 3> Local;
};

CellCoordinates Locate(const RegularField& f, const Point3& p)
{
  CellCoordinates c{};
  for (int a = 0; a < 3; ++a)
  {
    const int cells = std::max(f.Dimensions[a] - 1, 1);
    const double t = std::clamp((p[a] - f.Origin[a]) / f.Spacing[a], 0.0, double(cells));
    c.Cell[a] = std::min(static_cast<int>(t), cells - 1);
    c.Local[a] = f.Dimensions[a] > 1 ? t - c.Cell[a] : 0.0;
  }
  return c;
}

// The eight corner values, corner (dx, dy, dz) at dx + 2 dy + 4 dz.
std::array<double, 8> Corners(const RegularField& f, const CellCoordinates& c)
{
  std::array<double, 8> v{};
  for (int corner = 0; corner < 8; ++corner)
  {
    const int i = std::min(c.Cell[0] + (corner & 1), f.Dimensions[0] - 1);
    const int j = std::min(c.Cell[1] + ((corner >> 1) & 1), f.Dimensions[1] - 1);
    const int k = std::min(c.Cell[2] + ((corner >> 2) & 1), f.Dimensions[2] - 1);
    v[corner] = f.Values[f.Index(i, j, k)];
  }
  return v;
}
}

double RegularField::Value(const Point3& p) const
{
  const CellCoordinates c = Locate(*this, p);
  const std::array<double, 8> v = Corners(*this, c);
  const auto [x, y, z] = c.Local;
  const double bottom = (1 - y) * ((1 - x) * v[0] + x * v[1]) + y * ((1 - x) * v[2] + x * v[3]);
  const double top = (1 - y) * ((1 - x) * v[4] + x * v[5]) + y * ((1 - x) * v[6] + x * v[7]);
  return (1 - z) * bottom + z * top;
}

Point3 RegularField::Gradient(const Point3& p) const
{
  const CellCoordinates c = Locate(*this, p);
  const std::array<double, 8> v = Corners(*this, c);
  const auto [x, y, z] = c.Local;
  auto lerp = [](double a, double b, double t) { return (1 - t) * a + t * b; };
  const double dx = lerp(lerp(v[1] - v[0], v[3] - v[2], y), lerp(v[5] - v[4], v[7] - v[6], y), z);
  const double dy = lerp(lerp(v[2] - v[0], v[3] - v[1], x), lerp(v[6] - v[4], v[7] - v[5], x), z);
  const double dz = lerp(lerp(v[4] - v[0], v[5] - v[1], x), lerp(v[6] - v[2], v[7] - v[3], x), y);
  return { dx / this->Spacing[0], dy / this->Spacing[1], dz / this->Spacing[2] };
}

double RegularField::LargestSpacing() const
{
  return std::max({ this->Spacing[0], this->Spacing[1], this->Spacing[2] });
}

DistanceCheck CheckDistanceBound(const RegularField& field, double slack)
{
  DistanceCheck check;
  const auto& n = field.Dimensions;
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = 0; i < n[0]; ++i)
      {
        const double value = field.Values[field.Index(i, j, k)];
        const std::array<int, 3> at{ i, j, k };
        for (int a = 0; a < 3; ++a)
        {
          if (at[a] + 1 >= n[a])
          {
            continue;
          }
          std::array<int, 3> next = at;
          ++next[a];
          const double step =
            std::abs(field.Values[field.Index(next[0], next[1], next[2])] - value) /
            field.Spacing[a];
          if (step > slack)
          {
            if (check.Violations++ == 0)
            {
              check.First = field.PointAt(i, j, k);
            }
            check.Worst = std::max(check.Worst, step);
          }
        }
      }
    }
  }
  return check;
}
}
