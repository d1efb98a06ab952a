// SPDX-License-Identifier: GPL-3.0-or-later
// A strict look at the vertex and face lines of a Wavefront OBJ file before
// VTK's reader gets it: vtkOBJReader silently turns a coordinate such as
// "nan" or "1.0x" into a wrong number and skips unreadable face indices, so
// broken files would come out as plausible but wrong surfaces.
#ifndef medialaxis_ObjCheck_h
#define medialaxis_ObjCheck_h

#include <istream>
#include <string>

namespace medialaxis
{
/// Checks every `v` line for three finite coordinates (an optional fourth
/// weight or colour values may follow) and every `f` line for at least three
/// vertex references whose indices are non-zero integers within the vertices
/// read so far (negative indices count back). Returns "" when the lines are
/// well formed, otherwise "line N: ..." naming the first problem.
std::string CheckObjText(std::istream& in);
}

#endif
