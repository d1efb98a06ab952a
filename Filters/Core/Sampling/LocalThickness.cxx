// SPDX-License-Identifier: GPL-3.0-or-later
#include "Sampling/LocalThickness.h"

#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
namespace
{
// Two unit vectors completing n to an orthonormal frame (Duff et al. 2017).
void Frame(const Point3& n, Point3& u, Point3& v)
{
  const double sign = std::copysign(1.0, n[2]);
  const double a = -1.0 / (sign + n[2]);
  const double b = n[0] * n[1] * a;
  u = { 1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0] };
  v = { b, sign + n[1] * n[1] * a, -n[1] };
}
}

std::vector<double> EstimateLocalThickness(const TriangleMesh& surface,
  const TriangleLocator& locator, const std::vector<Point3>& points,
  const std::vector<Index>& triangles, const ThicknessOptions& options)
{
  const auto [lo, hi] = BoundingBox(surface.Points);
  const double diagonal = std::sqrt(Distance2(lo, hi));
  // Hits nearer than this are the start's own neighbourhood, not the far side.
  const double nearest = 1e-9 * diagonal;
  const int rays = std::max(1, options.Rays);
  const double angle = options.ConeAngleDegrees * Pi / 180.0;

  std::vector<double> thickness(points.size(), std::numeric_limits<double>::infinity());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      std::vector<double> lengths;
      for (std::size_t i = range.begin(); i != range.end(); ++i)
      {
        const Point3 inward = -1.0 * TriangleNormal(surface, triangles[i]);
        if (!(Dot(inward, inward) > 0.5))
        {
          continue; // a degenerate triangle has no normal
        }
        Point3 u, v;
        Frame(inward, u, v);
        lengths.clear();
        // Once more than half the rays have reached MaximumThickness, the
        // median is that whatever the others find (a hit is at most as far,
        // up to rounding, and it could only take a place above the middle):
        // the rest are not cast.
        int atMaximum = 0;
        for (int r = 0; r < rays && 2 * atMaximum <= rays; ++r)
        {
          Point3 direction = inward;
          if (r > 0)
          {
            const double around = 2.0 * Pi * (r - 1) / (rays - 1);
            direction = std::cos(angle) * inward +
              std::sin(angle) * (std::cos(around) * u + std::sin(around) * v);
          }
          const double cosine = Dot(direction, inward);
          const double reach = std::min(2.0 * diagonal, options.MaximumThickness / cosine);
          const TriangleLocator::RayHit hit =
            locator.FirstHit(points[i], direction, nearest, reach, triangles[i]);
          if (hit.Triangle < 0)
          {
            if (reach < 2.0 * diagonal)
            {
              lengths.push_back(options.MaximumThickness); // at least this thick
              ++atMaximum;
            }
          }
          // The first crossing must leave the solid: a hit on a face turned
          // towards the ray means it started outside (off a convex crease).
          else if (Dot(TriangleNormal(surface, hit.Triangle), direction) > 0.0)
          {
            lengths.push_back(hit.Distance * cosine);
          }
        }
        if (2 * lengths.size() >= static_cast<std::size_t>(rays))
        {
          auto middle = lengths.begin() + lengths.size() / 2;
          std::nth_element(lengths.begin(), middle, lengths.end());
          thickness[i] = *middle;
        }
      }
    });
  return thickness;
}
}
