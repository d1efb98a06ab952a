// SPDX-License-Identifier: GPL-3.0-or-later
// The topological check of the thin-part repair of the initial medial mesh
// (VoronoiMedialAxis.cxx, step 2b): of the Delaunay cells proposed because
// they span a thin part, keep those whose Voronoi vertices close holes or
// extend sheets, and drop those that would add a loop or enclose a void,
// which a solid's medial axis has not.
#ifndef medialaxis_ThinPartRepair_h
#define medialaxis_ThinPartRepair_h

#include "Voronoi/DelaunayCells.h"

#include <array>
#include <vector>

namespace medialaxis
{
/// `inside`: the cells whose circumcentres are inside (the medial complex
/// so far); `spanning`: the proposed cells, cleared where they would add a
/// loop or a void. `sites` is the number of sites.
void KeepSpanningCellsThatAddNoLoopOrVoid(const CellArray& cellSites,
  const CellArray& cellNeighbours, std::size_t sites, const std::vector<char>& inside,
  std::vector<char>& spanning);

/// The Voronoi faces (as sorted site pairs) to leave out so that the
/// complex of the `inside` cells encloses no void: for each void, the face
/// on its boundary whose cells have the smallest mean `radius` (the least
/// medial one). Sorted.
std::vector<std::array<Index, 2>> FacesOpeningVoids(const CellArray& cellSites,
  const CellArray& cellNeighbours, std::size_t sites, const std::vector<char>& inside,
  const std::vector<double>& radius);
}

#endif
