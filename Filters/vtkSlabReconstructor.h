// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkSlabReconstructor
 * @brief   The envelope of a medial mesh as a triangle surface.
 *
 * Input: a medial mesh (points with point data `Radius`; triangles, lines,
 * vertices; see docs/architecture.md). The envelope is the union of the primitives:
 * a ball at every vertex, on every edge (face edges included) the medial cone
 * (the convex hull of its two balls, bounded by the cone tangent to both), and
 * on every triangle the medial slab (the convex hull of its three balls,
 * bounded by the two planes tangent to all three).
 *
 * Mode "primitives" (default, fast): every primitive surface on its own, a UV
 * sphere per ball, the tangent band of every cone and the two tangent
 * triangles of every slab. They overlap and pass through each other (like the
 * Blender MAT add-on's display); render semi-transparent or with the input.
 *
 * Mode "boundary": only the outer boundary of the union, a closed surface
 * without interior parts (cavities of the union included as inner shells).
 * The union's signed distance F = min over primitive signed distances is
 * sampled on a regular grid, exactly near the boundary (the grid sampling
 * skips 8^3 blocks that F's Lipschitz bound proves far from it), and its zero
 * level set, which is exactly the union's boundary, is contoured with
 * vtkFlyingEdges3D. The grid spacing is the longest side of the union's
 * bounding box divided by BoundaryResolution: parts thinner than about one
 * spacing (balls of radius below half a spacing) can be lost or pinched;
 * field data `GridSpacing` and `ThinVertices` (vertices whose radius is
 * below a spacing) tell how fine the grid was relative to the radii.
 *
 * Degenerate primitives: a zero-radius ball has no surface; a cone whose
 * balls are nested (one inside the other, which includes zero-length edges)
 * is its bigger ball; a cone end of zero radius is an apex; a slab without
 * real tangent planes (collinear centres, or radii varying faster than the
 * centres) is the union of its edge cones.
 *
 * Output: triangles with cell data `PrimitiveKind` (0 = vertex ball, 1 = edge
 * cone, 2 = face slab), `PrimitiveId` (the vertex id, the edge's index in the
 * sorted list of all distinct edges, or the triangle's index among the input's
 * triangles) and `PrimitiveVertices` (the medial vertex ids of the primitive,
 * -1 padded). In boundary mode a triangle belongs to the primitive nearest to
 * its centroid, a ball when it lies on a cone's end cap.
 */
#ifndef vtkSlabReconstructor_h
#define vtkSlabReconstructor_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkSlabReconstructor : public vtkPolyDataAlgorithm
{
public:
  static vtkSlabReconstructor* New();
  vtkTypeMacro(vtkSlabReconstructor, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    PRIMITIVES = 0,
    BOUNDARY = 1
  };

  ///@{
  /// PRIMITIVES (0, default): all primitive surfaces, overlapping.
  /// BOUNDARY (1): the closed outer boundary of their union.
  vtkSetClampMacro(Mode, int, PRIMITIVES, BOUNDARY);
  vtkGetMacro(Mode, int);
  void SetModeToPrimitives() { this->SetMode(PRIMITIVES); }
  void SetModeToBoundary() { this->SetMode(BOUNDARY); }
  const char* GetModeAsString();
  ///@}

  ///@{
  /// Segments around a ball's equator in primitives mode (default 16; the
  /// ball has half as many latitude bands).
  vtkSetClampMacro(SphereResolution, int, 4, 1024);
  vtkGetMacro(SphereResolution, int);
  ///@}

  ///@{
  /// Segments around a cone in primitives mode (default 16).
  vtkSetClampMacro(ConeResolution, int, 3, 1024);
  vtkGetMacro(ConeResolution, int);
  ///@}

  ///@{
  /// Boundary mode: grid cells along the longest side of the envelope's
  /// bounding box (default 128; memory grows with its cube: 512 needs about
  /// 0.5 GB). Raise it when the radii are small compared with the model.
  vtkSetClampMacro(BoundaryResolution, int, 8, 512);
  vtkGetMacro(BoundaryResolution, int);
  ///@}

  ///@{
  /// Threads to use (0 = all cores, default). Does not change the result.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkSlabReconstructor() = default;
  ~vtkSlabReconstructor() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = PRIMITIVES;
  int SphereResolution = 16;
  int ConeResolution = 16;
  int BoundaryResolution = 128;
  int NumberOfThreads = 0;

private:
  vtkSlabReconstructor(const vtkSlabReconstructor&) = delete;
  void operator=(const vtkSlabReconstructor&) = delete;
};

#endif
