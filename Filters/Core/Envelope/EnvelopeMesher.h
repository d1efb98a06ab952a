// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle surfaces of a medial mesh's envelope: every primitive surface on
// its own ("primitives" mode), and the signed-distance grid from which the
// outer boundary of the union is contoured ("boundary" mode).
#ifndef medialaxis_EnvelopeMesher_h
#define medialaxis_EnvelopeMesher_h

#include "Envelope/EnvelopeDistance.h"
#include "Geometry/DistanceGrid.h"
#include "Mesh/PolygonMesh.h"

#include <functional>
#include <vector>

namespace medialaxis
{
struct EnvelopeMeshOptions
{
  /// Segments around a sphere's equator (latitude bands: half as many).
  int SphereResolution = 16;
  /// Segments around a cone.
  int ConeResolution = 16;
  /// Called with the fraction done; return false to abort.
  std::function<bool(double)> Progress;
};

/// A triangle surface whose triangles know the primitive they came from.
struct EnvelopeSurface
{
  TriangleMesh Mesh;
  std::vector<PrimitiveRef> Primitive; // one per triangle
  bool Aborted = false;
};

/// "Primitives" mode: a UV sphere per vertex ball, the tangent-cone band of
/// every edge and the two tangent triangles of every slab, each outward
/// oriented and with its own points. The surfaces overlap and pass through
/// each other. Degenerate cases: a zero-radius ball has no surface; a nested
/// cone (one ball inside the other, zero-length edges included) has no band,
/// its bigger ball stands for it; a band end of zero radius becomes an apex;
/// a slab without tangent planes (collinear centres, or a radius varying
/// faster than the centre) has no triangles, its edge cones stand for it.
EnvelopeSurface MeshEnvelopePrimitives(
  const MedialEnvelope& envelope, const EnvelopeMeshOptions& options);

/// F (the union's signed distance, 1-Lipschitz) on a regular grid, exact
/// near the boundary of the union (DistanceGrid.h), whose zero level set
/// is exactly that boundary.
DistanceGrid SampleUnionDistance(const MedialEnvelope& envelope, double spacing,
  const std::function<bool(double)>& progress = nullptr);

/// The primitive whose surface the boundary point x lies on: the primitive
/// nearest to x, and for a cone whose closest part is one of its end balls,
/// that vertex's sphere.
PrimitiveRef SurfacePrimitive(const MedialEnvelope& envelope, const Point3& x);

/// SurfacePrimitive of many points (e.g. triangle centroids), in parallel.
std::vector<PrimitiveRef> SurfacePrimitives(
  const MedialEnvelope& envelope, const std::vector<Point3>& points);
}

#endif
