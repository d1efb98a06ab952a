// SPDX-License-Identifier: GPL-3.0-or-later
// Walking a Delaunay triangulation stored as flat arrays: per cell its four
// site ids and its four neighbours (the one opposite each site; -1 for an
// infinite cell), as VoronoiMedialAxis.cxx copies them out of CGAL's.
#ifndef medialaxis_DelaunayCells_h
#define medialaxis_DelaunayCells_h

#include "Geometry/Types.h"

#include <array>
#include <utility>
#include <vector>

namespace medialaxis
{
// The local edges of a Delaunay cell (pairs of its four sites).
inline constexpr int edgeEnds[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 },
  { 2, 3 } };

using CellArray = std::vector<std::array<Index, 4>>;

// Position of `site` among cell c's four sites.
inline int LocalIndex(const CellArray& cellSites, Index c, Index site)
{
  const auto& s = cellSites[c];
  return s[0] == site ? 0 : (s[1] == site ? 1 : (s[2] == site ? 2 : 3));
}

// Local edge number of the local sites i and j.
inline int LocalEdge(int i, int j)
{
  if (i > j)
  {
    std::swap(i, j);
  }
  return i == 0 ? j - 1 : (i == 1 ? j + 1 : 5);
}

// Walks the cells around local edge e of cell `start` (once round): calls
// visit(cell) for each and stops early, returning false, when it returns
// false or a neighbour is infinite.
template <typename Visit>
bool AroundEdge(
  const CellArray& cellSites, const CellArray& cellNeighbours, Index start, int e, Visit&& visit)
{
  const Index u = cellSites[start][edgeEnds[e][0]], v = cellSites[start][edgeEnds[e][1]];
  int other = 0;
  while (other == edgeEnds[e][0] || other == edgeEnds[e][1])
  {
    ++other;
  }
  Index current = start, exitSite = cellSites[start][other];
  for (;;)
  {
    if (!visit(current))
    {
      return false;
    }
    const int exitLocal = LocalIndex(cellSites, current, exitSite);
    const int keep = 6 - exitLocal - LocalIndex(cellSites, current, u) -
      LocalIndex(cellSites, current, v); // the fourth local index
    const Index next = cellNeighbours[current][exitLocal];
    if (next < 0)
    {
      return false;
    }
    exitSite = cellSites[current][keep];
    current = next;
    if (current == start)
    {
      return true;
    }
  }
}
}

#endif
