// SPDX-License-Identifier: GPL-3.0-or-later
// The sheets of a medial mesh and how clean they are: a sheet is a maximal
// set of triangles connected across edges that have exactly two triangles,
// so that junction edges (three or more triangles) and sheet boundaries
// (one triangle) separate sheets. A clean medial axis has few, large sheets,
// no small fins hanging on them and no pleats.
#ifndef medialaxis_MedialSheets_h
#define medialaxis_MedialSheets_h

#include "Mesh/MedialMesh.h"

#include <cstddef>
#include <vector>

namespace medialaxis
{
/// Per triangle, the id of its sheet (0 .. count - 1, numbered by the lowest
/// triangle id in each sheet).
struct SheetDecomposition
{
  std::vector<Index> SheetOfTriangle;
  std::size_t NumberOfSheets = 0;
};

SheetDecomposition DecomposeIntoSheets(const MedialMesh& mesh);

/// Cleanliness of the medial sheets (triangles only; line cells ignored).
struct MedialCleanliness
{
  std::size_t Sheets = 0;
  /// N80: the fewest sheets that together hold 80% of the triangle area.
  std::size_t SheetsFor80PercentArea = 0;
  /// Share of the triangle area in the largest sheet.
  double LargestSheetAreaFraction = 0.0;
  /// Share of the triangle area in fins: sheets smaller than 1% of the area
  /// that touch a junction edge (an edge of three or more triangles).
  double FinAreaFraction = 0.0;
  /// Pleats: the share of two-triangle edges whose triangles meet at less
  /// than 90 degrees (the angle between the half-planes from the edge to
  /// each opposite vertex; 180 degrees is flat).
  double FoldedEdgeFraction = 0.0;
  std::size_t JunctionEdges = 0;
  /// Total length of the sheets' boundary (edges of one triangle) and of
  /// the junctions, in units of `diagonal` (see MeasureCleanliness).
  double BoundaryLength = 0.0;
  double JunctionLength = 0.0;
};

/// Sheets smaller than this share of the triangle area that touch a
/// junction edge are fins.
constexpr double FinAreaShare = 0.01;
/// Two-triangle edges whose half-planes meet below this angle are pleats.
constexpr double PleatAngleDegrees = 90.0;

/// The measures of MedialCleanliness; lengths are divided by `diagonal`
/// (e.g. the input surface's bounding-box diagonal; 1 keeps them absolute).
MedialCleanliness MeasureCleanliness(const MedialMesh& mesh, double diagonal = 1.0);
}

#endif
