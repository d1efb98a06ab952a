// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMedialSkeletalDiagram
 * @brief   A sparse skeleton of a shape with a generalized primitive per element
 *
 * The Medial Skeletal Diagram (Guo et al.) stands for a shape by a few dozen
 * skeletal vertices, edges and triangles, each carrying a generalized
 * enveloping primitive (a radius per direction; see
 * vtkGeneralizedPrimitiveFitter). This filter builds one from the shape's
 * simplified medial mesh: sites are chosen among its vertices (the largest
 * sphere, then InitialSites - 1 more by farthest-point selection along its
 * edges), the skeleton is the dual of their Voronoi cells on the medial mesh
 * (a skeletal vertex per site, an edge where two cells meet along a medial
 * edge, a triangle where three meet on a medial triangle), a primitive is
 * fitted to every element, and a site is added where the surface lies
 * farthest from the primitives' union, until every surface point is within
 * MaximumError (fraction of the bounding-box diagonal) of it or one more
 * site would take the diagram past MaximumElements. Sites are medial
 * vertices inside the surface. An edge whose straight chord would leave the
 * surface (sites on either side of a bend or a concave part) is routed
 * inside it along the medial mesh, bending at medial vertices (the paper
 * subdivides such edges); its primitive is one piece per straight part. A
 * triangle whose flat face would leave the surface is left out (its sides
 * stay). The paper's global optimisation of the sites and its exact
 * refinement are not done.
 *
 * Inputs: port 0 the closed surface; port 1 its simplified medial mesh
 * (point data `Radius`), e.g. vtkStructuralMedialAxis with a few hundred
 * spheres.
 *
 * Output 0: the skeleton: its vertices, then the bends of its edges (point
 * data `MedialVertexId`, `Radius`: the medial sphere's), a polyline per
 * edge (through its bends), triangles; field data `Vertices` (how many of
 * the points are skeletal vertices), `Error` and `MeanError` (surface to
 * primitives, fractions of the diagonal), `Insertions`, `FailedElements`
 * (elements with a piece outside the surface and so without a primitive),
 * `OmittedTriangles` (triangles of the dual left out) and
 * `ContinuousParameters` (the paper's N_c: the radii of all primitives
 * plus three coordinates per skeletal vertex and bend). Output 1: the
 * primitives as vtkGeneralizedPrimitiveFitter gives them, one partitioned
 * dataset per element (vertices, then edges, then triangles in the order
 * of output 0's vertices and cells; a bent edge's is one closed shell per
 * straight piece).
 *
 * Output 2 (when Reconstruct is on): the union of the primitives as one
 * closed, outward triangle surface: the zero level set of
 * F(x) = min over primitives of their signed distances, sampled on a grid
 * in a narrow band around it and contoured (as vtkSlabReconstructor's
 * boundary mode does for a medial mesh). The grid spacing is the longest
 * side of the union's bounding box divided by ReconstructionResolution;
 * field data `GridSpacing`. Connect it to port 1 of
 * vtkMedialReconstructionError to measure it against the surface.
 */
#ifndef vtkMedialSkeletalDiagram_h
#define vtkMedialSkeletalDiagram_h

#include "vtkAlgorithm.h"
#include "vtkMedialAxisFiltersModule.h"

class vtkPartitionedDataSetCollection;
class vtkPolyData;

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialSkeletalDiagram : public vtkAlgorithm
{
public:
  static vtkMedialSkeletalDiagram* New();
  vtkTypeMacro(vtkMedialSkeletalDiagram, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The simplified medial mesh of the surface on port 0.
  void SetMedialAxisConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  vtkPolyData* GetSkeleton();
  vtkPartitionedDataSetCollection* GetPrimitives();
  vtkPolyData* GetReconstruction();

  ///@{
  /// Largest distance of the surface from the primitives' union, as a
  /// fraction of the bounding-box diagonal. Default 0.005.
  vtkSetClampMacro(MaximumError, double, 1e-5, 1.0);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /// Most elements (vertices + edges + triangles). Default 100.
  vtkSetClampMacro(MaximumElements, int, 1, 1000000);
  vtkGetMacro(MaximumElements, int);
  ///@}

  ///@{
  /// Sites to start from. Default 1.
  vtkSetClampMacro(InitialSites, int, 1, 100000);
  vtkGetMacro(InitialSites, int);
  ///@}

  ///@{
  /// Template resolutions, as for vtkGeneralizedPrimitiveFitter: directions
  /// round a circle (32), the vertex template's subdivisions (3) and the
  /// spacing of base points as a fraction of the diagonal (0.02).
  vtkSetClampMacro(AngularResolution, int, 8, 256);
  vtkGetMacro(AngularResolution, int);
  vtkSetClampMacro(VertexSubdivisions, int, 0, 6);
  vtkGetMacro(VertexSubdivisions, int);
  vtkSetClampMacro(Spacing, double, 1e-4, 1.0);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /// Whether each primitive's radius in a direction is where its ray leaves
  /// the surface, with the template refined where the surface lies between
  /// directions (default on: the closest union), or the smooth fit of
  /// vtkGeneralizedPrimitiveFitter (off: the paper's, which stops short of
  /// the surface wherever the radii vary).
  vtkSetMacro(ExactRadii, vtkTypeBool);
  vtkGetMacro(ExactRadii, vtkTypeBool);
  vtkBooleanMacro(ExactRadii, vtkTypeBool);
  ///@}

  ///@{
  /// Whether output 2 gets the union of the primitives as one closed
  /// surface (default on), and the grid resolution it is contoured at:
  /// cells along the longest side of the union's bounding box (default
  /// 128; features thinner than about one cell are lost).
  vtkSetMacro(Reconstruct, vtkTypeBool);
  vtkGetMacro(Reconstruct, vtkTypeBool);
  vtkBooleanMacro(Reconstruct, vtkTypeBool);
  vtkSetClampMacro(ReconstructionResolution, int, 8, 1024);
  vtkGetMacro(ReconstructionResolution, int);
  ///@}

  ///@{
  /// The last run: the error reached (fraction of the diagonal) and the
  /// number of elements.
  vtkGetMacro(ReachedError, double);
  vtkGetMacro(NumberOfElements, vtkIdType);
  ///@}

  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkMedialSkeletalDiagram();
  ~vtkMedialSkeletalDiagram() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  double MaximumError = 0.005;
  int MaximumElements = 100;
  int InitialSites = 1;
  int AngularResolution = 32;
  int VertexSubdivisions = 3;
  double Spacing = 0.02;
  vtkTypeBool ExactRadii = true;
  vtkTypeBool Reconstruct = true;
  int ReconstructionResolution = 128;
  double ReachedError = 0.0;
  vtkIdType NumberOfElements = 0;

private:
  vtkMedialSkeletalDiagram(const vtkMedialSkeletalDiagram&) = delete;
  void operator=(const vtkMedialSkeletalDiagram&) = delete;
};

#endif
