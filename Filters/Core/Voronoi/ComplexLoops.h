// SPDX-License-Identifier: GPL-3.0-or-later
// The loops of a medial complex that the topology repair
// (MedialTopologyRepair.cxx) opens or caps: face-less edges on loops, the
// boundary loops of its sheets, and the cycles of what it collapses to.
#ifndef medialaxis_ComplexLoops_h
#define medialaxis_ComplexLoops_h

#include "Mesh/MedialMesh.h"
#include "Voronoi/CapPeeling.h"

#include <vector>

namespace medialaxis
{
namespace repair
{
/// Removes the face-less edge on the shortest loop (a loop round a handle is
/// long, a spurious one short), `excess` times at most; the number removed.
std::size_t CutLoops(MedialMesh& mesh, long long excess);

/// Cycles of sheet-boundary edges, shortest first.
std::vector<std::vector<Index>> BoundaryLoops(const MedialMesh& mesh);

/// The complex collapsed to a graph (the peeling's witnesses, then edges
/// with a free end): for each edge left out of a spanning tree of it, the
/// shortest cycle through that edge, shortest first. Empty when the complex
/// does not collapse to a graph.
std::vector<std::vector<Index>> CoreCycles(const MedialMesh& mesh, const CapPeeler& peeling);
}
}

#endif
