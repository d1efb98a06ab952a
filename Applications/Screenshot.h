// SPDX-License-Identifier: GPL-3.0-or-later
// Offscreen picture of a result of the medial-axis tool: the input surface
// (semi-transparent, fillet faces coloured when given), the medial mesh
// coloured by radius (or a mid-surface by thickness, or a curve skeleton as
// tubes by radius) and the fillet centre lines.
#ifndef medialaxis_Screenshot_h
#define medialaxis_Screenshot_h

#include <string>

class vtkPolyData;

namespace medialaxis
{
/// Renders into a PNG of width x height pixels. `filletFaces` (the surface
/// with cell data FilletId) and `filletLines` may be null. Returns an error
/// message, empty on success. Needs an X display (see main: the tool runs
/// itself under xvfb-run when there is none).
std::string WriteScreenshot(const std::string& path, vtkPolyData* surface, vtkPolyData* medial,
  vtkPolyData* filletFaces, vtkPolyData* filletLines, int width, int height);
}

#endif
