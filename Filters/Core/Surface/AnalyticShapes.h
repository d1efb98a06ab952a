// SPDX-License-Identifier: GPL-3.0-or-later
// Closed, manifold, outward-oriented triangle meshes of shapes whose medial
// axis is known exactly: the ground truths of the test suite. Every vertex
// lies exactly on the analytic surface.
#ifndef medialaxis_AnalyticShapes_h
#define medialaxis_AnalyticShapes_h

#include "Mesh/PolygonMesh.h"

namespace medialaxis
{
/// An axis-aligned box of the given full side lengths, centred at the origin,
/// whose edges and corners are rounded with radius `filletRadius` (quarter
/// cylinders on edges, sphere octants on corners): the Minkowski sum of a
/// smaller box with a ball. filletRadius = 0 gives a sharp box; equal sides
/// and filletRadius = side / 2 give a sphere. `resolution` is the number of
/// segments along a quarter circle (a sharp box uses it per side).
TriangleMesh MakeRoundedBox(const Point3& sides, double filletRadius, int resolution);

/// Sphere centred at the origin (a cube-sphere: rounded box with no flat part).
TriangleMesh MakeSphere(double radius, int resolution);

/// Capsule along z: the points within `radius` of the segment from
/// (0, 0, -axisLength / 2) to (0, 0, axisLength / 2).
TriangleMesh MakeCapsule(double radius, double axisLength, int resolution);

/// Torus around the z axis with the given centre-circle and tube radii.
TriangleMesh MakeTorus(double majorRadius, double minorRadius, int resolution);

/// Closed cylinder along z, centred at the origin.
TriangleMesh MakeCylinder(double radius, double height, int resolution);

/// L-shaped block: the box [-x/2, x/2] x [-y/2, y/2] x [-z/2, z/2] minus
/// its quadrant x > 0, y > 0 (through the whole thickness), so that the
/// vertical edge at x = y = 0 is a sharp concave (reflex) edge. Every face is
/// a regular grid with `resolution` cells per half side.
TriangleMesh MakeLBlock(const Point3& sides, int resolution);

/// Dumbbell along z, `length` from pole to pole: two balls of radius
/// `ballRadius` joined by a neck, a cylinder of radius `neckRadius` between
/// their centres. Its medial axis is connected and contractible (Euler
/// characteristic 1): the axis segment through the neck and the two balls'
/// centres. `resolution` is the number of segments along a quarter circle of
/// a ball; the neck is as finely divided around.
TriangleMesh MakeDumbbell(double length, double ballRadius, double neckRadius, int resolution);

/// A square plate side x side x thickness (centred at the origin, thickness
/// along z) with a cylindrical boss of radius `bossRadius` and height
/// `bossHeight` standing on the centre of its top face; all edges sharp. Its
/// medial axis is one connected, contractible piece (Euler characteristic
/// 1): the plate's mid-plane sheet without holes, joined to the boss's.
/// `resolution` is the number of segments along a quarter of the boss's
/// circle.
TriangleMesh MakePlateWithBoss(
  double side, double thickness, double bossRadius, double bossHeight, int resolution);

/// A block sides[0] x sides[1] x sides[2] (centred at the origin) with a
/// thin fin standing on the middle of its top face: finThickness along y,
/// finHeight along z, half the block's length along x (centred); all edges
/// sharp. Its medial axis is connected and contractible (Euler
/// characteristic 1): the block's, joined to the fin's mid-plane sheet.
/// `resolution` is the number of grid cells along the block's longest side;
/// the fin's sides are divided as finely.
TriangleMesh MakeBlockWithFin(
  const Point3& sides, double finHeight, double finThickness, int resolution);

/// Throws std::invalid_argument ("<what> must be positive and finite")
/// unless `value` is: the check of every shape parameter.
void RequirePositive(double value, const char* what);

/// Exact area and volume of the analytic shapes above (not of their meshes).
struct AreaVolume
{
  double Area;
  double Volume;
};
AreaVolume RoundedBoxAreaVolume(const Point3& sides, double filletRadius);
AreaVolume CapsuleAreaVolume(double radius, double axisLength);
AreaVolume TorusAreaVolume(double majorRadius, double minorRadius);
AreaVolume CylinderAreaVolume(double radius, double height);
AreaVolume LBlockAreaVolume(const Point3& sides);
AreaVolume DumbbellAreaVolume(double length, double ballRadius, double neckRadius);
AreaVolume BlockWithFinAreaVolume(const Point3& sides, double finHeight, double finThickness);
AreaVolume PlateWithBossAreaVolume(
  double side, double thickness, double bossRadius, double bossHeight);
}

#endif
