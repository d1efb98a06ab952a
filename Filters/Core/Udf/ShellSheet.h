// SPDX-License-Identifier: GPL-3.0-or-later
// The surface inside an epsilon-shell, read off the shell's medial mesh.
#ifndef medialaxis_ShellSheet_h
#define medialaxis_ShellSheet_h

#include "Mesh/MedialMesh.h"
#include "Mesh/PolygonMesh.h"
#include "Udf/DistanceFunction.h"

#include <cstddef>
#include <string>
#include <vector>

namespace medialaxis
{
struct ShellSheetOptions
{
  double Epsilon = 0.0;
  /// A medial triangle is on the sheet when all its spheres have a radius of
  /// at least this fraction of epsilon: a sphere centred on the surface
  /// inside the shell touches both sides at epsilon; the shell's medial axis
  /// also branches towards its own ridges (around a strongly curved rim),
  /// where the spheres shrink.
  double MinimumRadiusFraction = 0.5;
  /// Pieces joined to the rest only through junction edges (edges of three
  /// or more triangles) and smaller than this many epsilon^2 are folds of
  /// the medial axis, not sheets, and are dropped. A real junction's sheets
  /// are much larger.
  double MinimumFinArea = 4.0;
  /// Holes of the sheet whose boundary loop spans less than this many
  /// epsilon are closed: the epsilon-shell closes over any hole narrower
  /// than two epsilon, so such a hole is not in the field; it comes from
  /// the folds dropped where the shell's medial axis branches (along a
  /// sharp fold of the surface).
  double MaximumHoleSpan = 2.0;
  /// Projections onto the zero set (0: none). A sampled field (not exact
  /// near its zero set): each point of a manifold part of the sheet moves to
  /// the mean of the feet of the gradient steps from the two points epsilon
  /// away along its normal. An exact distance (a function): every point but
  /// those on junctions moves to its closest point on the zero set.
  int SnapSteps = 0;
};

struct ShellSheet
{
  TriangleMesh Surface;            // may be open and non-manifold
  std::vector<double> ShellRadius; // per point: its sphere's radius (about epsilon)
  std::vector<Index> MedialVertex; // per point: the medial mesh's vertex
  std::size_t ShrunkTriangles = 0; // dropped: a sphere below MinimumRadiusFraction
  std::size_t FinTriangles = 0;    // dropped: in small pieces hanging on junctions
  std::size_t FlapTriangles = 0;   // dropped: folded back across a junction edge
  std::size_t FilledHoles = 0;     // closed: holes narrower than MaximumHoleSpan
  double MeanSnapDistance = 0.0;   // how far the snapping moved the points
  std::string Error;               // the probe's, when it failed
};

/// The triangles of `medial` that lie on the sheet (see the options), their
/// points snapped onto the zero set of the distance that `probe` reads when
/// it is given and options.SnapSteps > 0. Deterministic.
ShellSheet ExtractShellSheet(
  const MedialMesh& medial, const ShellSheetOptions& options, const DistanceProbe* probe);

/// Closed loops of boundary edges (edges of one triangle) of a triangle
/// mesh: the number of its free boundaries.
std::size_t CountBoundaryLoops(const TriangleMesh& mesh);

/// Edges of three or more triangles.
std::size_t CountJunctionEdges(const TriangleMesh& mesh);
}

#endif
