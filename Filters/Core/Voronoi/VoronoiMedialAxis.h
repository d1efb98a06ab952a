// SPDX-License-Identifier: GPL-3.0-or-later
// The initial medial mesh: the part of the sites' 3D Voronoi diagram that
// lies inside the surface (Delaunay triangulation by CGAL; Voronoi vertices
// are circumcentres).
#ifndef medialaxis_VoronoiMedialAxis_h
#define medialaxis_VoronoiMedialAxis_h

#include "Mesh/MedialMesh.h"
#include "Mesh/PolygonMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace medialaxis
{
struct VoronoiMedialAxisOptions
{
  /// Circumcentres of adjacent Delaunay cells closer than this fraction of the
  /// surface's bounding-box diagonal become one medial vertex (co-spherical
  /// sites).
  double RelativeWeldTolerance = 1e-9;
  /// Paper Eq. 4: drop a face whose two sites both lie on concave-feature
  /// cells when the distance from their midpoint to the surface is below
  /// alpha * |s1 - s2| / 2.
  bool ConcaveFiltering = true;
  double ConcaveFilterAlpha = 0.7;
  /// Keep the Delaunay cells that span a thin part from one side to the
  /// other although their circumcentres fall outside (see the .cxx), so that
  /// the part's medial sheet has no holes (paper 000, Fig. 19).
  bool RepairThinParts = true;
  /// Give the complex the topology of the solid (MedialTopologyRepair.h):
  /// one piece per solid, one loop per handle; edges that leave the solid
  /// are removed, pieces cut off are joined,
  /// spurious loops opened and holes in sheets capped, smallest first.
  bool RepairTopology = true;
  /// Every surface point lies within this distance of a site: the largest
  /// CellRadius of the sites' restricted Voronoi diagram. With it, the
  /// topology repair skips the crossing test on the medial edges that
  /// provably stay inside; 0 (unknown) tests every edge. Same result.
  double CoveringRadius = 0.0;
  /// Fraction in [0, 1]; returning false aborts (the result is then empty).
  std::function<bool(double)> Progress;
};

struct VoronoiMedialAxisResult
{
  /// Vertices (circumcentres inside the surface) with radii, all inner
  /// Voronoi edges, and the fan-triangulated inner Voronoi faces.
  MedialMesh Mesh;
  /// Sites of each vertex: AtlasSites[AtlasOffsets[v] .. AtlasOffsets[v + 1]),
  /// sorted; 4 for a generic vertex, more where co-spherical sites were welded.
  std::vector<Index> AtlasOffsets{ 0 };
  std::vector<Index> AtlasSites;
  /// Per triangle: the two sites whose Delaunay edge its Voronoi face is dual to.
  std::vector<std::array<Index, 2>> FaceSitePair;
  /// Per vertex: a lower bound of the distance from its centre to the
  /// nearest site, from the empty circumspheres of its Delaunay cells; -1
  /// where unknown (centres moved inside by RepairThinParts, cells too flat
  /// for their circumcentre to be trusted, vertices added by the repair).
  std::vector<double> SiteClearance;

  // What happened, for reports and tests.
  std::size_t DelaunayCells = 0;
  std::size_t InsideCells = 0;
  std::size_t AmbiguousInsideTests = 0; // needed the closest-point test (see the .cxx)
  std::size_t WeldedCells = 0;          // cells merged into another's vertex
  std::size_t FilteredFaces = 0;        // triangles removed by Eq. 4 (by collapses)
  std::size_t DroppedPockets = 0;       // tiny disconnected pieces removed
  std::size_t SpanningCells = 0;        // kept by RepairThinParts, their vertices moved inside
  std::size_t OpenedVoids = 0;          // voids of the Voronoi complex opened by leaving out a face
  std::size_t EdgesAcrossSurface = 0;   // RepairTopology: edges leaving the solid, removed
  std::size_t JoinedPieces = 0;         // RepairTopology: pieces joined by a new edge
  std::size_t CutLoops = 0;             // RepairTopology: face-less edges removed to open a loop
  std::size_t FilledHoles = 0;          // RepairTopology: boundary loops capped
  std::size_t MissingLoops = 0;         // RepairTopology: handles the complex misses
  bool Aborted = false;
};

/// `siteTriangles`: the surface triangle each site lies on (may be empty:
/// the nearest triangle is then found). `concaveFeature`: per site, 1 if its
/// restricted cell crosses a concave sharp edge (may be empty: no concave
/// filtering).
VoronoiMedialAxisResult ComputeVoronoiMedialAxis(const TriangleMesh& surface,
  const std::vector<Point3>& sites, const std::vector<Index>& siteTriangles,
  const std::vector<std::uint8_t>& concaveFeature,
  const VoronoiMedialAxisOptions& options = VoronoiMedialAxisOptions());
}

#endif
