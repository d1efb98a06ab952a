// SPDX-License-Identifier: GPL-3.0-or-later
#include "Structure/WallSheets.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace medialaxis
{
double RadiusSlope(
  const Point3& a, const Point3& b, const Point3& c, double ra, double rb, double rc)
{
  // grad r = x e1 + y e2 with (e_i . grad r) = r_i - r_a: a 2 x 2 Gram system.
  const Point3 e1 = b - a, e2 = c - a;
  const double g11 = Dot(e1, e1), g12 = Dot(e1, e2), g22 = Dot(e2, e2);
  const double det = g11 * g22 - g12 * g12;
  if (!(det > 1e-24 * g11 * g22))
  {
    return 1.0;
  }
  const double d1 = rb - ra, d2 = rc - ra;
  const double x = (d1 * g22 - d2 * g12) / det, y = (d2 * g11 - d1 * g12) / det;
  return Norm(x * e1 + y * e2);
}

namespace
{
// The value below which `fraction` of the total weight lies.
double WeightedQuantile(std::vector<std::pair<double, double>> valueWeight, double fraction)
{
  if (valueWeight.empty())
  {
    return 0.0;
  }
  std::sort(valueWeight.begin(), valueWeight.end());
  double total = 0.0;
  for (const auto& vw : valueWeight)
  {
    total += vw.second;
  }
  double sum = 0.0;
  for (const auto& vw : valueWeight)
  {
    sum += vw.second;
    if (sum >= fraction * total)
    {
      return vw.first;
    }
  }
  return valueWeight.back().first;
}

double TriangleArea(const MedialMesh& mesh, const std::array<Index, 3>& f)
{
  const Point3& a = mesh.Centers[f[0]];
  return 0.5 * Norm(Cross(mesh.Centers[f[1]] - a, mesh.Centers[f[2]] - a));
}
}

double WallThicknessFromHistogram(
  const std::vector<double>& thickness, const std::vector<double>& area)
{
  std::vector<std::pair<double, double>> valueWeight;
  for (std::size_t i = 0; i < thickness.size(); ++i)
  {
    if (area[i] > 0.0)
    {
      valueWeight.emplace_back(thickness[i], area[i]);
    }
  }
  const double median = WeightedQuantile(valueWeight, 0.5);
  if (!(median > 0.0))
  {
    return 0.0;
  }
  // MidSurfer does not give its bin width; 5% of the typical thickness
  // separates walls that differ by more than manufacturing tolerances.
  const double width = 0.05 * median;
  std::vector<double> binArea;
  std::vector<double> binMaximum;
  for (const auto& vw : valueWeight)
  {
    // Bins centred on multiples of the width: the median is at the middle
    // of one, not on an edge.
    const std::size_t bin = static_cast<std::size_t>(std::floor(vw.first / width + 0.5));
    if (bin >= binArea.size())
    {
      binArea.resize(bin + 1, 0.0);
      binMaximum.resize(bin + 1, 0.0);
    }
    binArea[bin] += vw.second;
    binMaximum[bin] = std::max(binMaximum[bin], vw.first);
  }
  const std::size_t peak =
    static_cast<std::size_t>(std::max_element(binArea.begin(), binArea.end()) - binArea.begin());
  return binMaximum[peak];
}

WallSheets FindWallSheets(
  const MedialMesh& mesh, const MedialStructure& structure, const WallSheetOptions& options)
{
  WallSheets result;
  const std::size_t nf = mesh.Faces.size();
  result.FaceTaper.resize(nf);
  result.FaceThickness.resize(nf);
  result.FaceParallel.resize(nf);
  const double maximumSlope = std::sin(0.5 * std::min(options.MaximumNormalDeviation, Pi));
  std::vector<double> area(nf), parallelArea(nf, 0.0);
  for (std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = mesh.Faces[f];
    result.FaceTaper[f] = RadiusSlope(mesh.Centers[t[0]], mesh.Centers[t[1]], mesh.Centers[t[2]],
      mesh.Radii[t[0]], mesh.Radii[t[1]], mesh.Radii[t[2]]);
    result.FaceThickness[f] = 2.0 * (mesh.Radii[t[0]] + mesh.Radii[t[1]] + mesh.Radii[t[2]]) / 3.0;
    // Triangles of balls of radius 0 (fans along sharp edges) are no wall.
    const bool thick = mesh.Radii[t[0]] > 0.0 && mesh.Radii[t[1]] > 0.0 && mesh.Radii[t[2]] > 0.0;
    result.FaceParallel[f] = thick && result.FaceTaper[f] <= maximumSlope ? 1 : 0;
    area[f] = TriangleArea(mesh, t);
    parallelArea[f] = result.FaceParallel[f] ? area[f] : 0.0;
  }
  result.WallThickness = options.WallThickness > 0.0
    ? options.WallThickness
    : WallThicknessFromHistogram(result.FaceThickness, parallelArea);

  const std::size_t ns = structure.Sheets.size();
  std::vector<double> sheetArea(ns, 0.0), sheetParallel(ns, 0.0);
  std::vector<std::vector<std::pair<double, double>>> sheetThickness(ns);
  for (std::size_t f = 0; f < nf && f < structure.FaceSheet.size(); ++f)
  {
    const Index s = structure.FaceSheet[f];
    if (s < 0 || static_cast<std::size_t>(s) >= ns)
    {
      continue;
    }
    sheetArea[s] += area[f];
    if (result.FaceParallel[f])
    {
      sheetParallel[s] += area[f];
      sheetThickness[s].emplace_back(result.FaceThickness[f], area[f]);
    }
  }
  result.SheetIsWall.assign(ns, 0);
  for (std::size_t s = 0; s < ns; ++s)
  {
    const bool parallel =
      sheetArea[s] > 0.0 && sheetParallel[s] >= options.MinimumParallelFraction * sheetArea[s];
    // The 5% quantile rather than the minimum: a few parallel triangles at
    // a sheet's end are noise.
    const bool thin = parallel && WeightedQuantile(sheetThickness[s], 0.05) <= result.WallThickness;
    result.SheetIsWall[s] = parallel && thin ? 1 : 0;
    result.NumberOfWallSheets += result.SheetIsWall[s];
  }
  return result;
}
}
