// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkGeneralizedPrimitiveFitter
 * @brief   Fits a generalized enveloping primitive to each element of a skeleton
 *
 * The Medial Skeletal Diagram (Guo et al., "Medial Skeletal Diagram") stands for
 * a shape by a sparse skeleton whose vertices, edges and triangles each carry
 * a generalized enveloping primitive: a radius per direction instead of one
 * per sphere. This filter fits those primitives to a closed surface.
 *
 * Every point of the skeleton is a vertex element (the sphere of directions:
 * an icosahedron subdivided VertexSubdivisions times), every distinct edge of
 * its lines and triangles an edge element (the circles of directions around
 * it, rings at most Spacing apart, and a hemisphere beyond each end) and every
 * triangle a triangle element (+n and -n over it, a half circle beyond each
 * edge and the wedge of directions at each corner). AngularResolution
 * directions go round a circle. Each direction's radius grows from the
 * element's inscribed distance towards the surface and never past its ray's
 * first exit from it, the radius function kept smooth by the template's graph
 * Laplacian (weight Smoothness), over Progressions steps of growth. Where
 * the surface cuts in between two directions (a narrow gap, a reflex edge)
 * the primitive would pass it there: its template is then split where
 * surface points lie inside the primitive deeper than RefinementTolerance
 * (or the radius between two directions passes the surface by more) and
 * fitted again, a few times. The primitives therefore lie inside the
 * surface (within that tolerance); their union is the shape as far as the
 * skeleton reaches it.
 *
 * Inputs: port 0 the closed surface; port 1 the skeleton (vtkPolyData with
 * vertices, lines and triangles: a simplified medial mesh, a `.ma` file's, or
 * one drawn by hand). Its points must lie inside the surface.
 *
 * Output: a vtkPartitionedDataSetCollection with one partitioned dataset per
 * element (vertices first, in point order, then edges, then triangles in cell
 * order), each holding the primitive's closed triangle mesh with point data
 * `Radius` (per direction) and `MaximumRadius` (where the direction's ray
 * leaves the surface) and field data `ElementType` (0 vertex, 1 edge, 2
 * triangle) and `ElementId` (point id, edge number or triangle cell id); its
 * name says which element it is. An element outside the surface gets an
 * empty primitive and a warning that counts and names them.
 */
#ifndef vtkGeneralizedPrimitiveFitter_h
#define vtkGeneralizedPrimitiveFitter_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPartitionedDataSetCollectionAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkGeneralizedPrimitiveFitter
  : public vtkPartitionedDataSetCollectionAlgorithm
{
public:
  static vtkGeneralizedPrimitiveFitter* New();
  vtkTypeMacro(vtkGeneralizedPrimitiveFitter, vtkPartitionedDataSetCollectionAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The skeleton (port 1).
  void SetSkeletonConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  ///@{
  /// Directions round a circle of the edge and triangle templates. Default 32.
  vtkSetClampMacro(AngularResolution, int, 8, 256);
  vtkGetMacro(AngularResolution, int);
  ///@}

  ///@{
  /// Subdivisions of the icosahedron of a vertex element's directions
  /// (10 * 4^s + 2 directions). Default 3 (642).
  vtkSetClampMacro(VertexSubdivisions, int, 0, 6);
  vtkGetMacro(VertexSubdivisions, int);
  ///@}

  ///@{
  /// Largest spacing of the templates' base points along edges and over
  /// triangles, as a fraction of the surface's bounding-box diagonal.
  /// Default 0.02.
  vtkSetClampMacro(Spacing, double, 1e-4, 1.0);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /// Weight of the smoothness of the radius function against the growth
  /// towards the surface. Default 1 (0: each direction on its own).
  vtkSetClampMacro(Smoothness, double, 0.0, 1e6);
  vtkGetMacro(Smoothness, double);
  ///@}

  ///@{
  /// Steps of growth towards the surface, each by a tenth of the direction's
  /// distance to it. Default 20.
  vtkSetClampMacro(Progressions, int, 1, 1000);
  vtkGetMacro(Progressions, int);
  ///@}

  ///@{
  /// How far, as a fraction of the surface's bounding-box diagonal, a
  /// primitive may pass the surface between its directions before its
  /// template is refined there (default 0.0025; 0: never refine).
  vtkSetClampMacro(RefinementTolerance, double, 0.0, 1.0);
  vtkGetMacro(RefinementTolerance, double);
  ///@}

  ///@{
  /// Each direction's radius set to where its ray leaves the surface, with
  /// no smoothing (Smoothness and Progressions unused), and the template
  /// refined also where the primitive stops short of the surface between
  /// directions by more than RefinementTolerance. Default off (the paper's
  /// smooth fit); vtkMedialSkeletalDiagram uses it by default.
  vtkSetMacro(ExactRadii, vtkTypeBool);
  vtkGetMacro(ExactRadii, vtkTypeBool);
  vtkBooleanMacro(ExactRadii, vtkTypeBool);
  ///@}

  ///@{
  /// Elements whose primitive could not be fitted (outside the surface) in
  /// the last run.
  vtkGetMacro(NumberOfFailedElements, vtkIdType);
  ///@}

protected:
  vtkGeneralizedPrimitiveFitter();
  ~vtkGeneralizedPrimitiveFitter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int AngularResolution = 32;
  int VertexSubdivisions = 3;
  double Spacing = 0.02;
  double Smoothness = 1.0;
  int Progressions = 20;
  double RefinementTolerance = 0.0025;
  vtkTypeBool ExactRadii = false;
  vtkIdType NumberOfFailedElements = 0;

private:
  vtkGeneralizedPrimitiveFitter(const vtkGeneralizedPrimitiveFitter&) = delete;
  void operator=(const vtkGeneralizedPrimitiveFitter&) = delete;
};

#endif
