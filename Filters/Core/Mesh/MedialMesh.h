// SPDX-License-Identifier: GPL-3.0-or-later
// Plain C++ medial mesh (no VTK): sphere centres with radii, medial edges
// ("cones") and medial triangles ("slabs"). The VTK representation of the same
// data is described in docs/architecture.md; conversion lives in
// vtkMedialMeshConversion.
#ifndef medialaxis_MedialMesh_h
#define medialaxis_MedialMesh_h

#include "Geometry/Types.h"

#include <array>
#include <string>
#include <vector>

namespace medialaxis
{
struct MedialMesh
{
  std::vector<Point3> Centers;
  std::vector<double> Radii;
  std::vector<std::array<Index, 2>> Edges; // may include edges of faces
  std::vector<std::array<Index, 3>> Faces;

  std::size_t NumberOfVertices() const { return this->Centers.size(); }
};

/// Outcome of ValidateMedialMesh: empty Message means valid.
struct MedialMeshCheck
{
  std::string Message;
  bool IsValid() const { return this->Message.empty(); }
};

/// Checks the data contract every consumer relies on: one finite,
/// non-negative radius per vertex, finite coordinates, indices in range, no
/// degenerate (repeated-vertex) edges or faces and no duplicate edges or faces
/// (in any vertex order). The message names the first defect and its count.
MedialMeshCheck ValidateMedialMesh(const MedialMesh& mesh);

/// The edges that bound no face, sorted and unique: the "cone" edges stored
/// as line cells in the VTK representation.
std::vector<std::array<Index, 2>> EdgesNotOnFaces(const MedialMesh& mesh);

/// Sorts edge keys (a, b), a < b, lexicographically in linear time (a
/// counting sort on a); negative ids fall back to a comparison sort.
void SortEdgeKeys(std::vector<std::array<Index, 2>>& keys);

/// Every distinct edge, face edges included, sorted by (min, max) vertex id.
std::vector<std::array<Index, 2>> AllEdges(const MedialMesh& mesh);

/// The vertices joined to each vertex by an edge of AllEdges, in compressed
/// rows: those of v are Next[Start[v]] .. Next[Start[v + 1] - 1], in the
/// order of AllEdges.
struct MedialAdjacency
{
  std::vector<Index> Start;
  std::vector<Index> Next;
};
MedialAdjacency VertexAdjacency(const MedialMesh& mesh);

/// The triangle edges on exactly one triangle (the boundary of the medial
/// sheets), sorted by (min, max) vertex id.
std::vector<std::array<Index, 2>> SheetBoundaryEdges(const MedialMesh& mesh);

/// V - E + F of the complex (E counts every distinct edge, face edges included).
long long EulerCharacteristic(const MedialMesh& mesh);

/// Ids of vertices referenced by no edge and no face.
std::vector<Index> IsolatedVertices(const MedialMesh& mesh);

/// Rewrites a closed chain of vertex ids in one form whichever vertex and
/// direction it was given from: starting at its smallest id, towards the
/// smaller of that id's two neighbours.
void CanonicalCycle(std::vector<Index>& cycle);
}

#endif
