// SPDX-License-Identifier: GPL-3.0-or-later
// The three volume primitives of a medial mesh's envelope (Q-MAT, section 3):
// a ball per vertex, a medial cone per edge, a medial slab per triangle. Each
// is the union of the balls linearly interpolated between its vertex balls,
// which is also the convex hull of those balls.
//
// Closed-form signed distances (negative inside). For cones and slabs the
// value is min over interpolated balls of (|p - c(t)| - r(t)): the interpolated
// distance is convex in t, so its minimum is either at an interior critical
// point (the tangent cone or tangent planes) or on the boundary (an end
// ball, an edge cone). Outside, that is the Euclidean distance to the
// primitive. Inside it is exact too: the closest boundary point x lies on one
// interpolated ball B(c*, r*) with the same outward normal n, and the point is
// p = x - depth n with depth <= r* (a primitive is within r_max of its centre
// segment or triangle, and p lies on x's side of it), so that ball gives
// r* - |p - c*| = depth. TestEnvelope checks both against brute force.
#ifndef medialaxis_MedialPrimitives_h
#define medialaxis_MedialPrimitives_h

#include "Geometry/Types.h"

#include <array>
#include <cstdint>

namespace medialaxis
{
enum class PrimitiveKind : std::uint8_t
{
  Sphere = 0,
  Cone = 1,
  Slab = 2
};

/// Signed distance and the outward unit normal of the primitive's boundary at
/// the closest boundary point, which is p - Distance * Normal.
struct PrimitiveDistance
{
  double Distance;
  Point3 Normal;
};

struct SpherePrimitive
{
  Point3 Center;
  double Radius;
};
PrimitiveDistance SphereDistance(const SpherePrimitive& s, const Point3& p);

/// The convex hull of two balls. When one ball contains the other (nested
/// spheres, which includes a zero-length edge), the cone is the bigger ball:
/// Nested is set and Big says which end (0 or 1) that is.
struct ConePrimitive
{
  std::array<Point3, 2> C;
  std::array<double, 2> R;
  Point3 Axis;   // unit, from C[0] to C[1] (any unit vector when the length is 0)
  double Length; // |C[1] - C[0]|
  // The tangent cone's outward normal is SinPhi * Axis + CosPhi * (radial unit):
  // SinPhi = (R[0] - R[1]) / Length.
  double SinPhi;
  double CosPhi;
  bool Nested;
  int Big;
  Point3 Perp1, Perp2; // orthonormal frame around Axis (for meshing and sampling)
};
ConePrimitive MakeCone(const Point3& c0, double r0, const Point3& c1, double r1);
PrimitiveDistance ConeDistance(const ConePrimitive& cone, const Point3& p);

/// Where the tangent cone touches ball `end` (0 or 1): a circle in the plane
/// normal to the axis. Meaningless for a nested cone.
struct Circle3
{
  Point3 Center;
  double Radius;
};
Circle3 ConeTangentCircle(const ConePrimitive& cone, int end);
/// Point of the tangent cone at end `end`, angle `angle` around the axis.
Point3 ConeTangentPoint(const ConePrimitive& cone, int end, double angle);
/// Area of the lateral (tangent-cone) surface; 0 for a nested cone.
double ConeLateralArea(const ConePrimitive& cone);

/// The convex hull of three balls. Its boundary is made of the three edge
/// cones and, when the two planes tangent to all three balls exist
/// (HasTangentPlanes), two triangles on those planes. They do not exist when
/// the centres are collinear or when the radius varies faster than the
/// centre over the triangle (|grad r| >= 1): then the slab is the union of its
/// edge cones.
struct SlabPrimitive
{
  std::array<Point3, 3> C;
  std::array<double, 3> R;
  std::array<ConePrimitive, 3> Edges; // (0,1), (1,2), (2,0)
  bool HasTangentPlanes;
  Point3 PlaneNormal;            // unit normal of the centre triangle
  std::array<Point3, 2> Normals; // tangent planes: Normals[s] . x = Offsets[s]; s = 0 on the
  std::array<double, 2> Offsets; //   PlaneNormal side, 1 on the other
  double Gamma;                  // |Normals[s] . PlaneNormal|
  // Barycentric coordinates of a point in the centre plane.
  Point3 E1, E2;
  double InvG11, InvG12, InvG22;
};
SlabPrimitive MakeSlab(const std::array<Point3, 3>& c, const std::array<double, 3>& r);
/// The same without its edge cones (Edges left unset): enough for
/// SlabInteriorDistance, at a quarter of the work.
SlabPrimitive MakeSlabInterior(const std::array<Point3, 3>& c, const std::array<double, 3>& r);
/// Signed distance to the whole slab (tangent planes and edge cones).
PrimitiveDistance SlabDistance(const SlabPrimitive& slab, const Point3& p);
/// Only the part whose closest interpolated ball is interior to the triangle:
/// the signed distance to the tangent plane on p's side when the foot of p
/// falls inside the triangle, +infinity otherwise. SlabDistance is the
/// minimum of this and the three edge cones.
PrimitiveDistance SlabInteriorDistance(const SlabPrimitive& slab, const Point3& p);
/// The tangent triangle on side s (0 or 1), ordered so that its normal points
/// outward. Only when HasTangentPlanes.
std::array<Point3, 3> SlabTangentTriangle(const SlabPrimitive& slab, int side);
}

#endif
