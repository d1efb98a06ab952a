// SPDX-License-Identifier: GPL-3.0-or-later
// Atlas-guided medial mesh simplification by edge collapse (paper
// "Structural MAT", sections 4.2-4.4): every medial vertex keeps the set of
// surface cells it stands for (its Atlas); a collapse places the merged
// sphere by minimising the spherical quadric error over the union of both
// Atlases (each cell once) plus a uniform Laplacian, and edges are collapsed
// in order of that error weighted by a spike-stability sigmoid.
#ifndef medialaxis_AtlasSimplifier_h
#define medialaxis_AtlasSimplifier_h

#include "Fitting/EnvelopeFit.h"
#include "Mesh/MedialMesh.h"
#include "Simplification/EdgeCollapseCounts.h"
#include "Voronoi/RestrictedVoronoi.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace medialaxis
{
enum class FringeCollapseMode
{
  Off,
  On,
  Automatic
};

enum class ErrorBandMode
{
  Off,
  On,
  Automatic // on for organic shapes (PreserveSharpFeatures off) at 200 vertices and more
};

struct AtlasSimplifierOptions
{
  std::size_t TargetNumberOfVertices = 1000;
  /// Stop when the cheapest collapse costs more (in the unit-box model).
  double MaximumCost = std::numeric_limits<double>::infinity();
  /// Laplacian weight lambda, stability sharpness k and threshold tau, all
  /// in the model normalised to the unit box (paper: 6e-6, 100, 0.025).
  double Lambda = 6e-6;
  double SpikeSharpness = 100.0;
  double SpikeThreshold = 0.025;
  /// Spike edges (stability ratio below SpikeThreshold) between two
  /// non-feature vertices: the smaller ball, almost inside the larger, is
  /// absorbed by it (the merged sphere is the larger one, unchanged, as the
  /// scale axis transform drops balls devoured by their neighbours), and
  /// below SpikeThreshold Psi has sharpness SpikeRemovalSharpness, so that
  /// it vanishes as the paper means it to: at the paper's k = 100, Psi(0) =
  /// 0.076 only divides a spike's cost by 13, and most spikes outlast the
  /// collapses (bunny, 50,000 samples -> 5,000 spheres: of 417 spike edges
  /// left, 363 could have collapsed). The spike edges are also queued again
  /// near the end (EdgeCollapseOptions::RequeueSpikes). Measured with the
  /// final fit, seed 0: 16 organic meshes at 10,000 -> 1,000, the largest
  /// share of spike edges 0.53% -> 0.32%, median two-sided Hausdorff
  /// distance 0.526% -> 0.549%; at 50,000 -> 5,000 bunny 1.79% -> 0.63%
  /// spike edges (0.398% -> 0.401%), botijo 6.86% -> 0.32% (0.362% ->
  /// 0.347%); 13 CAD meshes at 50,000 -> 5,000, median 0.582% -> 0.564%,
  /// the largest share 4.37% -> 1.89%. Placing the merged sphere by the
  /// energy's optimum instead (k = 1000 alone) leaves merged balls out of
  /// the surface (armadillo at 50,000 -> 5,000: 2.09%). Off by default for
  /// now: a sphere's medial axis (1,000 samples -> 50 spheres) becomes a
  /// cluster of nearly coincident balls, on which the final fit amplifies
  /// rounding, so that the sphere scaled by 1e-30 or moved by 1e6 no longer
  /// gives the same result within 1e-6 of its diagonal (3e-3; 1e-9 without
  /// the fit, and with the fit but without absorption).
  bool AbsorbSpikes = false;
  double SpikeRemovalSharpness = 1000.0;
  /// Below this many vertices the link condition guards every collapse.
  /// Default: always. (The paper uses 200; measured on the bunny at 50K
  /// sites -> 5,000 vertices, 200 gives Euler characteristic 66 instead of
  /// 1, because earlier collapses close loops into bubbles.)
  std::size_t TopologyGuardVertexCount = std::numeric_limits<std::size_t>::max();
  /// Let collapses break the link condition while more than
  /// StrictLinkConditionVertexCount vertices remain when they keep the Euler
  /// characteristic (a loop closed and a face pair merged at once).
  /// - They remove the fringes of thin fins that large fillets (radius above
  ///   about 10 samples) leave along their centre lines: rounded box, radius
  ///   0.25, 50K sites -> 2,000 vertices: 244 instead of 1,485 boundary edges.
  /// - On organic shapes simplified far (e.g. 50K sites -> 1,000 vertices),
  ///   the strict condition leaves tangles of fins that no collapse may
  ///   remove; they use up the vertex budget, ears and fingers collapse
  ///   instead, and a stall then lifts the fold guard and the link condition.
  ///   Measured on the 16 organic meshes of the shared set, 50K -> 1,000:
  ///   two-sided Hausdorff distance median 9.4% of the diagonal strict
  ///   (1.3% to 29%), 1.4% with fringe collapses (0.6% to 6.3%), and no
  ///   folded triangle instead of up to 337. At 10K -> 1,000: median 1.21%
  ///   against 1.22%, the same Euler characteristic on all 16.
  /// - Below 200 vertices even more so on organic shapes: 10K sites -> 100
  ///   vertices on the same 16 meshes, median 2.2% against 11.2%, Euler
  ///   characteristic 1 - genus on 14 against 9, no folded triangle against
  ///   up to 28 (-> 50 vertices: 3.3% against 14.0%, 14 against 7).
  /// - But where the medial axis is a curve or a point they keep bands of
  ///   sheet that should shrink away: a torus simplified to 50 vertices keeps
  ///   folded sheets where the strict condition reaches the centre circle,
  ///   and on a coarse polyhedral sphere (1,000 sites -> 50 vertices) a ball
  ///   reaches 5% outside the surface. Hence Automatic stays off below 200.
  /// Automatic (default): on for organic shapes (PreserveSharpFeatures off)
  /// whose target is at least StrictLinkConditionVertexCount.
  FringeCollapseMode FringeCollapses = FringeCollapseMode::Automatic;
  /// The same for spike edges only (stability ratio below SpikeThreshold):
  /// spikes entangled with the sheets around them are removed without the
  /// side effects of FringeCollapses on tubes. Measured on the 16 organic
  /// meshes of the shared set (10K sites -> 1,000 vertices): triangles with
  /// a spike edge 1,037 -> 251 in all, the Euler characteristic unchanged and
  /// no folded triangle on every one. Off by default: on CAD parts it
  /// shortens fillet boundaries, and on a coarse sphere (1,000 sites -> 50
  /// vertices) merged balls reach up to 6% outside the surface.
  bool EulerNeutralSpikeCollapses = false;
  std::size_t StrictLinkConditionVertexCount = 200;
  /// When no collapse below the guard keeps the link condition and the
  /// target is not reached: stop there (strict) or go on without it
  /// (default; the collapses are counted in RelaxedCollapses).
  bool StrictTopologyGuard = false;
  /// CAD extension: snap feature vertices to sharp edges (r = 0) and keep
  /// them there (paper section 4.4).
  bool PreserveSharpFeatures = true;
  /// Distance-to-site fidelity for cells on concave edges (Eq. 11, solved by
  /// L-BFGS); when off they use the plane quadric like every other cell.
  bool InvaginatedTerm = true;
  /// A merged sphere may not contain the surface samples it stands for: its
  /// radius is clamped to the distance from its centre to the nearest site
  /// of the merged Atlas (a medial ball touches its part of the surface and
  /// never crosses it), and the collapse costs the energy there, so that it
  /// waits its turn. The spherical quadric alone fits tangent planes in the
  /// least-squares sense and lets balls bulge out where the Atlas curves.
  /// Measured at the suite's settings (two-sided Hausdorff distance, seed 0,
  /// off -> on): 13 CAD meshes at 50,000 samples -> 5,000 spheres, median
  /// 0.582% -> 0.471% (abc_00000125 0.59% -> 0.17%, rocker-arm 0.70% ->
  /// 0.38%, pinion 0.69% -> 0.50%; block 1.15% -> 1.39%); cheburashka at
  /// 10,000 -> 1,000 2.15% -> 1.19%. Off by default for now:
  /// on some organic meshes it is farther (octopus 0.98% -> 1.47%,
  /// armadillo 0.49% -> 0.71%; median 0.526% -> 0.553%), and analytic
  /// truths measured against the smooth shape see the balls of a faceted
  /// surface (a capsule tessellated with 24 segments: radius 0.485 for 0.5).
  bool ClampRadiiToAtlas = false;
  /// Error-bounded collapses: when above 0, a collapse whose local error
  /// exceeds this fraction of the diagonal of the sites' bounding box waits,
  /// and the simplification stops short of TargetNumberOfVertices when none
  /// within the bound is left (without lifting the fold guard or the link
  /// condition). The local error of a collapse is the largest distance from
  /// a site of the merged Atlas to the merged vertex's envelope (its ball,
  /// the cones to its neighbours and the slabs of its triangles), on either
  /// side: a site outside is surface the envelope falls short of, a site
  /// inside is surface it reaches past; and how far the merged ball pokes
  /// out of the surface past the nearest of all sites (its Atlas may lie on
  /// one side of a thin part only). The cost order stays the paper's.
  /// Measured (before the poke check) on the bunny (10,000 samples, target
  /// 1): a bound of 0.3% stops at 282 spheres, two-sided Hausdorff distance
  /// 0.53%, where the vertex target 282 gives 0.98% (0.5%: 148 spheres,
  /// 0.75% against 1.21%; 1%: 70 spheres, 1.14% against 2.03%). 0
  /// (default): no bound.
  double ErrorBound = 0.0;
  /// Error bands (when ErrorBound is 0): collapses whose local error (as
  /// for ErrorBound) exceeds a bound wait; the bound starts at
  /// InitialErrorBand times the diagonal and grows by ErrorBandGrowth at every
  /// stall short of the target (lifted once past the diagonal), so that the
  /// collapses go in the paper's cost order within bands of error. Spheres
  /// then go where they keep the envelope close. Measured with seed 0 and the
  /// final fit, median two-sided Hausdorff distance off -> on: 16 organic
  /// meshes, 10,000 samples -> 1,000 spheres 0.526% -> 0.437% (dragon 1.07%
  /// -> 0.74%, octopus 0.98% -> 0.64%; spot 0.36% -> 0.42%), -> 300 spheres
  /// 0.885% -> 0.526%; before the poke check, -> 100 spheres (On) 1.73% ->
  /// 1.06%, 13 CAD meshes (On), 50,000 -> 5,000, 0.582% -> 0.442%
  /// (thingi_69058 0.57% -> 0.09%, block 1.15% -> 0.53%; casting 0.45% ->
  /// 1.01%). Over five seeds at 50,000 -> 5,000 the distance spreads 1.18x
  /// (bunny) and 1.08x (armadillo) instead of 1.46x and 1.64x. The price:
  /// more spike edges (the needles cover surface that the bound keeps; at
  /// 1,000 spheres at most 1.22% of the edges instead of 0.53%) and about
  /// 1.3x the time of the whole pipeline. Automatic (default): on for organic
  /// shapes (PreserveSharpFeatures off) at every size (100 spheres from
  /// 10,000 samples: median 1.81% -> 0.95% over 16 organic meshes). On CAD
  /// parts the sheets' boundary then no longer follows the fillet centre
  /// lines, which the fillet detector needs (recall of a variable-radius
  /// fillet 0.37 instead of 0.95 or more).
  ErrorBandMode ErrorBands = ErrorBandMode::Automatic;
  double InitialErrorBand = 0.001;
  double ErrorBandGrowth = 1.5;
  /// Clean sheets. Three measures keep the medial sheets few, large and
  /// smooth (docs/methods.md, "Clean sheets"); measured on the 16 organic
  /// shared meshes at 10,000 samples -> 1,000 spheres, from all off to all
  /// on: N80 (the fewest sheets holding 80% of the area) median 18 -> 5.5,
  /// pleats (two-triangle edges meeting below 90 degrees) median 7.4% ->
  /// 0%, median two-sided Hausdorff distance 0.379% -> 0.447% (Q-MAT: N80
  /// 5.5, 1.01%); at 50,000 -> 5,000 N80 167.5 -> 5, pleats 13.7% -> 0%,
  /// distance 0.404% -> 0.350% (Q-MAT: 42, 0.549%).
  ///
  /// HairAngle: before the collapses, the triangles of Voronoi faces whose
  /// two surface samples subtend less than this angle (degrees) at their
  /// balls' centres (the angle filter of Dey and Zhao) are eroded from the
  /// free edges inwards by elementary collapses, which keep the topology
  /// (Simplification/HairErosion.h). Such faces stand for the sampling of
  /// a curved or bumpy surface, not for the solid's thickness, and become
  /// the fins that cut the sheets. Larger: cleaner; smaller: closer; 0: off.
  /// Only for organic shapes (PreserveSharpFeatures off) and targets of
  /// StrictLinkConditionVertexCount (200) and more.
  double HairAngle = 45.0;
  /// FinBudget: fins left after that (small sheets branching off a larger
  /// one) whose balls reach out of the cones of their junction by at most
  /// this fraction of the diagonal are collapsed into the junction at a few
  /// checkpoints on the way to the target (the last at 1.1 times it); 0:
  /// never. Only for organic shapes (PreserveSharpFeatures off).
  double FinBudget = 0.005;
  /// PleatAngle: with PreventFolds, a collapse may not leave more pairs of
  /// triangles meeting below this dihedral angle (degrees) around the
  /// merged vertex than there were; 10 refuses only triangles folded onto
  /// each other. Where no collapse is left, it gives way to the 10 degree
  /// fold guard. The final fit guards its moves at the same angle (no move
  /// pleats two triangles that met at it or more). Only for organic shapes
  /// (PreserveSharpFeatures off) and targets of
  /// StrictLinkConditionVertexCount and more.
  double PleatAngle = 90.0;
  /// Refuse collapses that fold two triangles onto each other (dihedral
  /// angle below 10 degrees); allowed anyway once nothing else is left.
  bool PreventFolds = true;
  /// The cheapest candidates whose edges lie at least five edges apart are
  /// collapsed at once, in parallel, in batches of up to 64: the same result
  /// at any thread count, though not exactly that of one collapse at a time.
  /// Off: strictly one at a time in the greedy order (on CAD parts at 50,000
  /// samples -> 5,000 spheres 30-40% slower, with the same Hausdorff
  /// distances and triangle quality; kept to compare).
  bool ParallelBatches = true;
  /// With ParallelBatches off, a second thread checks the next candidate's
  /// validity while the current one collapses
  /// (EdgeCollapseOptions::CheckAhead). The same result either way; off only
  /// to compare.
  bool CheckAhead = true;
  /// After the last collapse, fit the spheres to the surface with the
  /// connectivity fixed (Fitting/EnvelopeFit.h), through the sites and,
  /// without PreserveSharpFeatures, the corners of their cells
  /// (Fitting/FitPoints.h), in FitIterations rounds. With
  /// PreserveSharpFeatures the feature vertices and the boundary of the
  /// sheets (fillet centre lines) stay where the collapses left them.
  bool FinalFit = true;
  int FitIterations = 4;
  /// Weight of the fit's term that pulls spike edges (stability ratio below
  /// SpikeThreshold) apart until their ratio clears it by a little
  /// (EnvelopeFitOptions::SpikeRepairWeight; 0: off). The paper removes
  /// spikes by collapsing them first, but collapses that would cost
  /// accuracy wait, and the needles they leave stand for bumps of the
  /// surface; moving their balls a little keeps the bump covered without
  /// the needle. 16 organic meshes, 10,000 -> 1,000: largest share of spike
  /// edges 1.22% -> 0.29%, median two-sided Hausdorff 0.440% -> 0.379%.
  double FitSpikeRepair = 10.0;
  /// With PreserveSharpFeatures: fit the radii of the spheres on the sheets'
  /// boundary too (their centres still stay). Measured on the 13 CAD meshes
  /// of the shared set (50,000 samples -> 5,000 spheres): median two-sided
  /// Hausdorff distance 0.36% against 0.57%. The radii the collapses placed
  /// are kept as AtlasSimplifierResult::PlacedRadii for the fillet detector:
  /// on a fillet they are the rolling ball's, which the fitted radii, made
  /// to close the envelope between the balls, are not.
  bool FitSheetBoundaryRadii = true;
  /// Fraction in [0, 1]; returning false aborts (the result is then empty).
  std::function<bool(double)> Progress;
};

/// Whether `options` let Euler-neutral collapses break the link condition
/// (FringeCollapses, with Automatic resolved).
bool UsesFringeCollapses(const AtlasSimplifierOptions& options);
/// Whether `options` erode hair before the collapses (HairAngle above 0, no
/// sharp features and a target of at least StrictLinkConditionVertexCount).
bool UsesHairErosion(const AtlasSimplifierOptions& options);
/// Whether `options` guard the collapses against pleats (PleatAngle above
/// 10 degrees, no sharp features and a target of at least
/// StrictLinkConditionVertexCount).
bool UsesPleatGuard(const AtlasSimplifierOptions& options);
/// Whether `options` take the collapses in bands of error (ErrorBands, with
/// Automatic resolved; never with an ErrorBound).
bool UsesErrorBands(const AtlasSimplifierOptions& options);

/// A medial mesh with the Atlas of every vertex: sites
/// AtlasSites[AtlasOffsets[v] .. AtlasOffsets[v + 1]), sorted.
struct AtlasMedialMesh
{
  MedialMesh Mesh;
  std::vector<Index> AtlasOffsets{ 0 };
  std::vector<Index> AtlasSites;
  std::vector<std::uint8_t> FeatureVertex; // per vertex (output only)
  /// Per vertex (input only, optional): a lower bound of the distance from
  /// its centre to the nearest site, -1 where unknown (the Voronoi stage's
  /// SiteClearance). The error bands' test of balls reaching out of the
  /// surface then skips the search where the bound decides; same result.
  std::vector<double> SiteClearance;
};

/// The collapse counts (see EdgeCollapseCounts; QueueInitialisationSeconds
/// includes the set-up of the per-cell quadrics and Atlases) and the result.
struct AtlasSimplifierResult : EdgeCollapseCounts
{
  AtlasMedialMesh Medial;
  std::size_t SnappedVertices = 0; // feature vertices moved onto sharp edges
  /// Feature vertices snapped although that made a zero-area or folded
  /// triangle; the collapses around them go first to repair it.
  std::size_t ForcedSnaps = 0;
  /// Triangles of the input eroded as hair (HairAngle).
  std::size_t ErodedTriangles = 0;
  /// What the final fit did (all zero without it), and its time.
  EnvelopeFitResult Fit;
  double FitSeconds = 0.0;
  /// When the fit changed the radii of the spheres on the sheets' boundary
  /// (FitSheetBoundaryRadii): every sphere's radius as the collapses placed
  /// it (else empty).
  std::vector<double> PlacedRadii;
};

/// `rvd`: the restricted Voronoi diagram whose sites the Atlases refer to
/// (its polygons give each cell's quadric, its flags the feature classes);
/// `sites`: the site positions. Deterministic: the same result at any
/// thread count.
AtlasSimplifierResult SimplifyMedialAxis(const AtlasMedialMesh& input,
  const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const AtlasSimplifierOptions& options = AtlasSimplifierOptions());

/// The same, for a caller done with `input`: the hair is eroded in place
/// instead of in a copy, and the input's arrays are freed once the
/// collapses hold their own (the whole initial MAT less at the peak).
/// `input` is left empty.
AtlasSimplifierResult SimplifyMedialAxis(AtlasMedialMesh&& input,
  const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const AtlasSimplifierOptions& options = AtlasSimplifierOptions());
}

#endif
