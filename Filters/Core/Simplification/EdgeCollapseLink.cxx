// SPDX-License-Identifier: GPL-3.0-or-later
// The link condition: whether collapsing an edge keeps the medial mesh's
// topology (Dey's vertex condition, with the Euler-neutral exceptions).
#include "Simplification/EdgeCollapse.h"

#include "Support/SortedLists.h"

#include <algorithm>

namespace medialaxis
{
bool MedialEdgeCollapse::LinkConditionHolds(Index a, Index b, CollapseScratch& scratch) const
{
  scratch.EulerNeutral = false;
  // Dey's vertex condition: the common neighbours of a and b must be exactly
  // the apices of faces (a, b, x). With FringeCollapses (or, for spike
  // edges, EulerNeutralSpikeCollapses), where it fails the collapse is
  // still taken when it keeps the Euler characteristic: every
  // extra common neighbour x closes the loop (a, b, x), raising the
  // characteristic by one, and every face pair (a, x, y), (b, x, y) that
  // merges lowers it by one (e.g. the fins of a fringe along a fillet's
  // centre line, where (a, x, y), (b, x, y) and (a, b, x) form a disk).
  Index apices[16];
  std::size_t apexCount = 0;
  for (Index f : this->VertexFaces[a])
  {
    const auto& t = this->Faces[f];
    if (this->FaceAlive[f] && (t[0] == b || t[1] == b || t[2] == b))
    {
      const Index x = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
      if (apexCount < 16)
      {
        apices[apexCount++] = x;
      }
      else
      {
        return false; // an edge in more than 16 faces: too tangled to collapse
                      // safely
      }
    }
  }
  std::size_t extra = 0;
  ForEachShared(this->VertexNeighbours[a], this->VertexNeighbours[b],
    [&](Index x)
    { extra += std::find(apices, apices + apexCount, x) == apices + apexCount ? 1 : 0; });
  if (extra == 0)
  {
    return true;
  }
  const bool eulerNeutralAllowed = this->Options.FringeCollapses ||
    (this->Options.EulerNeutralSpikeCollapses &&
      this->StabilityRatio(a, b) < this->Options.SpikeThreshold);
  if (!eulerNeutralAllowed || this->NumberAlive <= this->Options.StrictLinkConditionVertexCount)
  {
    return false;
  }
  std::size_t merges = 0;
  for (Index f : this->VertexFaces[b])
  {
    const auto& t = this->Faces[f];
    if (!this->FaceAlive[f] || t[0] == a || t[1] == a || t[2] == a)
    {
      continue;
    }
    const int k = t[0] == b ? 0 : (t[1] == b ? 1 : 2);
    const Index x = t[(k + 1) % 3], y = t[(k + 2) % 3];
    for (Index g : this->VertexFaces[a])
    {
      const auto& u = this->Faces[g];
      if (this->FaceAlive[g] && (u[0] == x || u[1] == x || u[2] == x) &&
        (u[0] == y || u[1] == y || u[2] == y))
      {
        ++merges;
        break;
      }
    }
  }
  scratch.EulerNeutral = extra == merges;
  return scratch.EulerNeutral;
}
}
