// SPDX-License-Identifier: GPL-3.0-or-later
// Thin-walled test parts whose mid-surfaces are known exactly: a plate with a
// perpendicular rib (T), an L-bracket and a wedge plate, each a cross-section
// in the (y, z) plane extruded along x.
#ifndef medialaxis_WallShapes_h
#define medialaxis_WallShapes_h

#include "Surface/AnalyticShapes.h"

#include <array>
#include <vector>

namespace medialaxis
{
/// A cross-section: its outline in (y, z), counter-clockwise, and the exact
/// area and perimeter of the curve it samples.
struct WallSection
{
  std::vector<std::array<double, 2>> Outline;
  double Area = 0.0;
  double Perimeter = 0.0;
};

/// A plate `width` wide (y from -width/2) and `thickness` thick (z from
/// -thickness/2), with a rib `thickness` thick standing `ribHeight` high on
/// the middle of its top face. filletRadius > 0 rounds the two concave
/// corners where the rib meets the plate (concave quarter circles); all other
/// edges are sharp. Mid-surfaces: z = 0 and y = 0 (z > thickness / 2).
/// `spacing` bounds the length of the outline's straight segments;
/// `resolution` is the number of segments along a quarter circle.
WallSection TPlateSection(double width, double ribHeight, double thickness, double filletRadius,
  double spacing, int resolution);

/// An L: a plate `width` long (y from 0) and a wall `height` high (z from 0),
/// both `thickness` thick, meeting at the outer corner (0, 0). filletRadius >
/// 0 rounds the inner corner with that radius and the outer one with
/// filletRadius + thickness, so the wall keeps its thickness around the bend;
/// 0 leaves both sharp. Mid-surface: z = t/2 and y = t/2, joined by a quarter
/// circle of radius filletRadius + t/2 around (t + filletRadius, t +
/// filletRadius) where rounded.
WallSection LBracketSection(double width, double height, double thickness, double filletRadius,
  double spacing, int resolution);

/// A plate `width` wide (y from -width/2) whose thickness varies linearly
/// from startThickness at y = -width/2 to endThickness at y = width/2,
/// symmetric about z = 0 (its mid-surface).
WallSection WedgePlateSection(
  double width, double startThickness, double endThickness, double spacing);

/// The closed surface of the section extruded along x from -length/2 to
/// length/2: the sides divided every `spacing` along x, the caps triangulated.
TriangleMesh ExtrudeSection(const WallSection& section, double length, double spacing);

/// Exact area and volume of the extruded section.
AreaVolume ExtrudedAreaVolume(const WallSection& section, double length);

/// Triangles of a simple polygon given counter-clockwise (indices into it).
std::vector<std::array<Index, 3>> TriangulatePolygon(
  const std::vector<std::array<double, 2>>& polygon);
}

#endif
