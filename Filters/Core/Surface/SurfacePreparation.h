// SPDX-License-Identifier: GPL-3.0-or-later
// Surface validation and preparation: the single gate every surface-consuming
// stage goes through. Turns a triangle soup into a clean, closed, manifold,
// consistently outward-oriented triangle mesh, or says precisely why it can't.
#ifndef medialaxis_SurfacePreparation_h
#define medialaxis_SurfacePreparation_h

#include "Mesh/PolygonMesh.h"
#include "Surface/SelfIntersection.h"

#include <string>
#include <vector>

namespace medialaxis
{
struct SurfacePreparationOptions
{
  /// Points closer than this fraction of the bounding-box diagonal are merged.
  /// Zero merges only exactly coincident points.
  double RelativeMergeTolerance = 1e-10;
  /// Make the orientation consistent and outward instead of failing.
  bool FixOrientation = true;
  /// Triangles that cross are a local fold of the mesh (kept, with a note)
  /// when they are within this many vertex rings of each other on the
  /// surface; farther apart, the surface passes through itself.
  int LocalFoldRings = 2;
  /// A surface passing through itself is refused unless all such crossings
  /// fit in a box this fraction of the bounding-box diagonal across (a tiny
  /// contact, e.g. a scanned limb touching the body: kept, with a note).
  /// Shells that cross each other are always refused.
  double MaxPassThroughExtent = 0.01;
  /// Instead of refusing shells that cross or a surface passing through
  /// itself, resolve the crossings into the closed outer boundary of the
  /// solid they enclose (RepairSelfIntersections) and prepare that.
  bool RepairSelfIntersections = false;
  /// Where resolving the crossings exactly fails (CGAL's autorefinement gives
  /// up where three triangles cross at one point), the repair wraps the
  /// surface instead (CGAL's alpha wrapping) with balls of this fraction of
  /// the bounding-box diagonal, 1/30 of that outside it: details narrower
  /// than about that are bridged. Zero turns the fallback off.
  double WrapAlpha = 1.0 / 150.0;
  /// Where a small contact cannot be resolved exactly, a vertex of the
  /// surface poking through a wall far from it on the surface (a dent's tip
  /// through the far side of a thin part, ContactSeparation.h) is moved back
  /// behind the wall, this fraction of the bounding-box diagonal clear of it:
  /// enough room for the medial axis to close round the tip at any sampling
  /// the pipeline uses, and far below the spacing of its samples. Zero keeps
  /// such a surface as it is (with a note).
  double ContactGap = 1e-3;
  /// The crossings an earlier run found on the same input with the same
  /// options (its report's Crossings): the costly exact test is skipped.
  const std::vector<TriangleCrossing>* KnownCrossings = nullptr;
};

struct SurfacePreparationReport
{
  /// Empty when the prepared surface is usable; otherwise names the defect
  /// and its count, e.g. "surface is not closed: 37 boundary edges".
  std::string Error;
  /// Repairs made and facts found, as short sentences a user can read.
  std::vector<std::string> Notes;

  std::size_t InputPoints = 0;
  std::size_t InputTriangles = 0;
  std::size_t NonFinitePoints = 0;
  std::size_t MergedPoints = 0;        // points merged into a coincident one
  std::size_t UnusedPoints = 0;        // points no triangle references
  std::size_t DegenerateTriangles = 0; // repeated vertex or zero area, dropped
  std::size_t SplitNeighbours = 0;     // triangles split to absorb zero-area needles
  std::size_t DuplicateTriangles = 0;  // same vertex set as an earlier one, dropped
  std::size_t BoundaryEdges = 0;       // edges with one triangle
  std::size_t NonManifoldEdges = 0;    // edges with more than two triangles
  std::size_t NonManifoldVertices = 0; // vertices whose triangles form several fans
  std::size_t ReorientedTriangles = 0; // flipped to agree with their neighbours
  std::size_t InwardComponents = 0;    // components flipped to face outward
  std::size_t Components = 0;          // connected shells
  std::size_t SelfIntersections = 0;   // pairs of triangles that cross
  std::size_t CrossingShells = 0;      // of them, pairs from separate shells
  std::size_t CrossingFarApart = 0;    // of them, pairs far apart on one shell
  double PassThroughExtent = 0.0;      // box of those crossings / diagonal
  bool SelfIntersectionTested = false; // the run got as far as that test
  std::vector<TriangleCrossing> Crossings;
  bool Repaired = false;    // the crossings were resolved (the counts above are the input's)
  double RemovedArea = 0.0; // of the input, inside the solid: removed by the repair
  /// Which repair ran: "resolved crossings" (the input's triangles cut
  /// where they cross, the parts inside removed), "alpha wrap" (the
  /// fallback, a new surface round the input) or "pulled apart" (a small
  /// contact's piercing vertices moved back, ContactGap); empty without a
  /// repair.
  std::string RepairMethod;
  /// The largest distance from the repaired surface to the input, as a
  /// fraction of the bounding-box diagonal (0 for resolved crossings, which
  /// are pieces of the input; the largest move for a contact pulled apart).
  double RepairDeviation = 0.0;
  double Area = 0.0;
  double Volume = 0.0; // enclosed volume after orientation fixing

  bool Ok() const { return this->Error.empty(); }
};

/// Runs every step; on failure `output` holds whatever was prepared up to the
/// failing check (callers that fail must not use it).
SurfacePreparationReport PrepareSurface(const TriangleMesh& input, TriangleMesh& output,
  const SurfacePreparationOptions& options = SurfacePreparationOptions());

/// Whether a note of a report says that the repair moved the surface away
/// from the input (wrapped it, or pulled a contact apart): filters show such
/// notes as warnings.
bool IsMovedSurfaceNote(const std::string& note);

/// Area-weighted signed volume of a closed, oriented triangle mesh.
double SignedVolume(const TriangleMesh& mesh);
double SurfaceArea(const TriangleMesh& mesh);
}

#endif
