// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMedialCurveSkeleton
 * @brief   A curve skeleton: centre lines with radii and one loop per handle
 *
 * Thins the medial mesh of a closed surface to a graph of centre lines.
 * Edges of medial triangles are contracted, shortest first, wherever the
 * link condition holds, and triangles with a free edge are collapsed, both
 * of which keep the homotopy type: when the medial mesh has the solid's
 * topology, the skeleton has one loop per handle of the solid (its cycle
 * rank is the genus). A node stands at the centroid of the medial vertices
 * it gathered, weighted by their balls' volumes (inside the solid; where
 * that centroid is not, at the nearest of them). Branches from a free end
 * to a junction whose medial balls all lie in medial balls of the rest,
 * grown by PruneScale, are pruned: they stand for bumps, corners and rims of
 * the surface, not limbs. Nodes inside branches are smoothed without
 * leaving the solid, edges longer than NodeSpacing times the local radius
 * are split, and each node's radius is its distance to the surface (the
 * largest ball centred there inside the solid).
 *
 * Inputs: port 0 the closed surface; port 1 its medial mesh (point data
 * `Radius`), e.g. vtkStructuralMedialAxis's output.
 *
 * Output 0: the skeleton: its nodes with point data `Radius`, `NodeType`
 * (0 end, 1 regular, 2 junction) and `BranchId` (a junction's longest
 * branch); a polyline per branch, from an end or junction to the next (a
 * loop through no junction starts and ends at its lowest node), with cell
 * data `BranchId` and `Length`; a vertex cell for a skeleton of one node.
 * Field data: `Nodes`, `Branches`, `Junctions`, `Ends`, `CycleRank` (loops),
 * `Components`, `PrunedBranches`, `UncollapsedTriangles` (triangles of a
 * void of the medial mesh, which no homotopy-preserving step removes: 0
 * for the medial axis of a solid; a warning otherwise).
 *
 * Output 1: the surface (as prepared: closed, outward) with point data
 * `NodeId`, the node whose ball (radius `Radius`) comes nearest to each
 * point (the nodes' correspondence), and `BranchId`, that node's branch: a
 * segmentation of the surface into parts.
 *
 * vtkCurveSkeletonWriter writes output 0 as SWC or JSON.
 */
#ifndef vtkMedialCurveSkeleton_h
#define vtkMedialCurveSkeleton_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialCurveSkeleton : public vtkPolyDataAlgorithm
{
public:
  static vtkMedialCurveSkeleton* New();
  vtkTypeMacro(vtkMedialCurveSkeleton, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The medial mesh of the surface on port 0.
  void SetMedialAxisConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  ///@{
  /// A branch from a free end to a junction is pruned when each of its
  /// medial balls lies inside a medial ball of the rest of the skeleton
  /// grown by this factor: features smaller than (PruneScale - 1) times the
  /// local radius go. Default 1.5; 1 prunes only branches inside the rest.
  vtkSetClampMacro(PruneScale, double, 1.0, 10.0);
  vtkGetMacro(PruneScale, double);
  ///@}

  ///@{
  /// Passes of Laplacian smoothing over the nodes inside branches (each
  /// moves half way to its neighbours' mean unless that leaves the solid).
  /// Default 10; 0 leaves the nodes at their medial centroids.
  vtkSetClampMacro(SmoothingIterations, int, 0, 1000);
  vtkGetMacro(SmoothingIterations, int);
  ///@}

  ///@{
  /// Edges longer than this times the larger distance to the surface at
  /// their ends (and than 1% of the diagonal) are split evenly (where the
  /// new nodes lie inside the solid),
  /// so that each node's share of the surface is local. Default 1; 0 keeps
  /// only the nodes the thinning left.
  vtkSetClampMacro(NodeSpacing, double, 0.0, 100.0);
  vtkGetMacro(NodeSpacing, double);
  ///@}

  /// The skeleton (output 0) and the segmented surface (output 1).
  vtkPolyData* GetSkeleton() { return this->GetOutput(0); }
  vtkPolyData* GetSegmentation() { return this->GetOutput(1); }

protected:
  vtkMedialCurveSkeleton();
  ~vtkMedialCurveSkeleton() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double PruneScale = 1.5;
  int SmoothingIterations = 10;
  double NodeSpacing = 1.0;

private:
  vtkMedialCurveSkeleton(const vtkMedialCurveSkeleton&) = delete;
  void operator=(const vtkMedialCurveSkeleton&) = delete;
};

#endif
