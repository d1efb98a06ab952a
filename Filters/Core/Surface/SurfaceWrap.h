// SPDX-License-Identifier: GPL-3.0-or-later
// A closed surface without self-intersections round any triangle soup:
// CGAL's alpha wrapping. The fallback of the self-intersection repair where
// resolving the crossings exactly gives up, as CGAL 5.5's autorefinement
// does where three input triangles cross at one point. Kept in a
// translation unit of its own (a 3D Delaunay triangulation with exact
// constructions: heavy to compile, needs -frounding-math).
#ifndef medialaxis_SurfaceWrap_h
#define medialaxis_SurfaceWrap_h

#include "Mesh/PolygonMesh.h"

#include <string>

namespace medialaxis
{
struct SurfaceWrapResult
{
  /// Empty when wrapped; otherwise why not.
  std::string Error;
  /// Closed, 2-manifold, outward and free of self-intersections; it lies
  /// `Offset` outside the input and does not enter concave parts or gaps
  /// narrower than about `Alpha`.
  TriangleMesh Surface;
  double Alpha = 0.0;
  double Offset = 0.0;
  /// The largest distance from a point of Surface to the input surface.
  double LargestDeviation = 0.0;
};

/// Wraps the triangles of `input` (any soup: crossing, open or not
/// manifold) with balls of radius `alpha`, `offset` outside it (CGAL's
/// alpha_wrap_3). Both must be positive and finite.
SurfaceWrapResult WrapSurface(const TriangleMesh& input, double alpha, double offset);
}

#endif
