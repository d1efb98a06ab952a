// SPDX-License-Identifier: GPL-3.0-or-later
// Probes of the thin walls for the mid-surface (MidSurface.h): WallProbe
// finds the middle between a wall's two sides and its thickness there, by
// nearest points and chords on the closed surface; PlaneSet gathers the
// planes of the walls around a point of the mid-surface and finds where they
// meet.
#ifndef medialaxis_WallProbe_h
#define medialaxis_WallProbe_h

#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"

#include <cmath>
#include <vector>

namespace medialaxis
{
// Planes whose normals are this close continue one another (one wall).
const double SamePlaneCosine = std::cos(15.0 * Pi / 180.0);

// Thickness probes on the closed surface.
struct WallProbe
{
  const TriangleLocator& Locator;
  const std::vector<Point3>& Normals; // per surface triangle, unit
  // Per surface triangle: the largest angle to a neighbour on the same
  // smooth side, positive where the side bulges out (convex), negative
  // where it curves in (concave), 0 on a plane.
  const std::vector<double>& FacetTurn;

  // The two sides of a bent wall (concentric cylinders: one convex, one
  // concave) meet a chord at angles that differ by up to a triangle's turn.
  // A plane facing a curved side (a fillet's start) and two concave sides
  // facing each other (the fillets at a rib's foot) get no such allowance.
  double SidesTolerance(Index a, Index b) const;

  // The middle between the two sides near x, as MidSurfer's medial lines
  // find it: from the nearest surface point straight across the wall to
  // the other side, which must face it (parallel within
  // ChordSidesTolerance). Exact between parallel planes and between
  // concentric cylinders; false where the other side turns away (a
  // fillet, a rib, a corner).
  bool Centre(
    const Point3& x, const Point3& normal, double reach, Point3& middle, double& thickness) const;

  struct ChordResult
  {
    double Thickness = -1.0; // -1: the chord does not meet two parallel sides alike
    double Offset = 0.0;     // from x to the chord's middle, along n
  };

  // The chord through x along the unit normal n of the mid-surface: the
  // wall's thickness and its middle where the chord meets two parallel
  // sides at the same angle.
  ChordResult Chord(const Point3& x, const Point3& n, double reach) const;
};

// Planes (a point and a unit normal) merged where their normals agree.
struct PlaneSet
{
  std::vector<Point3> Points, Normals;
  std::vector<int> Count;

  void Add(const Point3& p, const Point3& n);

  // The point nearest `x` on every plane (where they meet), least squares
  // with a tiny pull towards x for the directions the planes leave free.
  Point3 Meet(const Point3& x) const;

  // `d` with its components along the planes' normals removed.
  Point3 AlongAll(Point3 d) const;
};
}

#endif
