// SPDX-License-Identifier: GPL-3.0-or-later
// Restricted Voronoi diagram (RVD) of sites on a triangle surface: every
// surface triangle is clipped exactly by the bisector planes of the sites'
// 3D Euclidean Voronoi cells, giving convex polygons (triangle ∩ cell).
#ifndef medialaxis_RestrictedVoronoi_h
#define medialaxis_RestrictedVoronoi_h

#include "Mesh/PolygonMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace medialaxis
{
struct RestrictedVoronoiOptions
{
  /// Tolerance phi of the sharp-feature test, in radians (default 45°).
  double FeatureAngle = 0.785398163397448309616;
  /// Iterations of bilateral normal filtering (BilateralFaceNormals) whose
  /// normals must confirm every sharp convex edge; 0 tests the raw normals
  /// alone. On noisy surfaces (scans) raw normals take the noise for ridges.
  int FeatureNormalFiltering = 3;
  /// Called with a fraction in [0, 1] from the calling thread; returning
  /// false aborts the computation (the result is then empty).
  std::function<bool(double)> Progress;
};

struct RestrictedVoronoiDiagram
{
  // Polygons, in triangle order: polygon p has vertices
  // Vertices[Offsets[p] .. Offsets[p + 1]), counter-clockwise seen from
  // outside (the triangle's orientation).
  std::vector<Point3> Vertices;
  std::vector<Index> Offsets{ 0 };
  std::vector<Index> PolygonSite;
  std::vector<Index> PolygonTriangle;

  // Per site.
  std::vector<double> CellArea;
  /// How far the cell reaches from its site (its farthest vertex). Every
  /// surface point lies within the largest of these of some site.
  std::vector<double> CellRadius;
  std::vector<Point3> CellCentroid;
  std::vector<std::uint8_t> ConvexFeature;  // the cell crosses a sharp convex edge
  std::vector<std::uint8_t> ConcaveFeature; // the cell crosses a sharp concave edge
  std::vector<int> CellComponents;          // disconnected pieces of the cell

  bool Aborted = false;

  std::size_t NumberOfPolygons() const { return this->PolygonSite.size(); }
};

/// Sites need not lie on the surface. Runs in parallel (TBB); the result does
/// not depend on the number of threads.
RestrictedVoronoiDiagram ComputeRestrictedVoronoi(const TriangleMesh& surface,
  const std::vector<Point3>& sites,
  const RestrictedVoronoiOptions& options = RestrictedVoronoiOptions());
}

#endif
