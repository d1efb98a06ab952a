// SPDX-License-Identifier: GPL-3.0-or-later
// Which sheets of a medial mesh are the middles of thin walls: sheets whose
// two sides are nearly parallel surface regions (MidSurfer's face pairs, seen
// from the medial axis) no thicker than the part's wall thickness.
#ifndef medialaxis_WallSheets_h
#define medialaxis_WallSheets_h

#include "Structure/MedialStructure.h"

#include <cstdint>
#include <vector>

namespace medialaxis
{
struct WallSheetOptions
{
  /// The thickest wall: a sheet is a wall only where its parallel part is
  /// this thin somewhere (its 5% area quantile). 0: automatic, MidSurfer's
  /// rule (WallThicknessFromHistogram).
  double WallThickness = 0.0;
  /// Largest angle, radians, between one side's normal and the opposite of
  /// the other side's for a triangle to join two parallel sides (MidSurfer's
  /// 15 degrees). A medial triangle's sides differ by 2 asin |grad r|.
  double MaximumNormalDeviation = 0.2617993877991494;
  /// Sheets whose parallel triangles make at least this share of their area
  /// are walls; the rest (branches to convex edges and corners, whose sides
  /// meet at an angle) are pruned.
  double MinimumParallelFraction = 0.5;
};

struct WallSheets
{
  /// Per face: |grad r|, the radius' slope along the triangle (0 between
  /// parallel sides), and 2 x its mean radius.
  std::vector<double> FaceTaper;
  std::vector<double> FaceThickness;
  std::vector<std::uint8_t> FaceParallel;
  /// Per sheet of the structure: a wall or not.
  std::vector<std::uint8_t> SheetIsWall;
  double WallThickness = 0.0; // as given, or estimated
  std::size_t NumberOfWallSheets = 0;
};

/// |grad r| of the radius interpolated linearly on the triangle (a, b, c);
/// 1 (sides meeting head-on) for a degenerate triangle.
double RadiusSlope(
  const Point3& a, const Point3& b, const Point3& c, double ra, double rb, double rc);

/// MidSurfer's automatic wall thickness: the area-weighted histogram of the
/// thicknesses (bins 5% of the median wide), and the largest thickness in
/// its fullest bin. 0 when no area.
double WallThicknessFromHistogram(
  const std::vector<double>& thickness, const std::vector<double>& area);

/// Classifies the sheets of `structure` (ClassifyMedialStructure of `mesh`).
WallSheets FindWallSheets(
  const MedialMesh& mesh, const MedialStructure& structure, const WallSheetOptions& options);
}

#endif
