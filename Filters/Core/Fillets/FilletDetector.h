// SPDX-License-Identifier: GPL-3.0-or-later
// Fillet detection from a Structural MAT (paper "Structural MAT", section 5.7):
// the rolling-ball centre lines of fillets with their radii, and the surface
// triangles of each fillet.
//
// A fillet is swept by a ball rolling between two faces, so its medial axis
// is the ball's centre line: a boundary of the medial sheet along which the
// ball touches a whole arc of the surface. A medial boundary edge is taken as
// a centre-line edge when most of the surface its two spheres correspond to
// (their Atlas, restricted to the edge's span) lies on the edge's envelope,
// the cone of interpolated balls, with matching normals. Accepted edges are
// chained into polylines; each polyline's fillet faces are grown over the
// surface from its Atlas triangles, through triangles whose corners all lie
// on the polyline's envelope. The polyline is then refined, vertex by vertex,
// by a circle fit to the fillet's cross-section, and the faces grown again
// with a tighter tolerance. Past the open ends of a line, where the ball
// reaches a cap the medial line stops short of, the faces are grown along
// the line extrapolated (least-squares trend of its last radii), with a
// tolerance that loosens with the distance past the end.
#ifndef medialaxis_FilletDetector_h
#define medialaxis_FilletDetector_h

#include "Mesh/MedialMesh.h"
#include "Mesh/PolygonMesh.h"

#include <cstddef>
#include <vector>

namespace medialaxis
{
struct FilletDetectorOptions
{
  /// A surface point lies on a fillet when its distance to the envelope of
  /// the centre line is within this fraction of the local ball radius.
  double RadiusTolerance = 0.05;
  /// Largest angle (radians) between a fillet triangle's normal and the
  /// envelope's normal at its closest point.
  double NormalTolerance = 0.5235987755982988; // 30 degrees
  /// A surface vertex belongs to a fillet's faces when its distance to the
  /// refined centre line's envelope is within this fraction of the radius
  /// (triangle centroids, off the curved surface by the chord, use
  /// RadiusTolerance).
  double FaceTolerance = 0.02;
  /// Fraction of an edge's corresponding surface (by area, within the edge's
  /// span) that must lie on its envelope for the edge to be a centre-line edge.
  double MinimumConsistentFraction = 0.5;
  /// Smallest arc (radians) the matching surface must wrap around an edge:
  /// a fillet's ball touches an arc, a sheet boundary's ball a flat face.
  double MinimumArcAngle = 0.3490658503988659; // 20 degrees
  /// Balls smaller than this fraction of the surface's bounding-box diagonal
  /// belong to sharp edges (radius 0), not to fillets.
  double MinimumRadius = 0.002;
  /// Centre lines shorter than this fraction of the diagonal are dropped, and
  /// so are those whose faces cover less than half of Length * MeanRadius *
  /// MinimumArcAngle (a rolling ball leaves at least that).
  double MinimumLength = 0.02;
  /// A centre line is split where it turns by more than this angle (radians)
  /// at a vertex, e.g. at the corner where two fillets of a box meet.
  double SplitAngle = 0.8726646259971648; // 50 degrees
};

struct Fillet
{
  /// Medial vertex ids along the centre line; a closed one (Closed) does not
  /// repeat its first vertex.
  std::vector<Index> Vertices;
  /// The rolling ball along the line, per vertex: the medial vertex's sphere
  /// refined by a circle fit to the fillet's cross-section there.
  std::vector<Point3> Centres;
  std::vector<double> Radii;
  bool Closed = false;
  double Length = 0.0;
  double MeanRadius = 0.0; // length-weighted
  double MinimumRadius = 0.0;
  double MaximumRadius = 0.0;
  /// (MaximumRadius - MinimumRadius) / MeanRadius: 0 for a constant-radius fillet.
  double RadiusVariation = 0.0;
  /// Arc (radians) of the ball's circle its faces cover across the line
  /// (the median along it): pi minus the angle between the faces it blends,
  /// pi / 2 for a right-angled edge.
  double ArcAngle = 0.0;
  std::size_t SurfaceTriangles = 0;
  double SurfaceArea = 0.0;
};

struct FilletDetectionResult
{
  std::vector<Fillet> Fillets;
  /// Per surface triangle: the index of its fillet in Fillets, -1 for none.
  std::vector<int> TriangleFillet;
  std::size_t BoundaryEdges = 0;   // medial edges on exactly one triangle
  std::size_t CentreLineEdges = 0; // of those, the ones accepted
  double Diagonal = 0.0;           // of the surface's bounding box
};

/// The medial mesh with its Atlas (vertex v corresponds to the sites
/// atlasSites[atlasOffsets[v] .. atlasOffsets[v + 1])), and the restricted
/// Voronoi diagram of those sites on `surface` given as the site and the
/// surface triangle of each of its polygons. Deterministic; runs in parallel.
/// Throws std::invalid_argument when the arrays do not fit together.
FilletDetectionResult DetectFillets(const TriangleMesh& surface, const MedialMesh& medial,
  const std::vector<Index>& atlasOffsets, const std::vector<Index>& atlasSites,
  const std::vector<Index>& polygonSite, const std::vector<Index>& polygonTriangle,
  const FilletDetectorOptions& options = FilletDetectorOptions());
}

#endif
