// SPDX-License-Identifier: GPL-3.0-or-later
// The union of closed primitive meshes (fitted generalized primitives) as a
// signed distance, for contouring it as one closed surface (the
// reconstruction of a skeletal diagram) on a narrow-band grid.
//
// F(x) = distance to the nearest primitive surface where x lies outside
// every primitive (exactly the distance to the union there), and
// -(largest distance to the surface of a primitive containing x) inside
// (at most the depth in the union, since each primitive lies inside it).
// F is continuous, has the union's boundary as its zero level set and
// never exceeds the distance to it: what SampleNarrowBand needs.
#ifndef medialaxis_PrimitiveUnion_h
#define medialaxis_PrimitiveUnion_h

#include "Geometry/BoxTree.h"
#include "Geometry/DistanceGrid.h"
#include "Mesh/PolygonMesh.h"
#include "Mesh/TriangleLocator.h"

#include <deque>
#include <functional>
#include <memory>
#include <vector>

namespace medialaxis
{
class PrimitiveUnion
{
public:
  /// `primitives`: closed, outward, self-intersection-free meshes (empty
  /// ones are skipped). Copies them.
  explicit PrimitiveUnion(const std::vector<TriangleMesh>& primitives);

  bool Empty() const { return this->Meshes.empty(); }
  const Box& Bounds() const { return this->AllBounds; }
  std::size_t NumberOfPrimitives() const { return this->Meshes.size(); }

  /// F(x) above. Thread-safe.
  double SignedDistance(const Point3& x) const;

  /// F for the points within `radius` of `centre`: a primitive whose
  /// surface lies farther than `radius` from the centre contains all of
  /// them or none, so only the primitives whose surface passes near are
  /// tested point by point. Thread-safe.
  std::function<double(const Point3&)> LocalSignedDistance(
    const Point3& centre, double radius) const;

  /// Whether x lies inside primitive i (TriangleLocator::Inside).
  bool Inside(std::size_t i, const Point3& x) const;

private:
  std::deque<TriangleMesh> Meshes; // stable addresses for the locators
  std::vector<std::unique_ptr<TriangleLocator>> Locators;
  std::vector<Box> Boxes;
  TriangleMesh All;
  std::unique_ptr<TriangleLocator> AllLocator;
  Box AllBounds;
};

/// Drops the components of `contour` (a contour of F) that enclose none of
/// `skeleton`'s points (points of the skeletal elements, e.g. vertices and
/// points along edges). Every primitive contains its skeletal element, so
/// each true part of the union holds some of it; a small shell around none
/// is a grid point whose inside test a fold of a primitive misled. Returns the
/// triangles dropped (their points go too, the others are renumbered in
/// the order the triangles use them).
std::size_t KeepComponentsAroundSkeleton(
  TriangleMesh& contour, const std::vector<Point3>& skeleton);

/// F of the union sampled for contouring: the grid spans the union's bounds
/// with the given spacing (DistanceGrid.h).
DistanceGrid SamplePrimitiveUnion(const PrimitiveUnion& primitives, double spacing,
  const std::function<bool(double)>& progress = nullptr);
}

#endif
