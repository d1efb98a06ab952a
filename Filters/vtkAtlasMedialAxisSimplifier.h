// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkAtlasMedialAxisSimplifier
 * @brief   Simplifies a medial mesh by Atlas-guided edge collapses (Structural MAT).
 *
 * Input port 0: a medial mesh with its Atlas (field data `AtlasSites` /
 * `AtlasOffsets`), normally from vtkVoronoiMedialAxis (whose point data
 * `SiteClearance`, when present with double-precision points, spares the
 * error bands most of their searches; the result is the same without it).
 * Input port 1: the
 * restricted Voronoi diagram (output 0 of vtkRestrictedVoronoiDiagram): its
 * polygons give each surface cell's spherical quadric, and its field data
 * (`SitePositions`, `SiteConvexFeature`, `SiteConcaveFeature`) the per-site
 * values, so the per-site feature flags travel with the RVD.
 *
 * Every vertex stands for the surface cells of its Atlas. Collapsing an edge
 * places the merged sphere where the spherical quadric error over the union
 * of both Atlases (each cell counted once) plus Lambda x a uniform Laplacian
 * over the merged one-ring is smallest (closed form; L-BFGS when cells on
 * concave edges use the distance-to-site term). Edges are collapsed in order
 * of that error times a sigmoid of their stability ratio, so spikes go first.
 * A collapse that would create a duplicate, degenerate or flipped triangle,
 * or fold two triangles onto each other (dihedral angle below 10 degrees),
 * is refused (and retried only after its neighbourhood changes); only when
 * no other collapse is left (tubes whose thin sheets must shrink to a curve)
 * are folds allowed, counted in field data FoldingAllowedCollapses. Below
 * TopologyGuardVertexCount vertices the link condition also guards the
 * topology; collapses that break it but keep the Euler characteristic are
 * allowed above 200 vertices by FringeCollapses (automatic by default: for
 * organic shapes; field data FringeCollapsesUsed says whether they were).
 * With PreserveSharpFeatures, feature vertices (Atlas on a sharp convex
 * edge, none on a concave one) are first snapped to their edge with radius 0
 * and stay there; snaps that fold or flatten a triangle are made last and
 * the collapses around them first (field data ForcedSnaps). Folds that
 * those collapses leave are removed just before the target is reached: a
 * few vertices short of it, the cheapest collapse at each fold that leaves
 * fewer folds around it is made (field data FoldRepairCollapses).
 *
 * The cheapest collapses whose edges lie at least five edges apart are made
 * at once, in parallel, in batches of up to 64 (field data CollapseBatches):
 * the result is the same at any thread count, though not exactly that of
 * strictly one collapse at a time, with or without PreserveSharpFeatures.
 *
 * Output port 0: the simplified medial mesh (input units) with `Radius`,
 * the final Atlas (`AtlasSites`, `AtlasOffsets`, `AtlasCount`), point data
 * `FeatureVertex` and cell data `StabilityRatio` (per line: its edge's ratio;
 * per triangle: the smallest of its edges'). Output port 1: the RVD with
 * cell data `MedialVertexId`: a vertex whose Atlas holds the polygon's site
 * (colour the surface by it to see the correspondence).
 */
#ifndef vtkAtlasMedialAxisSimplifier_h
#define vtkAtlasMedialAxisSimplifier_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkAtlasMedialAxisSimplifier : public vtkPolyDataAlgorithm
{
public:
  static vtkAtlasMedialAxisSimplifier* New();
  vtkTypeMacro(vtkAtlasMedialAxisSimplifier, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Stop when this many vertices remain (default 1000; the paper uses 1,000
  /// for organic and 5,000 for CAD models).
  vtkSetClampMacro(TargetNumberOfVertices, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(TargetNumberOfVertices, vtkIdType);
  ///@}

  ///@{
  /// Stop earlier when the cheapest collapse costs more than this (in the
  /// model scaled to the unit box; default: no limit).
  vtkSetClampMacro(MaximumCost, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumCost, double);
  ///@}

  ///@{
  /// Weight of the Laplacian term in the unit-box model (default 6e-6).
  vtkSetClampMacro(Lambda, double, 0.0, 1.0);
  vtkGetMacro(Lambda, double);
  ///@}

  ///@{
  /// Stability threshold tau (default 0.025) and sigmoid sharpness k
  /// (default 100): edges less stable than tau are collapsed first.
  vtkSetClampMacro(SpikeThreshold, double, 0.0, 1.0);
  vtkGetMacro(SpikeThreshold, double);
  vtkSetClampMacro(SpikeSharpness, double, 0.0, 1e6);
  vtkGetMacro(SpikeSharpness, double);
  ///@}

  ///@{
  /// Below this many vertices every collapse must satisfy the link condition
  /// (default 0: always, at any count). The paper uses 200; on the bunny
  /// (50K sites -> 5,000 vertices) that leaves Euler characteristic 66
  /// instead of 1, because earlier collapses close loops into bubbles. 1
  /// never guards.
  vtkSetClampMacro(TopologyGuardVertexCount, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(TopologyGuardVertexCount, vtkIdType);
  ///@}

  ///@{
  /// When, below the guard, no collapse keeps the link condition before the
  /// target is reached: stop there (on) or reach the target without it (off,
  /// default; such collapses are counted in field data RelaxedCollapses).
  vtkSetMacro(StrictTopologyGuard, bool);
  vtkGetMacro(StrictTopologyGuard, bool);
  vtkBooleanMacro(StrictTopologyGuard, bool);
  ///@}

  ///@{
  /// CAD mode: snap feature vertices to sharp edges with radius 0 and keep
  /// them there (default on; turn off for organic shapes).
  vtkSetMacro(PreserveSharpFeatures, bool);
  vtkGetMacro(PreserveSharpFeatures, bool);
  vtkBooleanMacro(PreserveSharpFeatures, bool);
  ///@}

  ///@{
  /// Use the distance-to-site fidelity for cells on concave edges (default
  /// on); off treats them like every other cell (an ablation switch).
  vtkSetMacro(InvaginatedTerm, bool);
  vtkGetMacro(InvaginatedTerm, bool);
  vtkBooleanMacro(InvaginatedTerm, bool);
  ///@}

  ///@{
  /// Spike edges (stability ratio below SpikeThreshold) collapse into the
  /// larger ball, unchanged, ahead of everything else (see
  /// AtlasSimplifierOptions::AbsorbSpikes): far fewer spike edges (16
  /// organic meshes at 10,000 samples -> 1,000 spheres: at most 0.32%
  /// instead of 0.53%) at a slightly larger distance (median 0.526% ->
  /// 0.549%). Default off.
  vtkSetMacro(AbsorbSpikes, bool);
  vtkGetMacro(AbsorbSpikes, bool);
  vtkBooleanMacro(AbsorbSpikes, bool);
  ///@}

  ///@{
  /// Error bands (when ErrorBound is 0): a collapse whose local error (see
  /// ErrorBound) exceeds a bound waits; the bound starts at 0.1% of the
  /// diagonal and grows by half at every stall short of the target, so that
  /// the collapses go in the paper's cost order within bands of error and
  /// spheres go where they keep the envelope close (16 organic meshes,
  /// 10,000 samples -> 1,000 spheres: median two-sided Hausdorff distance
  /// 0.53% -> 0.44%; -> 300 spheres 0.89% -> 0.53%), at the price of more
  /// spike edges, which cover surface the bound keeps.
  /// - Off (0): the paper's cost order alone.
  /// - On (1).
  /// - Automatic (2, default): on for organic shapes (PreserveSharpFeatures
  ///   off). On CAD parts the sheets' boundary no longer follows the fillet
  ///   centre lines (which vtkFilletDetector needs).
  /// Field data ErrorBandsUsed says whether they were used.
  enum ErrorBandType
  {
    BandsOff = 0,
    BandsOn = 1,
    BandsAutomatic = 2
  };
  vtkSetClampMacro(ErrorBands, int, BandsOff, BandsAutomatic);
  vtkGetMacro(ErrorBands, int);
  vtkBooleanMacro(ErrorBands, int);
  void SetErrorBandsToAutomatic() { this->SetErrorBands(BandsAutomatic); }
  ///@}

  ///@{
  /// Cleaner or closer (docs/methods.md, "Clean sheets"). HairAngle: before
  /// the collapses, Voronoi faces whose two surface samples subtend less
  /// than this angle (degrees) at their spheres' centres are eroded from
  /// their free edges inwards, keeping the topology: they stand for the
  /// sampling of a curved or bumpy surface, not for the solid's thickness,
  /// and become the fins that cut the sheets into pieces. Larger: fewer,
  /// larger sheets; smaller: closer to small bumps; 0: off. Default 45.
  /// Organic shapes only (PreserveSharpFeatures off), from 200 target
  /// spheres up. Field data ErodedTriangles counts the triangles eroded.
  vtkSetClampMacro(HairAngle, double, 0.0, 90.0);
  vtkGetMacro(HairAngle, double);
  ///@}

  ///@{
  /// FinBudget: fins left after the erosion (small sheets that branch off a
  /// larger one) whose spheres reach out of the cones of their junction by
  /// at most this fraction of the surface's bounding-box diagonal are
  /// collapsed into the junction (whose spheres stay) at a few checkpoints
  /// on the way to the target. 0 keeps every fin. Default 0.005 (0.5%).
  /// Organic shapes only (PreserveSharpFeatures off).
  /// Field data FinCollapses counts the collapses.
  vtkSetClampMacro(FinBudget, double, 0.0, 0.1);
  vtkGetMacro(FinBudget, double);
  ///@}

  ///@{
  /// PleatAngle: with PreventFolds, a collapse may not leave more pairs of
  /// triangles meeting below this dihedral angle (degrees) around the merged
  /// sphere than there were (pleats), besides never folding two triangles
  /// onto each other; where no collapse is left, only the latter holds.
  /// The final fit holds to the same angle. Organic shapes only
  /// (PreserveSharpFeatures off), from 200 target spheres up. Default 90;
  /// 10 guards against folds only.
  vtkSetClampMacro(PleatAngle, double, 10.0, 90.0);
  vtkGetMacro(PleatAngle, double);
  ///@}

  ///@{
  /// Error-bounded collapses: when above 0, a collapse whose local error
  /// exceeds this fraction of the surface's bounding-box diagonal waits, and
  /// the simplification stops short of TargetNumberOfVertices when none
  /// within the bound is left (field data `ErrorBound`; the vertex count
  /// reached is the output's). The local error is the largest distance,
  /// inside or outside, from a surface sample of the merged Atlas to the
  /// merged sphere's ball, cones and slabs, or how far the merged ball pokes
  /// out of the surface past the nearest sample. Set TargetNumberOfVertices to 1
  /// to simplify as far as the bound allows. Far closer than a vertex target
  /// at the same count (bunny, 10,000 samples: bound 0.3% stops at 282
  /// spheres with a two-sided Hausdorff distance of 0.53%, where the target
  /// 282 gives 0.98%). Default 0: no bound.
  vtkSetClampMacro(ErrorBound, double, 0.0, 1.0);
  vtkGetMacro(ErrorBound, double);
  ///@}

  ///@{
  /// Clamp each merged sphere's radius to the distance from its centre to
  /// the nearest surface sample of its Atlas, so that no sphere crosses the
  /// part of the surface it stands for (default off; closer on CAD parts,
  /// see AtlasSimplifierOptions::ClampRadiiToAtlas for the figures).
  vtkSetMacro(ClampRadiiToAtlas, bool);
  vtkGetMacro(ClampRadiiToAtlas, bool);
  vtkBooleanMacro(ClampRadiiToAtlas, bool);
  ///@}

  ///@{
  /// Refuse collapses that would fold two triangles onto each other
  /// (dihedral angle below 10 degrees), until no other collapse is left
  /// (default on; off reproduces the paper, which only tests each
  /// triangle's own flip).
  vtkSetMacro(PreventFolds, bool);
  vtkGetMacro(PreventFolds, bool);
  vtkBooleanMacro(PreventFolds, bool);
  ///@}

  ///@{
  /// Let collapses break the link condition, while more than 200 vertices
  /// remain, when they keep the Euler characteristic:
  /// - On (1): they remove the fringes of thin fins that large fillets leave
  ///   along their centre lines (rounded box, radius 0.25, 50K sites -> 2,000
  ///   vertices: 244 instead of 1,485 boundary edges), and the tangles of fins
  ///   that keep organic shapes simplified far (50K sites -> 1,000 vertices)
  ///   from reaching the target cleanly: without them ears and fingers
  ///   collapse first (two-sided Hausdorff distance median 9.4% of the
  ///   diagonal on 16 organic meshes, 1.4% with them).
  /// - Off (0): Dey's link condition guards every collapse.
  /// - Automatic (2, default): on for organic shapes (PreserveSharpFeatures
  ///   off) simplified to at least 200 vertices; off otherwise, since on
  ///   tube-like parts simplified to very few vertices (a torus to 50) they
  ///   leave folded sheets. For other organic shapes, On is the better choice
  ///   below 200 too (10K sites -> 100 vertices on the 16 organic meshes:
  ///   Hausdorff median 2.2% against 11.2% of the diagonal).
  enum FringeCollapseType
  {
    FringeOff = 0,
    FringeOn = 1,
    FringeAutomatic = 2
  };
  vtkSetClampMacro(FringeCollapses, int, FringeOff, FringeAutomatic);
  vtkGetMacro(FringeCollapses, int);
  vtkBooleanMacro(FringeCollapses, int);
  void SetFringeCollapsesToAutomatic() { this->SetFringeCollapses(FringeAutomatic); }
  ///@}

  ///@{
  /// The same for spike edges only (stability ratio below SpikeThreshold):
  /// removes spikes entangled with the sheets around them, which the link
  /// condition would otherwise keep to the end (16 organic meshes, 10K sites
  /// -> 1,000 vertices: triangles with a spike edge 1,037 -> 251, Euler
  /// characteristic unchanged, no folded triangles). Default off: on CAD
  /// parts it shortens fillet boundaries, and on a coarse sphere simplified
  /// to 50 vertices the merged balls reach up to 6% outside the surface.
  vtkSetMacro(EulerNeutralSpikeCollapses, bool);
  vtkGetMacro(EulerNeutralSpikeCollapses, bool);
  vtkBooleanMacro(EulerNeutralSpikeCollapses, bool);
  ///@}

  ///@{
  /// After the last collapse, fit the spheres to the surface (default on):
  /// with the connectivity fixed, centres and radii move so that the
  /// envelope passes through the sites (and, without PreserveSharpFeatures,
  /// the corners where three of their cells meet), by at most FitIterations
  /// damped Gauss-Newton rounds (each kept only when it lowers the squared
  /// distances; no move may fold or flatten a triangle or make a spike
  /// edge). With PreserveSharpFeatures the feature vertices and the spheres
  /// on the sheets' boundary (fillet centre lines) stay as placed (see
  /// FitSheetBoundaryRadii; CAD median 0.59% -> 0.57%). The simplification's placement
  /// lets spheres fall short of the surface between their tangent points;
  /// measured on the 16 organic meshes of the shared set (10,000 samples ->
  /// 1,000 spheres), the fit lowers the median two-sided Hausdorff distance
  /// from 1.21% to 0.73% of the diagonal. Field data FitRounds (rounds
  /// kept) and FitRMSBefore / FitRMSAfter (root mean square distance of the
  /// fit points to the envelope) and FitSeconds.
  vtkSetMacro(FinalFit, bool);
  vtkGetMacro(FinalFit, bool);
  vtkBooleanMacro(FinalFit, bool);
  vtkSetClampMacro(FitIterations, int, 0, 100);
  vtkGetMacro(FitIterations, int);
  ///@}

  ///@{
  /// Weight of the final fit's term that pulls spike edges (stability
  /// ratio below SpikeThreshold: one ball nearly inside the other) apart
  /// until they are no spikes, relative to the term that keeps balls inside
  /// the surface (default 10; 0: spike edges stay as the collapses left
  /// them). Collapses that would cost accuracy wait, and the needles they
  /// leave stand for bumps of the surface; moving their balls a little keeps
  /// the bump covered without the needle. 16 organic meshes, 10,000 samples
  /// -> 1,000 spheres: largest share of spike edges 1.22% -> 0.29%, median
  /// two-sided Hausdorff distance 0.440% -> 0.379%.
  vtkSetClampMacro(FitSpikeRepair, double, 0.0, 1e6);
  vtkGetMacro(FitSpikeRepair, double);
  ///@}

  ///@{
  /// With PreserveSharpFeatures the final fit keeps the centres of the
  /// spheres on the boundary of the sheets (fillet centre lines) as the
  /// collapses placed them; on (default), it fits their radii, off it keeps
  /// those too. On the 13 CAD meshes of the shared set (50,000 samples ->
  /// 5,000 spheres) the median two-sided Hausdorff distance falls from 0.57%
  /// to 0.36%. The placed radii are then point data `PlacedRadius`: on a
  /// fillet they are the rolling ball's, and vtkFilletDetector reads them.
  vtkSetMacro(FitSheetBoundaryRadii, bool);
  vtkGetMacro(FitSheetBoundaryRadii, bool);
  vtkBooleanMacro(FitSheetBoundaryRadii, bool);
  ///@}

  ///@{
  /// Threads to use (0 = all cores, default; or as many as an enclosing
  /// limit allows). Does not change the result.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkAtlasMedialAxisSimplifier();
  ~vtkAtlasMedialAxisSimplifier() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType TargetNumberOfVertices = 1000;
  int NumberOfThreads = 0;
  double MaximumCost = VTK_DOUBLE_MAX;
  double Lambda = 6e-6;
  double SpikeThreshold = 0.025;
  double SpikeSharpness = 100.0;
  vtkIdType TopologyGuardVertexCount = 0; // 0: always
  bool StrictTopologyGuard = false;
  bool PreserveSharpFeatures = true;
  bool InvaginatedTerm = true;
  bool ClampRadiiToAtlas = false;
  double ErrorBound = 0.0;
  int ErrorBands = BandsAutomatic;
  double HairAngle = 45.0;
  double FinBudget = 0.005;
  double PleatAngle = 90.0;
  bool AbsorbSpikes = false;
  bool PreventFolds = true;
  int FringeCollapses = FringeAutomatic;
  bool EulerNeutralSpikeCollapses = false;
  bool FinalFit = true;
  int FitIterations = 4;
  double FitSpikeRepair = 10.0;
  bool FitSheetBoundaryRadii = true;

private:
  vtkAtlasMedialAxisSimplifier(const vtkAtlasMedialAxisSimplifier&) = delete;
  void operator=(const vtkAtlasMedialAxisSimplifier&) = delete;
};

#endif
