// SPDX-License-Identifier: GPL-3.0-or-later
#include "Udf/UnsignedDistanceField.h"

#include "Mesh/TriangleLocator.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace medialaxis
{
RegularField GridAroundBox(const Box& bounds, std::array<int, 3> dimensions, int padding)
{
  RegularField field;
  double spacing = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    dimensions[a] = std::max(dimensions[a], 2);
    const int free =
      std::max(1, dimensions[a] - 1 - 2 * std::min(padding, (dimensions[a] - 3) / 2));
    spacing = std::max(spacing, (bounds.Hi[a] - bounds.Lo[a]) / free);
  }
  if (!(spacing > 0.0) || !std::isfinite(spacing))
  {
    field.Spacing = { 0, 0, 0 };
    return field;
  }
  for (int a = 0; a < 3; ++a)
  {
    field.Dimensions[a] = dimensions[a];
    field.Spacing[a] = spacing;
    field.Origin[a] = 0.5 * (bounds.Lo[a] + bounds.Hi[a]) - 0.5 * spacing * (dimensions[a] - 1);
  }
  return field;
}

bool SampleUnsignedDistance(
  const TriangleMesh& surface, RegularField& field, const std::function<bool(double)>& progress)
{
  const std::size_t total =
    static_cast<std::size_t>(field.Dimensions[0]) * field.Dimensions[1] * field.Dimensions[2];
  field.Values.assign(total, 0.0);
  if (total == 0 || surface.Triangles.empty())
  {
    return total == 0;
  }
  const TriangleLocator locator(surface);
  // Slabs of slices in parallel, progress between them from this thread.
  const int slices = field.Dimensions[2];
  const int slab = std::max(1, slices / 32);
  for (int first = 0; first < slices; first += slab)
  {
    const int last = std::min(slices, first + slab);
    tbb::parallel_for(first, last,
      [&](int k)
      {
        for (int j = 0; j < field.Dimensions[1]; ++j)
        {
          for (int i = 0; i < field.Dimensions[0]; ++i)
          {
            field.Values[field.Index(i, j, k)] = locator.Distance(field.PointAt(i, j, k));
          }
        }
      });
    if (progress && progress(static_cast<double>(last) / slices))
    {
      return false;
    }
  }
  return true;
}
}
