// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle normals filtered for the sharp-feature test on noisy surfaces.
#ifndef medialaxis_FeatureNormals_h
#define medialaxis_FeatureNormals_h

#include "Mesh/PolygonMesh.h"
#include "Mesh/TriangleAdjacency.h"

#include <cstdint>
#include <vector>

namespace medialaxis
{
/// Bilateral normal filtering (Zheng et al., "Bilateral Normal Filtering for
/// Mesh Denoising", IEEE TVCG 2011), applied to the normals only (the points
/// do not move). Each iteration replaces a triangle's normal by the mean of
/// the normals of the triangles sharing a vertex with it, weighted by their
/// area, by a Gaussian of the distance between centroids (sigma: the mean
/// edge length) and by a Gaussian of the difference of the normals (sigma:
/// `rangeSigma`). Noise averages out within a flat or smooth region, while
/// across a sharp edge the normals differ too much to mix, so the edge stays.
/// Deterministic at any thread count. Degenerate triangles keep a zero normal
/// and weigh nothing. No library we use offers this filter (VTK's and CGAL's
/// smoothers move vertices and test features on the raw normals).
///
/// With `needed` (a flag per triangle), only the flagged triangles' normals
/// are filtered, the others keep their own: a filtered normal depends only
/// on the triangles within `iterations` vertex rings, so only those are
/// visited, and the flagged values are the same as without `needed`.
std::vector<Point3> BilateralFaceNormals(const TriangleMesh& mesh, int iterations,
  double rangeSigma = 0.35, const std::vector<std::uint8_t>* needed = nullptr);

/// ComputeTriangleAdjacency, with `normalFiltering` iterations of
/// BilateralFaceNormals confirming the convex edges: a convex edge is sharp
/// only when both the triangles' own normals and their filtered normals
/// differ by more than `featureAngle`, so that noise does not pass for ridges
/// (which the simplifier snaps medial vertices onto), and the creases the
/// filter may sharpen on smooth regions are not added. Concave edges keep the
/// raw test: they only mark spurious medial faces for removal, which the
/// dents of a noisy surface do cause. The filter runs only beside the edges
/// the raw test finds (on a 268,686-triangle scan, 0.3 s -> a few ms);
/// `filteredNormals` (optional) receives the filtered normals there and the
/// triangles' own elsewhere.
TriangleAdjacency FeatureAdjacency(const TriangleMesh& mesh, double featureAngle,
  int normalFiltering, std::vector<Point3>* filteredNormals = nullptr);
}

#endif
