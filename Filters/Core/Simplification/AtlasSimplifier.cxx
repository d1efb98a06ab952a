// SPDX-License-Identifier: GPL-3.0-or-later
#include "Simplification/AtlasSimplifier.h"
#include "Simplification/HairErosion.h"

#include "Fitting/EnvelopeFit.h"
#include "Fitting/FitPoints.h"

#include "Simplification/AtlasPolicy.h"
#include "Simplification/EdgeCollapse.h"
#include "Support/HeapRelease.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

namespace medialaxis
{
namespace
{
EdgeCollapseOptions CollapseOptions(const AtlasSimplifierOptions& o)
{
  EdgeCollapseOptions c;
  c.TargetNumberOfVertices = o.TargetNumberOfVertices;
  c.MaximumCost = o.MaximumCost;
  c.SpikeThreshold = o.SpikeThreshold;
  c.RequeueSpikes = o.AbsorbSpikes;
  c.TopologyGuardVertexCount = o.TopologyGuardVertexCount;
  c.FringeCollapses = UsesFringeCollapses(o);
  c.EulerNeutralSpikeCollapses = o.EulerNeutralSpikeCollapses;
  c.StrictLinkConditionVertexCount = o.StrictLinkConditionVertexCount;
  c.StrictTopologyGuard = o.StrictTopologyGuard;
  c.PreventFolds = o.PreventFolds;
  c.StopWhenStalled = o.ErrorBound > 0.0;
  c.MaximumBatch = o.ParallelBatches ? c.MaximumBatch : 1;
  c.CheckAhead = o.CheckAhead;
  c.Progress = o.Progress;
  return c;
}
} // namespace

bool UsesErrorBands(const AtlasSimplifierOptions& o)
{
  if (o.ErrorBound > 0.0)
  {
    return false;
  }
  switch (o.ErrorBands)
  {
    case ErrorBandMode::On:
      return true;
    case ErrorBandMode::Off:
      return false;
    default:
      return !o.PreserveSharpFeatures;
  }
}

bool UsesHairErosion(const AtlasSimplifierOptions& o)
{
  // Not on CAD parts (sharp features preserved): there the erosion and the
  // fin collapses shorten the sheets' boundary (fandisk, 50,000 -> 5,000:
  // 18.0 -> 12.6 diagonals) but move the fillet centre lines the detector
  // reads off that boundary (a box with fillets of radius 0.1: by up to
  // 1.01% of the diagonal, where 1% is the bound its tests hold).
  return o.HairAngle > 0.0 && !o.PreserveSharpFeatures &&
    o.TargetNumberOfVertices >= o.StrictLinkConditionVertexCount;
}

bool UsesPleatGuard(const AtlasSimplifierOptions& o)
{
  // Like the erosion, not below the strict link condition's count: tubes
  // shrink to a curve there through sliver triangles that pleat (a dumbbell
  // at 5,000 samples -> 100 spheres keeps a strip that needs 9 skeletal
  // elements instead of 3). Nor on CAD parts, whose medial structure it
  // changes: a box with rounded edges (5,000 spheres) then has 10 sheets by
  // its tangent components instead of its 12.
  return o.PleatAngle > FoldAngleDegrees && !o.PreserveSharpFeatures &&
    o.TargetNumberOfVertices >= o.StrictLinkConditionVertexCount;
}

bool UsesFringeCollapses(const AtlasSimplifierOptions& o)
{
  switch (o.FringeCollapses)
  {
    case FringeCollapseMode::On:
      return true;
    case FringeCollapseMode::Off:
      return false;
    case FringeCollapseMode::Automatic:
      break;
  }
  return !o.PreserveSharpFeatures && o.TargetNumberOfVertices >= o.StrictLinkConditionVertexCount;
}

namespace
{
using Clock = std::chrono::steady_clock;

// The surface points of the final fit. Organic shapes: the corners of the
// cells, where an envelope through the sites falls shortest on curved
// surfaces, triple the points. CAD parts, mostly flat or singly curved and
// sampled densely, fit as closely through the sites alone at a third of the
// cost, but their balls poke out along sharp edges, which only the dense
// surface sees.
FitTarget FinalFitTarget(const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const AtlasSimplifierOptions& options)
{
  FitPointsOptions pointOptions;
  pointOptions.Corners = !options.PreserveSharpFeatures;
  pointOptions.DenseSurface = options.PreserveSharpFeatures;
  return FitPoints(rvd, sites, pointOptions);
}

// `owned`: `initial` when the caller gave it up; it is then freed as soon
// as the collapses and the policy hold what they need of it.
AtlasSimplifierResult Simplify(const AtlasMedialMesh& initial, AtlasMedialMesh* owned,
  std::size_t erodedTriangles, Clock::time_point start, const RestrictedVoronoiDiagram& rvd,
  const std::vector<Point3>& sites, const AtlasSimplifierOptions& options,
  std::unique_ptr<const AtlasSiteCells> cells)
{
  // (The sites' part of the policy when the caller did not make it.)
  if (!cells)
  {
    cells = std::make_unique<const AtlasSiteCells>(rvd, sites, options);
  }
  AtlasPolicy policy(initial, rvd, std::move(cells), options);
  EdgeCollapseOptions collapseOptions = CollapseOptions(options);
  // Fins, as the erosion, on organic shapes only (see UsesHairErosion).
  collapseOptions.FinBudget =
    options.PreserveSharpFeatures ? 0.0 : options.FinBudget * policy.DiagonalLength();
  collapseOptions.FoldAngle =
    UsesPleatGuard(options) ? std::max(options.PleatAngle, FoldAngleDegrees) : FoldAngleDegrees;
  MedialEdgeCollapse mesh(initial.Mesh, policy.Frame(), collapseOptions, policy);
  if (owned)
  {
    *owned = AtlasMedialMesh();
    ReleaseFreeHeapPages();
  }
  const double setupSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  const EdgeCollapseCounts counts = mesh.Run();
  AtlasSimplifierResult result;
  static_cast<EdgeCollapseCounts&>(result) = counts;
  result.QueueInitialisationSeconds += setupSeconds;
  result.ErodedTriangles = erodedTriangles;
  if (!counts.Aborted)
  {
    result.Medial = policy.Output(mesh);
    result.ForcedSnaps = policy.ForcedSnaps;
    result.SnappedVertices = policy.Snapped.load();
    if (options.FinalFit)
    {
      const auto fitStart = std::chrono::steady_clock::now();
      const FitTarget target = FinalFitTarget(rvd, sites, options);
      EnvelopeFitOptions fit;
      fit.Iterations = options.FitIterations;
      fit.SpikeThreshold = options.SpikeThreshold;
      fit.SpikeRepairWeight = options.FitSpikeRepair;
      // The fit may not pleat what the collapses kept smooth (with the pleat
      // guard, the fit made every pleat left: 16 organic meshes at 10,000 ->
      // 1,000, median 1.8% -> 0%). Not on CAD parts: there the guard holds
      // back moves that close the envelope along sharp edges (fandisk,
      // 50,000 -> 5,000: pleats 2.6% -> 1.6%, Hausdorff 0.58% -> 0.83%).
      fit.FoldAngle = collapseOptions.FoldAngle;
      fit.Progress = [&](double) { return !options.Progress || options.Progress(1.0); };
      // CAD parts: feature vertices stay on their sharp edges, and the
      // boundary of the medial sheets, where fillet centre lines run, keeps
      // its centres (the fillet detector finds and refines those lines from
      // them) and, without FitSheetBoundaryRadii, its radii; with it, the
      // placed radii are kept aside for the detector.
      std::vector<SphereFreedom> freedom;
      if (options.PreserveSharpFeatures)
      {
        if (options.FitSheetBoundaryRadii)
        {
          result.PlacedRadii = result.Medial.Mesh.Radii;
        }
        freedom.assign(result.Medial.Mesh.NumberOfVertices(), SphereFreedom::Free);
        for (const auto& e : SheetBoundaryEdges(result.Medial.Mesh))
        {
          freedom[e[0]] = freedom[e[1]] =
            options.FitSheetBoundaryRadii ? SphereFreedom::RadiusOnly : SphereFreedom::Fixed;
        }
        for (std::size_t v = 0; v < freedom.size(); ++v)
        {
          if (result.Medial.FeatureVertex[v])
          {
            freedom[v] = SphereFreedom::Fixed;
          }
        }
      }
      result.Fit = FitMedialEnvelope(result.Medial.Mesh, target, freedom, fit);
      result.FitSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - fitStart).count();
    }
  }
  return result;
}
} // namespace

AtlasSimplifierResult SimplifyMedialAxis(const AtlasMedialMesh& input,
  const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const AtlasSimplifierOptions& options)
{
  if (UsesHairErosion(options))
  {
    return SimplifyMedialAxis(AtlasMedialMesh(input), rvd, sites, options);
  }
  // Not eroded: the collapses copy what they need, the input stays as given.
  return Simplify(input, nullptr, 0, Clock::now(), rvd, sites, options, nullptr);
}

AtlasSimplifierResult SimplifyMedialAxis(AtlasMedialMesh&& input,
  const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const AtlasSimplifierOptions& options)
{
  // Setup (per-cell quadrics, Atlases, connectivity) plus the snapping and
  // evaluation of every edge is the queue initialisation.
  const Clock::time_point start = Clock::now();
  ReleaseFreeHeapPages();
  // Hair first: the collapses then start from the sheets that stand for the
  // solid's thickness. Not below StrictLinkConditionVertexCount, where the
  // medial axis of a tube must shrink to a curve under the strict link
  // condition: from the eroded sheets the collapses stall short of it (a
  // torus, 10,000 samples -> 50 spheres, keeps 52 triangles where it has
  // none without the erosion; at 200 spheres it keeps 23 against 399
  // without).
  std::size_t eroded = 0;
  std::unique_ptr<const AtlasSiteCells> cells;
  if (UsesHairErosion(options))
  {
    // The erosion runs on one thread; the policy's part of the sites is made
    // beside it (bunny at 50,000 samples: 0.04-0.07 s of the set-up). (Not
    // the fit's points too: held through the collapses, they raised igea's
    // peak at 50,000 samples from 283 to 303 MB.)
    tbb::task_group beside;
    beside.run([&] { cells = std::make_unique<const AtlasSiteCells>(rvd, sites, options); });
    try
    {
      eroded = ErodeHair(input, sites, options.HairAngle).RemovedTriangles;
    }
    catch (...)
    {
      beside.wait();
      throw;
    }
    beside.wait();
  }
  return Simplify(input, &input, eroded, start, rvd, sites, options, std::move(cells));
}
} // namespace medialaxis
