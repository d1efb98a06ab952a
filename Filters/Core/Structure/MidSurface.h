// SPDX-License-Identifier: GPL-3.0-or-later
// The mid-surface of a thin-walled part from its medial mesh: the wall
// sheets (WallSheets.h), their vertices moved to the exact middle between
// the two sides, their branches at junctions straightened onto the walls'
// planes and stitched where the planes meet, and their free boundaries
// extended to the lateral faces of the walls.
#ifndef medialaxis_MidSurface_h
#define medialaxis_MidSurface_h

#include "Mesh/PolygonMesh.h"
#include "Structure/WallSheets.h"

#include <cstdint>
#include <vector>

namespace medialaxis
{
struct MidSurfaceOptions
{
  WallSheetOptions Walls;
  /// Extend the free boundaries along the mid-surface to the surface (the
  /// walls' lateral faces), at most one wall thickness away.
  bool ExtendToLateralFaces = true;
};

/// How a point of the mid-surface was placed.
enum class MidSurfacePointType : std::uint8_t
{
  Centred = 0,      // the middle of a chord between the wall's two sides
  Straightened = 1, // onto the plane of the nearest centred point of its wall
  Junction = 2,     // where the planes of two or more walls meet
  Medial = 3,       // no centred point on its sheet: the medial vertex itself
  Lateral = 4       // added on a lateral face (or on the wall a boundary faces)
};

struct MidSurfaceWall
{
  double Area = 0.0;
  double MeanThickness = 0.0; // area-weighted, the thickness linear on each triangle
  double MinimumThickness = 0.0;
  double MaximumThickness = 0.0;
};

struct MidSurface
{
  TriangleMesh Mesh;
  /// Per point: the wall's thickness there, and the medial vertex it comes
  /// from (-1 for points added on the lateral faces).
  std::vector<double> Thickness;
  std::vector<Index> MedialVertex;
  std::vector<MidSurfacePointType> PointType;
  /// Per triangle: its wall, the triangles joined across edges where the
  /// surface bends by less than 30 degrees (and across junctions, the
  /// triangles on either side that continue one another's plane).
  std::vector<Index> WallOfTriangle;
  std::vector<MidSurfaceWall> Walls;
  double WallThickness = 0.0;
  std::size_t WallSheets = 0;
  /// Edges of three or more triangles (where walls meet) and of one (the
  /// boundary left: free edges of walls and the lateral faces' ends).
  std::size_t JunctionEdges = 0;
  std::size_t BoundaryEdges = 0;
  /// Boundary points moved out to the lateral faces, and vertices moved to
  /// the middle between the two sides by rays.
  std::size_t ExtendedPoints = 0;
  std::size_t CentredPoints = 0;
  /// Triangles dropped: made flat by straightening; with a vertex more
  /// than three wall thicknesses (along its sheet) from any centred point,
  /// or straightened to less than 0.3 thickness from the surface (where a
  /// wall bends into a tube or a block); the smaller of two triangles
  /// still facing opposite ways after the folds of the medial axis' fins
  /// are untangled. FoldedEdges: edges whose two triangles still do.
  std::size_t DroppedTriangles = 0;
  std::size_t FoldedEdges = 0;
};

/// `mesh` a valid medial mesh of the closed `surface`, `structure` its
/// ClassifyMedialStructure.
MidSurface ExtractMidSurface(const MedialMesh& mesh, const MedialStructure& structure,
  const TriangleMesh& surface, const MidSurfaceOptions& options = MidSurfaceOptions());
}

#endif
