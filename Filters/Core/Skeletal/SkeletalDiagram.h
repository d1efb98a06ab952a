// SPDX-License-Identifier: GPL-3.0-or-later
// A sparse skeleton of a shape with one generalized primitive per element
// (Medial Skeletal Diagram, paper 004, section 5.1, without its global
// optimisation): sites chosen on a simplified medial mesh, the skeleton as
// the dual of their Voronoi diagram restricted to that mesh (geodesic along
// its edges; DualSkeleton.h), its edges routed inside the surface, a
// primitive fitted to each vertex, edge (a piece per straight part) and
// triangle inside the surface, and new
// sites inserted where the surface lies farthest from the primitives' union
// until it is within MaximumError everywhere or MaximumElements is reached.
#ifndef medialaxis_SkeletalDiagram_h
#define medialaxis_SkeletalDiagram_h

#include "Mesh/MedialMesh.h"
#include "Mesh/PolygonMesh.h"
#include "Skeletal/PrimitiveFit.h"
#include "Skeletal/PrimitiveTemplate.h"

#include <functional>
#include <vector>

namespace medialaxis
{
/// The diagram's default fit (see SkeletalDiagramOptions::Fit).
inline PrimitiveFitOptions DiagramFitOptions()
{
  PrimitiveFitOptions fit;
  fit.ExactRadii = true;
  fit.MaximumRefinements = 16;
  fit.RefinementGrowth = 32;
  return fit;
}

struct SkeletalDiagramOptions
{
  /// Sites to start from, spread by farthest-point selection along the
  /// medial mesh (the first: its largest sphere).
  int InitialSites = 1;
  /// Elements (vertices + edges + triangles) the diagram may have.
  int MaximumElements = 100;
  /// Stop once every surface point lies within this fraction of the
  /// bounding-box diagonal of the primitives' union.
  double MaximumError = 0.005;
  /// Templates: directions round a circle, the vertex template's
  /// subdivisions, the spacing of base points (fraction of the diagonal).
  int AngularResolution = 32;
  int VertexSubdivisions = 3;
  double Spacing = 0.02;
  /// The fit: exact radii (each direction's ray exit), refined in up to 16
  /// rounds to 32 times the template's points. RefinementTolerance 0: a
  /// fifth of MaximumError. Against the smooth fit with the refinement's
  /// former budget (8 rounds, 8 times), the hand's two-sided mean distance
  /// at 30 elements fell from 0.044% to 0.018% of the diagonal.
  PrimitiveFitOptions Fit = DiagramFitOptions();
  /// Called with a fraction in [0, 1] (of MaximumElements reached);
  /// returning false stops with the diagram as it is.
  std::function<bool(double)> Progress;
};

struct SkeletalDiagram
{
  /// The skeleton: its vertices are medial vertices (Sites).
  std::vector<Index> Sites;
  std::vector<Point3> Points;
  std::vector<std::array<Index, 2>> Edges;
  std::vector<Triangle> Triangles;
  /// Per edge, the medial vertices where it bends to stay inside the
  /// surface (between its ends, in order from Edges[e][0]; empty for a
  /// straight edge) and their positions.
  std::vector<std::vector<Index>> EdgeBends;
  std::vector<std::vector<Point3>> EdgeBendPoints;
  /// The primitives: one per vertex, per straight piece of an edge and per
  /// triangle, in the order of the elements (vertices, then edges, then
  /// triangles); PieceElement gives each piece's element. A piece whose
  /// element leaves the surface has an empty fit.
  std::vector<PrimitiveTemplate> Templates;
  std::vector<FittedPrimitive> Primitives;
  std::vector<Index> PieceElement;
  /// Distance from the surface points to the primitives' union: largest
  /// and mean, absolute; and the bounding-box diagonal.
  double Error = 0.0, MeanError = 0.0, Diagonal = 0.0;
  /// Sites inserted after the initial ones; elements with a piece without
  /// a primitive; triangles of the dual left out because their flat face
  /// leaves the surface (a curved sheet's three sites; their sides stay).
  int Insertions = 0;
  int FailedElements = 0;
  int OmittedTriangles = 0;
  bool Aborted = false;

  /// The paper's N_c: every primitive's radii plus three coordinates per
  /// skeletal vertex and edge bend.
  std::size_t ContinuousParameters() const
  {
    std::size_t count = 3 * this->Points.size();
    for (const auto& bends : this->EdgeBends)
    {
      count += 3 * bends.size();
    }
    for (const FittedPrimitive& p : this->Primitives)
    {
      count += p.Radius.size();
    }
    return count;
  }

  std::size_t NumberOfElements() const
  {
    return this->Points.size() + this->Edges.size() + this->Triangles.size();
  }

  /// The points of edge e from its first vertex to its second, bends
  /// included.
  std::vector<Point3> EdgePolyline(std::size_t e) const
  {
    std::vector<Point3> line = { this->Points[this->Edges[e][0]] };
    line.insert(line.end(), this->EdgeBendPoints[e].begin(), this->EdgeBendPoints[e].end());
    line.push_back(this->Points[this->Edges[e][1]]);
    return line;
  }
};

/// Points of the skeleton's elements: its vertices, each edge's bends and
/// `perEdge` - 1 points evenly along each of its straight pieces, and each
/// triangle's centroid (each lies in its element's primitive).
std::vector<Point3> ElementPoints(const SkeletalDiagram& diagram, int perEdge);

/// Builds the diagram of the closed `surface` (outward) from its simplified
/// medial mesh. Deterministic. Throws std::invalid_argument for an empty
/// medial mesh.
SkeletalDiagram BuildSkeletalDiagram(const TriangleMesh& surface, const MedialMesh& medial,
  const SkeletalDiagramOptions& options = SkeletalDiagramOptions());
}

#endif
