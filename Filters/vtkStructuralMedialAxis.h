// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkStructuralMedialAxis
 * @brief   Surface in, simplified Structural MAT out: the whole chain in one filter.
 *
 * Runs vtkBlueNoiseSurfaceSampler -> vtkRestrictedVoronoiDiagram ->
 * vtkVoronoiMedialAxis -> vtkAtlasMedialAxisSimplifier (or, with Strategy
 * QMat, vtkQMatSimplifier on the same initial medial mesh) on a closed
 * triangle surface, with every stage's main parameters exposed here. Two presets
 * follow the paper's settings: SetPresetToCAD() (50,000 samples -> 5,000
 * spheres, sharp features preserved) and SetPresetToOrganic() (10,000 ->
 * 1,000, no feature snapping); the constructor applies the organic one.
 *
 * Output port 0: the simplified medial mesh (`Radius`, Atlas, `FeatureVertex`,
 * `StabilityRatio`), with field data `<Stage>Seconds` for the stages
 * Sampling, RestrictedVoronoi, VoronoiMedialAxis and Simplification,
 * `TotalSeconds`, and the counts `Sites`, `InitialVertices`,
 * `InitialTriangles` and the simplifier's own. Output port 1: the restricted
 * Voronoi diagram with `MedialVertexId` (the surface coloured by
 * correspondence). Output port 2: the surface sites. Output port 3 (with
 * GenerateEnvelope, the default): the envelope of the medial mesh as
 * vtkSlabReconstructor's overlapping primitive surfaces (field data
 * `EnvelopeSeconds` on port 0).
 *
 * With RepairSelfIntersections (the default), a surface whose shells cross
 * or that passes through itself is first resolved into the closed outer
 * boundary of the solid (see vtkMedialSurfaceValidator); the stages run on
 * it, port 0's field data says so (`RepairedCrossingPairs`,
 * `RepairRemovedAreaFraction`, `RepairSeconds`) and port 1 gets
 * `InputTriangleId`, the input cell each Voronoi cell's triangle is a piece
 * of. Where the crossings cannot be resolved exactly, the surface is
 * wrapped instead (the validator's fallback): a warning says so, with
 * `RepairWrapped` 1 and `RepairDeviationFraction` (the largest distance from
 * the wrap to the input over the diagonal); `InputTriangleId` is then the
 * nearest input cell. A small contact that cannot be resolved, a vertex
 * poking through a wall far from it on the surface, is pulled apart instead
 * (see vtkMedialSurfaceValidator): a warning says so, with
 * `RepairPulledApart` 1 and `RepairDeviationFraction` the largest move.
 *
 * The medial axis of a solid has one loop per handle. Where the initial
 * medial mesh has fewer (a handle thinner than the sampling could follow),
 * the sites are drawn again: with AdaptiveSampling, thin parts twice as
 * dense each round with samples beyond NumberOfSamples there
 * (vtkBlueNoiseSurfaceSampler's ThinPartExtraSamples); without it, twice as
 * many samples; three rounds at most. Port 0's field data `AddedSamples`
 * gives the samples beyond NumberOfSamples and `MissingLoops` the handles
 * still missed, which a warning names.
 *
 * Progress moves through the stages in proportion to their usual cost; an
 * abort stops the running stage and leaves the outputs empty. Errors of a
 * stage (e.g. an open or non-manifold surface) are reported with the stage's
 * name and leave the outputs empty.
 *
 * The stages run on the surface moved to the origin and scaled by a power of
 * two to about unit size; the outputs are moved back. A surface far from the
 * origin (an offset of 1e6) or at any scale (1e-30, 1e30) thus gives its
 * medial axis with the precision of a unit-sized one.
 */
#ifndef vtkStructuralMedialAxis_h
#define vtkStructuralMedialAxis_h

#include "vtkAtlasMedialAxisSimplifier.h" // for its FringeCollapseType values
#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkStructuralMedialAxis : public vtkPolyDataAlgorithm
{
public:
  static vtkStructuralMedialAxis* New();
  vtkTypeMacro(vtkStructuralMedialAxis, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The paper's CAD settings: 50,000 samples, 5,000 spheres, sharp
  /// features preserved.
  void SetPresetToCAD();
  /// The paper's organic settings: 10,000 samples, 1,000 spheres, no
  /// feature snapping.
  void SetPresetToOrganic();

  ///@{
  /// Number of blue-noise surface samples (sites), exactly (default 10,000).
  vtkSetClampMacro(NumberOfSamples, vtkIdType, 4, 100000000);
  vtkGetMacro(NumberOfSamples, vtkIdType);
  ///@}

  ///@{
  /// Sample thin parts densely, by the local thickness of the solid (see
  /// vtkBlueNoiseSurfaceSampler::Adaptive), so that tentacles, ears and
  /// thin plates are in the medial axis. On in the organic preset (the
  /// default; organic median Hausdorff 0.73% -> 0.55%, octopus 5.6% ->
  /// 1.0%), off in the CAD preset (50,000 uniform samples resolve CAD
  /// parts, and the sharp edges of some lose by the thinner spacing
  /// elsewhere).
  vtkSetMacro(AdaptiveSampling, bool);
  vtkGetMacro(AdaptiveSampling, bool);
  vtkBooleanMacro(AdaptiveSampling, bool);
  ///@}

  ///@{
  /// Seed of the sampler: same seed, same result (default 0).
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /// Spheres left after simplification (default 1,000).
  vtkSetClampMacro(TargetNumberOfVertices, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(TargetNumberOfVertices, vtkIdType);
  ///@}

  ///@{
  /// An error target instead of the vertex target: when above 0, the
  /// simplification goes to few spheres whose two-sided Hausdorff distance
  /// to the surface (vtkMedialReconstructionError, default settings) stays
  /// within MaximumError times the surface's bounding-box diagonal (e.g.
  /// 0.005 for 0.5%). The Structural strategy simplifies by error-bounded
  /// collapses (vtkAtlasMedialAxisSimplifier::ErrorBound) as far as they
  /// go, at local bounds of MaximumError, a half, a quarter and an eighth of
  /// it, and keeps the first run whose distance is within MaximumError
  /// (field data `ErrorBound`: the local bound used; bunny, 10,000 samples,
  /// 0.5%: 396 spheres at 0.46% after two runs). When none is, and with the
  /// QMat strategy, the count is searched, halving from the initial medial
  /// mesh until the bound is first passed and then bisecting between the
  /// last two counts to within 5%; each step simplifies and measures, so
  /// this costs about ten to twenty runs of the simplifier and the error
  /// measure. The distance does not always grow as spheres go, so the count
  /// found is within the bound but not always the smallest that is (bunny at
  /// 0.5%: 21,862 spheres). When even the initial medial mesh is not within
  /// it, that is the output, with a warning (more samples are needed).
  /// Field data: `MaximumError`, `ErrorTargetHausdorff` (reached, same
  /// units), `ErrorTargetEvaluations`. Default 0: TargetNumberOfVertices.
  vtkSetClampMacro(MaximumError, double, 0.0, 1.0);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /// CAD mode: snap spheres whose surface cells touch a sharp convex edge
  /// onto it with radius 0 (default off).
  vtkSetMacro(PreserveSharpFeatures, bool);
  vtkGetMacro(PreserveSharpFeatures, bool);
  vtkBooleanMacro(PreserveSharpFeatures, bool);
  ///@}

  ///@{
  /// Dihedral tolerance (degrees) for sharp convex and concave surface edges
  /// (default 45, as in the paper).
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// Iterations of bilateral normal filtering that must confirm every sharp
  /// convex edge (default 3; 0 = test the raw triangle normals alone). On
  /// noisy surfaces (scans, perturbed exports) the raw normals take the
  /// noise for ridges, which PreserveSharpFeatures would snap medial
  /// vertices onto; the filtered normals average it out while keeping real
  /// edges. On clean meshes it only drops edges within a few degrees of the
  /// FeatureAngle. Concave edges keep the raw test.
  vtkSetClampMacro(FeatureNormalFiltering, int, 0, 100);
  vtkGetMacro(FeatureNormalFiltering, int);
  ///@}

  ///@{
  /// Remove medial faces near concave edges (paper Eq. 4; default on).
  vtkSetMacro(ConcaveFiltering, bool);
  vtkGetMacro(ConcaveFiltering, bool);
  vtkBooleanMacro(ConcaveFiltering, bool);
  ///@}

  ///@{
  /// Let the simplifier break the link condition with collapses that keep
  /// the Euler characteristic (see vtkAtlasMedialAxisSimplifier, whose
  /// FringeOff / FringeOn / FringeAutomatic values this takes): automatic by
  /// default, on for organic shapes simplified to at least 200 spheres. They remove the fringe of
  /// thin fins along large fillets' centre lines and keep organic shapes simplified far (50K
  /// samples -> 1,000 spheres) from losing ears and fingers. Automatic below 200 spheres on an
  /// organic shape (without MaximumError): the simplification runs without and with them, and
  /// the run with the smaller two-sided Hausdorff distance is kept (most organic shapes keep
  /// their parts and topology with them; tubes and blobs, whose medial axis is a curve or a
  /// point, shrink to it without). Field data `FringeCollapsesUsed`,
  /// `HausdorffWithoutFringeCollapses` and `HausdorffWithFringeCollapses` (fractions of the
  /// bounding-box diagonal) tell which and why.
  vtkSetClampMacro(FringeCollapses, int, vtkAtlasMedialAxisSimplifier::FringeOff,
    vtkAtlasMedialAxisSimplifier::FringeAutomatic);
  vtkGetMacro(FringeCollapses, int);
  vtkBooleanMacro(FringeCollapses, int);
  void SetFringeCollapsesToAutomatic()
  {
    this->SetFringeCollapses(vtkAtlasMedialAxisSimplifier::FringeAutomatic);
  }
  ///@}

  ///@{
  /// Error bands (see vtkAtlasMedialAxisSimplifier::ErrorBands): collapses
  /// go in the paper's cost order within bands of local error, so that
  /// spheres go where they keep the envelope close. Automatic (default): on
  /// for organic shapes (PreserveSharpFeatures off). Structural
  /// strategy only; field data ErrorBandsUsed.
  vtkSetClampMacro(ErrorBands, int, vtkAtlasMedialAxisSimplifier::BandsOff,
    vtkAtlasMedialAxisSimplifier::BandsAutomatic);
  vtkGetMacro(ErrorBands, int);
  vtkBooleanMacro(ErrorBands, int);
  void SetErrorBandsToAutomatic()
  {
    this->SetErrorBands(vtkAtlasMedialAxisSimplifier::BandsAutomatic);
  }
  ///@}

  ///@{
  /// Cleaner or closer (see vtkAtlasMedialAxisSimplifier::HairAngle and
  /// FinBudget): Voronoi faces whose two samples subtend less than
  /// HairAngle degrees at their spheres are eroded before the collapses
  /// (default 45; 0: off), and fins whose spheres reach out of their
  /// junction by at most FinBudget of the diagonal are collapsed into the
  /// sheet they hang on (default 0.005; 0: off). Larger values: fewer,
  /// larger sheets. Structural strategy and organic shapes only (sharp
  /// features not preserved); field data ErodedTriangles and FinCollapses.
  vtkSetClampMacro(HairAngle, double, 0.0, 90.0);
  vtkGetMacro(HairAngle, double);
  vtkSetClampMacro(FinBudget, double, 0.0, 0.1);
  vtkGetMacro(FinBudget, double);
  /// The pleat guard (see vtkAtlasMedialAxisSimplifier::PleatAngle):
  /// default 90 degrees; 10 guards against folds only.
  vtkSetClampMacro(PleatAngle, double, 10.0, 90.0);
  vtkGetMacro(PleatAngle, double);
  ///@}

  ///@{
  /// Spike edges (stability ratio below SpikeThreshold) collapse into the
  /// larger ball, unchanged, ahead of everything else (see
  /// vtkAtlasMedialAxisSimplifier): far fewer spike edges (16
  /// organic meshes at 10,000 samples -> 1,000 spheres: at most 0.32%
  /// instead of 0.53%) at a slightly larger distance (median 0.526% ->
  /// 0.549%). Default off.
  vtkSetMacro(AbsorbSpikes, bool);
  vtkGetMacro(AbsorbSpikes, bool);
  vtkBooleanMacro(AbsorbSpikes, bool);
  ///@}

  ///@{
  /// Clamp each merged sphere's radius to the distance to the nearest surface
  /// sample of its Atlas (see vtkAtlasMedialAxisSimplifier): closer on CAD
  /// parts (median two-sided Hausdorff distance of the 13 CAD meshes of the
  /// shared set 0.58% -> 0.47%), farther on some organic ones; default off.
  vtkSetMacro(ClampRadiiToAtlas, bool);
  vtkGetMacro(ClampRadiiToAtlas, bool);
  vtkBooleanMacro(ClampRadiiToAtlas, bool);
  ///@}

  ///@{
  /// Let spike edges pass the link condition with collapses that keep the
  /// Euler characteristic (see vtkAtlasMedialAxisSimplifier): removes most
  /// spike triangles of organic shapes (default off: on coarse convex shapes
  /// the merged balls can reach a few percent outside the surface).
  vtkSetMacro(EulerNeutralSpikeCollapses, bool);
  vtkGetMacro(EulerNeutralSpikeCollapses, bool);
  vtkBooleanMacro(EulerNeutralSpikeCollapses, bool);
  ///@}

  ///@{
  /// Fit the spheres to the surface after the last collapse (default on; see
  /// vtkAtlasMedialAxisSimplifier::FinalFit). Structural strategy only.
  vtkSetMacro(FinalFit, bool);
  vtkGetMacro(FinalFit, bool);
  vtkBooleanMacro(FinalFit, bool);
  ///@}

  ///@{
  /// CAD mode: let the final fit change the radii of the spheres on the
  /// sheets' boundary (fillet centre lines) too (default on; the placed
  /// radii stay as point data `PlacedRadius`; see
  /// vtkAtlasMedialAxisSimplifier::FitSheetBoundaryRadii).
  vtkSetMacro(FitSheetBoundaryRadii, bool);
  vtkGetMacro(FitSheetBoundaryRadii, bool);
  vtkBooleanMacro(FitSheetBoundaryRadii, bool);
  ///@}

  ///@{
  /// Weight of the final fit's pull on spike edges (default 10; 0: off; see
  /// vtkAtlasMedialAxisSimplifier::FitSpikeRepair).
  vtkSetClampMacro(FitSpikeRepair, double, 0.0, 1e6);
  vtkGetMacro(FitSpikeRepair, double);
  ///@}

  ///@{
  /// Simplification strategy: Structural (default, the Atlas-guided energy
  /// of Structural MAT) or QMat (Q-MAT's slab quadric error on the same
  /// initial medial mesh, for comparison; sharp-feature snapping, Lambda and
  /// SpikeThreshold do not apply to it).
  enum StrategyType
  {
    Structural = 0,
    QMat = 1
  };
  vtkSetClampMacro(Strategy, int, Structural, QMat);
  vtkGetMacro(Strategy, int);
  void SetStrategyToStructural() { this->SetStrategy(Structural); }
  void SetStrategyToQMat() { this->SetStrategy(QMat); }
  ///@}

  ///@{
  /// Laplacian weight of the collapse energy, in the model scaled to the
  /// unit box (default 6e-6, as in the paper).
  vtkSetClampMacro(Lambda, double, 0.0, 1.0);
  vtkGetMacro(Lambda, double);
  ///@}

  ///@{
  /// Stability ratio below which an edge is a spike, collapsed first
  /// (default 0.025, as in the paper).
  vtkSetClampMacro(SpikeThreshold, double, 0.0, 1.0);
  vtkGetMacro(SpikeThreshold, double);
  ///@}

  ///@{
  /// Threads for the parallel stages; 0 = all cores (default). The result
  /// does not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Resolve shells that cross each other and a surface that passes
  /// through itself into the outer boundary of the solid they enclose, and
  /// compute the medial axis of that, instead of refusing them (default on).
  /// Open, non-manifold and non-orientable surfaces are refused either way.
  vtkSetMacro(RepairSelfIntersections, bool);
  vtkGetMacro(RepairSelfIntersections, bool);
  vtkBooleanMacro(RepairSelfIntersections, bool);
  ///@}

  ///@{
  /// Also output the envelope (balls, cones, slabs) on port 3 (default on;
  /// it costs a few percent of the run).
  vtkSetMacro(GenerateEnvelope, bool);
  vtkGetMacro(GenerateEnvelope, bool);
  vtkBooleanMacro(GenerateEnvelope, bool);
  ///@}

protected:
  vtkStructuralMedialAxis();
  ~vtkStructuralMedialAxis() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfSamples = 10000;
  int RandomSeed = 0;
  bool AdaptiveSampling = true;
  vtkIdType TargetNumberOfVertices = 1000;
  double MaximumError = 0.0;
  bool PreserveSharpFeatures = false;
  int FringeCollapses = vtkAtlasMedialAxisSimplifier::FringeAutomatic;
  int ErrorBands = vtkAtlasMedialAxisSimplifier::BandsAutomatic;
  double HairAngle = 45.0;
  double FinBudget = 0.005;
  double PleatAngle = 90.0;
  bool EulerNeutralSpikeCollapses = false;
  bool ClampRadiiToAtlas = false;
  bool AbsorbSpikes = false;
  bool FinalFit = true;
  bool FitSheetBoundaryRadii = true;
  double FitSpikeRepair = 10.0;
  int Strategy = Structural;
  double FeatureAngle = 45.0;
  int FeatureNormalFiltering = 3;
  bool ConcaveFiltering = true;
  double Lambda = 6e-6;
  double SpikeThreshold = 0.025;
  int NumberOfThreads = 0;
  bool GenerateEnvelope = true;
  bool RepairSelfIntersections = true;

private:
  vtkStructuralMedialAxis(const vtkStructuralMedialAxis&) = delete;
  void operator=(const vtkStructuralMedialAxis&) = delete;
};

#endif
