// SPDX-License-Identifier: GPL-3.0-or-later
// The VTK side of surface preparation: every filter that consumes a surface
// calls PrepareSurfacePolyData first and stops with the report's error.
// Private to the module: not wrapped.
#ifndef vtkSurfacePreparation_h
#define vtkSurfacePreparation_h

#include "Surface/SurfacePreparation.h"

class vtkPolyData;

namespace medialaxis
{
/// Triangulates polygons and strips of `input` (vertices and lines are
/// ignored), then runs PrepareSurface. On success `output` holds the clean
/// triangle surface (double-precision points); on failure it is left empty.
SurfacePreparationReport PrepareSurfacePolyData(vtkPolyData* input, vtkPolyData* output,
  const SurfacePreparationOptions& options = SurfacePreparationOptions());

/// The same, giving the prepared surface as a plain triangle mesh. The last
/// input's result is remembered (keyed by its points' and cells' modification
/// times and the options), so that the stages of one pipeline prepare it once.
SurfacePreparationReport PrepareSurfaceMesh(vtkPolyData* input, TriangleMesh& prepared,
  const SurfacePreparationOptions& options = SurfacePreparationOptions());

/// The triangles of a closed surface (polygons fanned), facing outward,
/// without the checks of PrepareSurfaceMesh: for a surface that passed them.
TriangleMesh OutwardTriangleMesh(vtkPolyData* input);

/// Converts a prepared triangle mesh to poly data (points and triangles).
void TriangleMeshToPolyData(const TriangleMesh& mesh, vtkPolyData* output);
}

#endif
