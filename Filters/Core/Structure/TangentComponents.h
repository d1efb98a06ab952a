// SPDX-License-Identifier: GPL-3.0-or-later
// MATFP's classification of medial spheres, on the Atlas of a Structural
// MAT: the surface a medial vertex corresponds to (the restricted Voronoi
// cells of its Atlas' sites) splits into connected pieces, one per side of
// the surface its ball touches: 2 on a sheet, 3 on a seam, 4 or more at a
// junction, 1 on a rim, a sharp edge or a tube's axis.
#ifndef medialaxis_TangentComponents_h
#define medialaxis_TangentComponents_h

#include "Geometry/Types.h"

#include <vector>

namespace medialaxis
{
/// Which restricted Voronoi cells touch: per site, the sorted sites whose
/// cells share a polygon vertex with its own (within `tolerance`; the cells
/// are polygons per surface triangle, `Offsets` into `Vertices` as in
/// RestrictedVoronoiDiagram, `PolygonSite` the site of each).
struct SiteAdjacency
{
  std::vector<Index> Offsets{ 0 };
  std::vector<Index> Neighbours;
};
SiteAdjacency ComputeSiteAdjacency(const std::vector<Point3>& vertices,
  const std::vector<Index>& offsets, const std::vector<Index>& polygonSite,
  std::size_t numberOfSites, double tolerance);

/// Per medial vertex, the number of connected pieces of its Atlas' cells
/// (`atlasOffsets` / `atlasSites` as AtlasMedialMesh has them; 0 for an
/// empty Atlas).
std::vector<int> CountTangentComponents(const std::vector<Index>& atlasOffsets,
  const std::vector<Index>& atlasSites, const SiteAdjacency& adjacency);
}

#endif
