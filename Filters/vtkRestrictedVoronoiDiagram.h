// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkRestrictedVoronoiDiagram
 * @brief   Splits a surface into the cells of sites' 3D Voronoi diagram.
 *
 * Input port 0: the surface (prepared like in every MedialAxis filter).
 * Input port 1: the sites, e.g. from vtkBlueNoiseSurfaceSampler.
 *
 * Output port 0, the restricted Voronoi diagram (RVD): convex polygons, each
 * the intersection of one surface triangle with one site's Euclidean 3D
 * Voronoi cell, computed by exact clipping with bisector planes; cell data
 * `SiteId` and `TriangleId`. A site's restricted cell can have several
 * disconnected pieces (both sides of a thin wall): all are found. Its field
 * data repeats the per-site values later stages need: `SitePositions`,
 * `SiteConvexFeature` and `SiteConcaveFeature`.
 *
 * Output port 1, the sites with their point data plus, per site:
 * `CellArea` (area of its restricted cell), `CellRadius` (the distance
 * from the site to the farthest point of its cell: every surface point lies
 * within the largest CellRadius of a site), `CellCentroid`,
 * `ConvexFeature` / `ConcaveFeature` (1 when the cell crosses a sharp convex
 * edge, dihedral angle below 180° - FeatureAngle, or a sharp concave edge,
 * above 180° + FeatureAngle; convex edges are confirmed by filtered normals,
 * see FeatureNormalFiltering) and `CellComponents` (its number of pieces).
 *
 * Parallel, and identical whatever NumberOfThreads.
 */
#ifndef vtkRestrictedVoronoiDiagram_h
#define vtkRestrictedVoronoiDiagram_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkRestrictedVoronoiDiagram : public vtkPolyDataAlgorithm
{
public:
  static vtkRestrictedVoronoiDiagram* New();
  vtkTypeMacro(vtkRestrictedVoronoiDiagram, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Convenience: the sites (input port 1).
  void SetSourceConnection(vtkAlgorithmOutput* sites) { this->SetInputConnection(1, sites); }

  ///@{
  /// Tolerance phi of the sharp-edge test, in degrees (default 45): an edge
  /// is a convex feature when its dihedral angle is below 180 - phi, a
  /// concave one when above 180 + phi.
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
  /// Threads to use (0 = all cores, default). Does not change the result.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkRestrictedVoronoiDiagram();
  ~vtkRestrictedVoronoiDiagram() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double FeatureAngle = 45.0;
  int FeatureNormalFiltering = 3;
  int NumberOfThreads = 0;

private:
  vtkRestrictedVoronoiDiagram(const vtkRestrictedVoronoiDiagram&) = delete;
  void operator=(const vtkRestrictedVoronoiDiagram&) = delete;
};

#endif
