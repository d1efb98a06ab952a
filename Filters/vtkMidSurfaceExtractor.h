// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMidSurfaceExtractor
 * @brief   The mid-surface of a thin-walled part, with its thickness, from the part's medial axis.
 *
 * Input port 0: the closed triangle surface of the part. Input port 1
 * (optional): its medial mesh (point data `Radius`), e.g. output 0 of
 * vtkStructuralMedialAxis; without it the filter computes one with
 * vtkStructuralMedialAxis' CAD preset (50,000 samples -> 5,000 spheres).
 *
 * The medial mesh is split into sheets at its seams (vtkMedialStructure's
 * rules). A sheet is a wall when most of its area lies between two nearly
 * parallel sides of the surface (their normals within
 * MaximumNormalDeviation of opposite: MidSurfer's face pairs, seen from the
 * medial axis) and its thinnest part is no thicker than WallThickness; the
 * other sheets, the branches of the medial axis towards convex edges,
 * corners and rims, are pruned. Then, on the walls:
 * - each vertex between parallel sides moves to the middle of the chord
 *   through it along the wall's normal (point data `Thickness` is the chord);
 * - the vertices of the branches that curve into a junction move onto the
 *   plane of the nearest such vertex of each wall they belong to, where
 *   those planes meet: walls meeting in a T or an L are stitched along the
 *   intersection of their mid-planes;
 * - with ExtendToLateralFaces, the free boundaries are extended along the
 *   mid-surface to the surface (the walls' lateral faces), at most one wall
 *   thickness away.
 *
 * Output: the mid-surface as triangles, consistently oriented within each
 * wall; point data `Thickness` and `MedialVertexId` (-1 on the points added
 * on the lateral faces); cell data `WallId` (triangles joined where the
 * surface bends by less than 30 degrees, and across junctions where one
 * continues another's plane); field data `WallThickness` (the value used),
 * `NumberOfWalls`, `NumberOfWallSheets`, `JunctionEdges` (edges of three or
 * more triangles, where walls meet), `BoundaryEdges`, `FoldedEdges` (edges
 * whose triangles still face opposite ways after the folds of the medial
 * axis' fins are untangled; 0 on a clean result), and per wall
 * `WallArea`, `WallMeanThickness` (area-weighted), `WallMinimumThickness`,
 * `WallMaximumThickness`.
 */
#ifndef vtkMidSurfaceExtractor_h
#define vtkMidSurfaceExtractor_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkMidSurfaceExtractor : public vtkPolyDataAlgorithm
{
public:
  static vtkMidSurfaceExtractor* New();
  vtkTypeMacro(vtkMidSurfaceExtractor, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The optional medial mesh of the surface on port 0.
  void SetMedialAxisConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  ///@{
  /// The thickest wall, in the surface's units: sheets whose thinnest part
  /// (the 5% area quantile of their parallel triangles' thickness) is
  /// thicker are not walls. 0 (default): automatic, as MidSurfer does: the
  /// largest thickness in the fullest bin of the area-weighted thickness
  /// histogram of all parallel medial triangles (bins 5% of the median wide).
  vtkSetClampMacro(WallThickness, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(WallThickness, double);
  ///@}

  ///@{
  /// Largest angle, in degrees, between one side's normal and the opposite
  /// of the other side's for a medial triangle to lie between parallel
  /// sides. Default 15 (MidSurfer's industrial default); a tapered wall
  /// needs at least its taper angle.
  vtkSetClampMacro(MaximumNormalDeviation, double, 0.5, 90.0);
  vtkGetMacro(MaximumNormalDeviation, double);
  ///@}

  ///@{
  /// Share of a sheet's area that must lie between parallel sides for the
  /// sheet to be a wall. Default 0.5.
  vtkSetClampMacro(MinimumParallelFraction, double, 0.0, 1.0);
  vtkGetMacro(MinimumParallelFraction, double);
  ///@}

  ///@{
  /// Extend the free boundaries along the mid-surface to the walls' lateral
  /// faces. Default on.
  vtkSetMacro(ExtendToLateralFaces, bool);
  vtkGetMacro(ExtendToLateralFaces, bool);
  vtkBooleanMacro(ExtendToLateralFaces, bool);
  ///@}

  ///@{
  /// Results of the last update: the wall thickness used, the walls, the
  /// medial sheets kept, and the edges where walls meet.
  vtkGetMacro(EstimatedWallThickness, double);
  vtkGetMacro(NumberOfWalls, vtkIdType);
  vtkGetMacro(NumberOfWallSheets, vtkIdType);
  vtkGetMacro(NumberOfJunctionEdges, vtkIdType);
  ///@}

protected:
  vtkMidSurfaceExtractor();
  ~vtkMidSurfaceExtractor() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double WallThickness = 0.0;
  double MaximumNormalDeviation = 15.0;
  double MinimumParallelFraction = 0.5;
  bool ExtendToLateralFaces = true;
  double EstimatedWallThickness = 0.0;
  vtkIdType NumberOfWalls = 0;
  vtkIdType NumberOfWallSheets = 0;
  vtkIdType NumberOfJunctionEdges = 0;

private:
  vtkMidSurfaceExtractor(const vtkMidSurfaceExtractor&) = delete;
  void operator=(const vtkMidSurfaceExtractor&) = delete;
};

#endif
