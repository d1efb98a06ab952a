// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle normals filtered for the sharp-feature test on noisy surfaces.
#ifndef medialaxis_FeatureNormals_h
#define medialaxis_FeatureNormals_h

#include "Mesh/PolygonMesh.h"

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
std::vector<Point3> BilateralFaceNormals(
  const TriangleMesh& mesh, int iterations, double rangeSigma = 0.35);
}

#endif
