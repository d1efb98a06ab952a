// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkFilletDetector
 * @brief   Fillet centre lines, radii and fillet faces from a Structural MAT.
 *
 * A fillet is the surface swept by a ball rolling between two faces; its
 * medial axis is the ball's centre line, a boundary of the medial sheet with
 * the fillet radius (paper "Structural MAT", section 5.7). This filter finds
 * those centre lines on a simplified medial mesh (vtkAtlasMedialAxisSimplifier,
 * with feature preservation on for CAD parts) and marks the fillet faces of
 * the surface, constant- and variable-radius fillets alike.
 *
 * Method: a medial boundary edge (an edge of exactly one medial triangle) is a
 * centre-line edge when, among the surface triangles its two spheres
 * correspond to (their Atlas), at least MinimumConsistentFraction of the area
 * within the edge's span lies on the edge's envelope: at a distance within
 * RadiusTolerance times the local radius, with a normal within
 * NormalTolerance of the envelope's, wrapping an arc of at least
 * MinimumArcAngle around it. Edges with a radius below MinimumRadius
 * (sharp edges, radius 0) are no fillet. Accepted edges are chained into
 * polylines (small cycles opened, short spurs pruned, small gaps bridged),
 * split where three or more meet or where the line turns by more than
 * SplitAngle; polylines shorter than MinimumLength are dropped. The fillet
 * faces of each polyline are grown over the surface from its Atlas through
 * the triangles whose corners all lie on its envelope (the ball rolls on up
 * to one radius past a polyline's end, e.g. to a sharp edge); each vertex of
 * the polyline is then moved to the centre of the circle fitted to the
 * fillet's cross-section there, and the faces are grown again along the
 * refined line, their corners within FaceTolerance of its envelope and
 * within its arc (where the ball leaves the surface the faces end, though the
 * flat face beyond stays near the envelope for a while). A polyline whose
 * faces wrap more than five eighths of the ball's circle goes round a tube
 * (a handle, a pipe), not a fillet (a ball between two faces touches at most
 * half of it), and is dropped.
 *
 * Inputs: port 0 the medial mesh with its Atlas (field data `AtlasSites` /
 * `AtlasOffsets`, point data `Radius`; where it also has `PlacedRadius`, the
 * radii the collapses placed before the final fit changed those on the
 * sheets' boundary, the rolling balls are taken from it); port 1 the restricted Voronoi diagram
 * of the same sites (cell data `SiteId` and `TriangleId`: output 0 of
 * vtkRestrictedVoronoiDiagram or output 1 of the simplifier); port 2 the
 * surface the diagram was computed on.
 *
 * Output 0: the centre lines, one polyline per fillet (a closed fillet
 * repeats its first point) through the refined ball centres, with point
 * data `Radius` (refined) and `MedialVertexId` (the medial vertex refined)
 * and cell data `FilletId`, `MeanRadius` (length-weighted), `MinimumRadius`,
 * `MaximumRadius`, `RadiusVariation` ((max - min) / mean: 0 for a
 * constant-radius fillet), `Length`, `SurfaceArea` (of its faces) and
 * `ArcAngle` (degrees of the ball's circle its faces cover: 180 minus the
 * angle between the faces it blends, 90 on a right-angled edge). `FilletId`
 * is the active scalars (ParaView colours the lines by fillet on Apply).
 * Output 1: the surface (as prepared for the pipeline: same triangles as the
 * diagram refers to) with cell data `FilletId` (-1 on no fillet). Both
 * outputs carry field data `NumberOfFillets`, `BoundaryEdges` and
 * `CentreLineEdges`.
 */
#ifndef vtkFilletDetector_h
#define vtkFilletDetector_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkFilletDetector : public vtkPolyDataAlgorithm
{
public:
  static vtkFilletDetector* New();
  vtkTypeMacro(vtkFilletDetector, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// How far (as a fraction of the local ball radius) a surface point may lie
  /// from the centre line's envelope and still be on the fillet. Default 0.05.
  vtkSetClampMacro(RadiusTolerance, double, 1e-4, 1.0);
  vtkGetMacro(RadiusTolerance, double);
  ///@}

  ///@{
  /// How far (as a fraction of the local radius) a surface vertex may lie
  /// from the refined centre line's envelope and still be on a fillet face.
  /// Default 0.02.
  vtkSetClampMacro(FaceTolerance, double, 1e-4, 1.0);
  vtkGetMacro(FaceTolerance, double);
  ///@}

  ///@{
  /// Largest angle in degrees between a fillet triangle's normal and the
  /// envelope's normal. Default 30.
  vtkSetClampMacro(NormalTolerance, double, 0.0, 90.0);
  vtkGetMacro(NormalTolerance, double);
  ///@}

  ///@{
  /// Fraction of the surface a medial boundary edge corresponds to (by area,
  /// within the edge's span) that must lie on its envelope. Default 0.5.
  vtkSetClampMacro(MinimumConsistentFraction, double, 0.0, 1.0);
  vtkGetMacro(MinimumConsistentFraction, double);
  ///@}

  ///@{
  /// Smallest arc in degrees the matching surface must wrap around a
  /// centre-line edge: a rolling ball touches an arc, a ball on an ordinary
  /// sheet boundary touches a flat face. Default 20.
  vtkSetClampMacro(MinimumArcAngle, double, 0.0, 360.0);
  vtkGetMacro(MinimumArcAngle, double);
  ///@}

  ///@{
  /// Smallest fillet radius, in percent of the surface's bounding-box
  /// diagonal: thinner balls sit on sharp edges. Default 0.2 (%).
  vtkSetClampMacro(MinimumRadius, double, 0.0, 100.0);
  vtkGetMacro(MinimumRadius, double);
  ///@}

  ///@{
  /// Shortest centre line kept, in percent of the surface's bounding-box
  /// diagonal. Default 2 (%).
  vtkSetClampMacro(MinimumLength, double, 0.0, 100.0);
  vtkGetMacro(MinimumLength, double);
  ///@}

  ///@{
  /// A centre line is split into two fillets where it turns by more than this
  /// angle in degrees at a vertex. Default 50.
  vtkSetClampMacro(SplitAngle, double, 0.0, 180.0);
  vtkGetMacro(SplitAngle, double);
  ///@}

protected:
  vtkFilletDetector();
  ~vtkFilletDetector() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double RadiusTolerance = 0.05;
  double FaceTolerance = 0.02;
  double NormalTolerance = 30.0;
  double MinimumConsistentFraction = 0.5;
  double MinimumArcAngle = 20.0;
  double MinimumRadius = 0.2;
  double MinimumLength = 2.0;
  double SplitAngle = 50.0;

private:
  vtkFilletDetector(const vtkFilletDetector&) = delete;
  void operator=(const vtkFilletDetector&) = delete;
};

#endif
