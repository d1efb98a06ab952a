// SPDX-License-Identifier: GPL-3.0-or-later
// Curve skeletons as files other tools read: SWC, the neuron morphology
// format (one tree per piece, loops broken and listed), and a JSON graph.
#ifndef medialaxis_SkeletonExport_h
#define medialaxis_SkeletonExport_h

#include "Skeleton/CurveSkeleton.h"

#include <string>

namespace medialaxis
{
/// SWC: a line "id type x y z radius parent" per node (ids from 1, parent
/// -1 for a root). Each piece is a tree grown breadth-first from its node of
/// largest radius (type 1, soma; the others type 0, undefined); the edges
/// left out to break its loops are listed in "# loop" comment lines as pairs
/// of ids. `header` lines are written first as comments.
std::string SkeletonToSwc(const CurveSkeleton& skeleton, const std::string& header);

/// JSON: {"nodes": [{"id", "position", "radius", "type", "branch"}],
/// "edges": [{"source", "target", "length"}], "branches": [[node ids]],
/// "cycle_rank", "components"}.
std::string SkeletonToJson(const CurveSkeleton& skeleton);
}

#endif
