// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle quality and fold-over counts of a medial mesh, measured the way
// the medial-axis papers report them.
#ifndef medialaxis_MedialMeshQuality_h
#define medialaxis_MedialMeshQuality_h

#include "Geometry/Vec3.h"
#include "Mesh/MedialMesh.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace medialaxis
{
struct MedialMeshQuality
{
  std::size_t Triangles = 0;
  /// Triangles with (numerically) zero area: twice the area at most 1e-12
  /// times the longest edge squared.
  std::size_t DegenerateTriangles = 0;
  /// Edges shared by exactly two triangles that fold onto each other: with
  /// both oriented consistently across the edge, their normals point in
  /// opposite directions to within FoldAngleDegrees (the two triangles
  /// overlap, as after a flipping collapse). Each such fold counts its two
  /// triangles once each in FoldedTriangles.
  std::size_t FoldedEdges = 0;
  std::size_t FoldedTriangles = 0;
  /// Triangle edges on one triangle (the boundary of the medial sheets) and
  /// on three or more (seams where sheets meet, or fins).
  std::size_t BoundaryEdges = 0;
  std::size_t NonManifoldEdges = 0;
  /// Mean smallest angle (degrees) and the share of triangles whose smallest
  /// angle is below 30 degrees, over non-degenerate triangles.
  double MeanMinimumAngle = 0.0;
  double PercentMinimumAngleBelow30 = 0.0;
  /// Mean Q = 6 / sqrt(3) * area / (longest edge * half perimeter): 1 for
  /// an equilateral triangle, 0 for a degenerate one.
  double MeanQuality = 0.0;
};

/// A fold is a dihedral angle (between the two triangles' planes, on their
/// side) below this many degrees.
constexpr double FoldAngleDegrees = 10.0;
/// cos(FoldAngleDegrees).
constexpr double FoldCosine = 0.98480775301220802032;

MedialMeshQuality MeasureQuality(const MedialMesh& mesh);

/// Whether the triangle (a, b, c) has (numerically) zero area: twice its
/// area at most 1e-12 times its longest edge squared.
inline bool IsDegenerateTriangle(const Point3& a, const Point3& b, const Point3& c)
{
  const double longest2 = std::max({ Distance2(a, b), Distance2(b, c), Distance2(c, a) });
  return !(Norm(Cross(b - a, c - a)) > 1e-12 * longest2);
}

/// The two triangles across an edge (U, V) on exactly two, F = (U, V, X)
/// and G = (V, U, Y) up to orientation: where a fold can appear.
struct TriangleHinge
{
  Index U, V, F, X, G, Y;
};

/// Every hinge of the mesh, by edge (U < V); with the counts of edges on one
/// triangle and on three or more when asked.
std::vector<TriangleHinge> TriangleHinges(const MedialMesh& mesh,
  std::size_t* boundaryEdges = nullptr, std::size_t* nonManifoldEdges = nullptr);

/// Whether the triangles (u, v, x) and (v, u, y), which share the edge
/// (u, v), fold onto each other (see MedialMeshQuality::FoldedEdges).
/// With `cosFold` = cos(A), a fold is a dihedral angle below A instead.
inline bool IsFold(
  const Point3& u, const Point3& v, const Point3& x, const Point3& y, double cosFold = FoldCosine)
{
  const Point3 e = v - u;
  const Point3 n1 = Cross(e, x - u);
  const Point3 n2 = Cross(y - v, e); // = (u - v) x (y - v)
  return Dot(n1, n2) < -cosFold * Norm(n1) * Norm(n2);
}

/// IsFold at two angles from one pair of normals: 2 where the triangles
/// fold onto each other (IsFold), 1 where they only meet below the angle
/// whose cosine is `cosPleat` (a pleat), 0 otherwise.
inline int FoldLevel(
  const Point3& u, const Point3& v, const Point3& x, const Point3& y, double cosPleat)
{
  const Point3 e = v - u;
  const Point3 n1 = Cross(e, x - u);
  const Point3 n2 = Cross(y - v, e); // = (u - v) x (y - v)
  const double dot = Dot(n1, n2);
  if (dot < -FoldCosine * Norm(n1) * Norm(n2))
  {
    return 2;
  }
  return dot < -cosPleat * Norm(n1) * Norm(n2) ? 1 : 0;
}
}

#endif
