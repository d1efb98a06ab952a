// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkQMatSimplifier
 * @brief   Simplifies a medial mesh by Q-MAT's slab quadric error metric.
 *
 * Q-MAT (Li et al. 2015) is the classic simplifier that Structural MAT
 * improves on; having it on the same initial medial mesh gives a side-by-side
 * comparison and reproduces the results users know from Q-MAT's `.ma` files.
 * It shares the collapse machinery with vtkAtlasMedialAxisSimplifier (queue,
 * validity checks, link condition, fold prevention); only the cost differs.
 *
 * Input: any medial mesh (point data `Radius`; triangles are slabs, lines
 * are cones), e.g. from vtkVoronoiMedialAxis or vtkMedialAxisReader. No
 * surface is needed: every vertex starts with the slab quadric error (SQE)
 * of its incident slabs (both tangent planes) and of the cones of its edges
 * that bound no triangle (four tangent planes), plus soft planes at stable
 * boundary vertices and edges (weight BoundaryWeight x stability ratio^2).
 * A collapse puts the merged sphere at the minimiser of the summed SQE (the
 * best of both ends and the midpoint when that is singular) and costs
 * (SQE + K) x stability ratio^2, so spikes go first.
 *
 * Output: the simplified medial mesh (input units) with `Radius` and cell
 * data `StabilityRatio`; when the input has Atlas arrays (`AtlasSites`,
 * `AtlasOffsets`) every output vertex gets the union of the Atlases merged
 * into it. Field data: Collapses, RejectedCollapses, RelaxedCollapses,
 * FoldingAllowedCollapses, MergedFaces, FacesWithoutTangentPlanes,
 * NestedCones, CollapseBatches (equal to Collapses + RejectedCollapses: as in
 * the published method, one collapse at a time).
 */
#ifndef vtkQMatSimplifier_h
#define vtkQMatSimplifier_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkQMatSimplifier : public vtkPolyDataAlgorithm
{
public:
  static vtkQMatSimplifier* New();
  vtkTypeMacro(vtkQMatSimplifier, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Stop when this many vertices remain (default 1000).
  vtkSetClampMacro(TargetNumberOfVertices, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(TargetNumberOfVertices, vtkIdType);
  ///@}

  ///@{
  /// Stop earlier when the cheapest collapse costs more than this (in the
  /// model scaled to a unit bounding-box diagonal; default: no limit).
  vtkSetClampMacro(MaximumCost, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumCost, double);
  ///@}

  ///@{
  /// The paper's k (default 1e-5, unit-diagonal model): while the SQE is far
  /// below it, edges collapse in order of stability ratio (spikes first).
  vtkSetClampMacro(K, double, 0.0, 1.0);
  vtkGetMacro(K, double);
  ///@}

  ///@{
  /// The paper's k0 (default 0.1): weight of the soft planes that keep stable
  /// boundaries from shrinking; 0 switches them off.
  vtkSetClampMacro(BoundaryWeight, double, 0.0, 1e6);
  vtkGetMacro(BoundaryWeight, double);
  ///@}

  ///@{
  /// The paper's eta: below this many vertices every collapse must satisfy
  /// the link condition (default 200).
  vtkSetClampMacro(TopologyGuardVertexCount, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(TopologyGuardVertexCount, vtkIdType);
  ///@}

  ///@{
  /// When, below the guard, no collapse keeps the link condition before the
  /// target is reached: stop there (on) or reach the target without it (off,
  /// default; counted in field data RelaxedCollapses).
  vtkSetMacro(StrictTopologyGuard, bool);
  vtkGetMacro(StrictTopologyGuard, bool);
  vtkBooleanMacro(StrictTopologyGuard, bool);
  ///@}

  ///@{
  /// Refuse collapses that fold two triangles onto each other until no other
  /// collapse is left (default on).
  vtkSetMacro(PreventFolds, bool);
  vtkGetMacro(PreventFolds, bool);
  vtkBooleanMacro(PreventFolds, bool);
  ///@}

  ///@{
  /// Where the link condition fails, still allow collapses that keep the
  /// Euler characteristic (default on): spikes entangled with the sheets
  /// around them are removed this way. Off follows the paper.
  vtkSetMacro(EulerNeutralCollapses, bool);
  vtkGetMacro(EulerNeutralCollapses, bool);
  vtkBooleanMacro(EulerNeutralCollapses, bool);
  ///@}

  ///@{
  /// Edges whose stability ratio is below this (default 0.1) are spikes:
  /// they merge into their bigger ball instead of the SQE minimiser, which
  /// is ill-defined along a spike. 0 follows the paper.
  vtkSetClampMacro(SpikeRatio, double, 0.0, 1.0);
  vtkGetMacro(SpikeRatio, double);
  ///@}

protected:
  vtkQMatSimplifier();
  ~vtkQMatSimplifier() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType TargetNumberOfVertices = 1000;
  double MaximumCost = VTK_DOUBLE_MAX;
  double K = 1e-5;
  double BoundaryWeight = 0.1;
  vtkIdType TopologyGuardVertexCount = 200;
  bool StrictTopologyGuard = false;
  bool PreventFolds = true;
  bool EulerNeutralCollapses = true;
  double SpikeRatio = 0.1;

private:
  vtkQMatSimplifier(const vtkQMatSimplifier&) = delete;
  void operator=(const vtkQMatSimplifier&) = delete;
};

#endif
