// SPDX-License-Identifier: GPL-3.0-or-later
// Erosion of the Voronoi medial mesh's hair before simplification: a
// triangle of the inner Voronoi diagram lies on the Voronoi face dual to
// the Delaunay edge between two surface samples p and q (the sites its three
// vertices share). Where p and q are neighbours on the surface (|p - q| a few
// sample spacings), the face stands for no thickness of the solid, only for
// the sampling of a curved or bumpy surface: such faces hang off the real
// sheets as fins, and the simplification keeps many of them. This is the
// lambda-medial axis of Chazal and Lieutier, |p - q| >= lambda, with lambda
// scaled by the local sample spacing; it is applied as a sequence of
// elementary collapses (a triangle with a free edge, an edge with a free
// vertex), from the free edges inwards, so that the homotopy type of the
// medial mesh (and its Euler characteristic) is kept. Written by hand: no
// library erodes a simplicial 2-complex by collapses.
#ifndef medialaxis_HairErosion_h
#define medialaxis_HairErosion_h

#include "Geometry/Types.h"
#include "Simplification/AtlasSimplifier.h"

#include <cstddef>
#include <vector>

namespace medialaxis
{
struct HairErosionResult
{
  std::size_t RemovedTriangles = 0;
  std::size_t RemovedVertices = 0;
};

/// Erodes the triangles of `mesh` whose dual sites p, q (the two sites
/// shared by the Atlases of its three vertices) subtend less than
/// `angleDegrees` at the centre of the largest of its three balls (|p - q| <
/// 2 r sin(angle / 2)), while they have a free edge; then the dangling
/// edges so made. A vertex left without a simplex gives its Atlas to the
/// vertex it was collapsed into. The same at any thread count (the
/// collapses run on one thread).
HairErosionResult ErodeHair(
  AtlasMedialMesh& mesh, const std::vector<Point3>& sites, double angleDegrees);
}

#endif
