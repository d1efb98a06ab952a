// SPDX-License-Identifier: GPL-3.0-or-later
// Curve skeletons (Core/Skeleton/CurveSkeleton.h) to and from poly data, as
// vtkMedialCurveSkeleton gives them.
#ifndef vtkCurveSkeletonConversion_h
#define vtkCurveSkeletonConversion_h

#include "Skeleton/CurveSkeleton.h"

#include <string>

class vtkPolyData;

namespace medialaxis
{
/// Nodes as points (`Radius`, `NodeType`, `BranchId`), a polyline per branch
/// (`BranchId`, `Length`), a vertex for a lone node, counts as field data.
void CurveSkeletonToPolyData(const CurveSkeleton& skeleton, vtkPolyData* output);

/// The skeleton in `input` (points, and polylines or lines as edges; point
/// data `Radius` required). Returns why it cannot be read, or empty.
std::string PolyDataToCurveSkeleton(vtkPolyData* input, CurveSkeleton& skeleton);
}

#endif
