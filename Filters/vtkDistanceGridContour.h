// SPDX-License-Identifier: GPL-3.0-or-later
// The zero level set of a sampled signed distance (Geometry/DistanceGrid.h)
// as a closed, outward triangle mesh, by vtkFlyingEdges3D. Shared by
// vtkSlabReconstructor and vtkMedialSkeletalDiagram. Private to the module:
// not wrapped.
#ifndef vtkDistanceGridContour_h
#define vtkDistanceGridContour_h

#include "Geometry/DistanceGrid.h"
#include "Mesh/PolygonMesh.h"

namespace medialaxis
{
/// The triangles of F = 0, oriented so that the enclosed volume is
/// positive (outward normals, F negative inside).
TriangleMesh ContourDistanceGrid(const DistanceGrid& grid);
}

#endif
