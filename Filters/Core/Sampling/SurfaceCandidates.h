// SPDX-License-Identifier: GPL-3.0-or-later
// Random candidate points on a surface for sample elimination: uniform by
// area, or with the density a sizing field asks for.
#ifndef medialaxis_SurfaceCandidates_h
#define medialaxis_SurfaceCandidates_h

#include "Mesh/PolygonMesh.h"

#include <cstdint>
#include <vector>

namespace medialaxis
{
class SizingField;

struct Candidates
{
  std::vector<Point3> Points;
  std::vector<Index> Triangles; // the triangle each point lies on
  std::vector<double> Spacing;  // the wanted spacing there (adaptive only)
};

/// `count` area-uniform random points; the surface must have positive area.
Candidates UniformCandidates(const TriangleMesh& surface, std::size_t count, std::uint64_t seed);

/// `count` random points with density proportional to 1 / spacing^2, by
/// rejection inside each triangle from a per-triangle bound of the density.
Candidates AdaptiveCandidates(
  const TriangleMesh& surface, const SizingField& field, std::size_t count, std::uint64_t seed);

/// Reorders the candidates along a Morton (Z-order) curve so that points close
/// in space are close in memory: every later pass touches neighbours.
void SortSpatially(Candidates& candidates);
}

#endif
