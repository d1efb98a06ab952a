// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMedialSurfaceValidator
 * @brief   Checks and repairs a surface so that the medial-axis filters can use it.
 *
 * The same preparation runs inside every MedialAxis filter that takes a
 * surface; this filter exposes it on its own so that a user can see what
 * would be repaired or why a mesh is refused.
 *
 * Repairs (each counted): points closer than RelativeMergeTolerance x the
 * bounding-box diagonal are merged (so OBJ triangle soups become closed),
 * polygons and strips are triangulated, triangles with a repeated vertex or
 * zero area and duplicate triangles are dropped, inconsistently oriented
 * triangles are flipped and shells facing inward are turned outward (a shell
 * nested inside another is a cavity and faces inward).
 *
 * Refusals (output empty, ErrorMessage set, vtkErrorMacro): no triangles,
 * NaN/Inf coordinates, open boundary edges, edges shared by more than two
 * triangles, vertices where separate sheets touch, non-orientable surfaces
 * and surfaces that enclose no volume. Several shells are allowed. Shells
 * that cross each other and a surface that passes through itself are
 * refused too, unless RepairSelfIntersections is on: then the crossings are
 * resolved into the closed outer boundary of the solid they enclose (CGAL's
 * autorefinement, the parts inside removed), which is prepared and output,
 * with a note of the pairs resolved and the area removed. Where that gives
 * up (three triangles crossing at one point, common in exported booleans),
 * the surface is wrapped instead (CGAL's alpha wrapping, balls of
 * WrapAlpha times the diagonal): Wrapped is set, RepairDeviation says how
 * far the wrap strays from the input, and a warning says so. A small contact
 * (the crossings within 1% of the diagonal) that cannot be resolved exactly
 * is kept as it is, unless it is a vertex poking through a wall far from it
 * on the surface (a dent's tip through the far side of a thin part): then
 * that vertex is moved back behind the wall, 0.1% of the diagonal clear of
 * it, RepairMethod is "pulled apart", RepairDeviation gives the move and a
 * warning says so.
 *
 * The output's field data carries the counts (arrays named like the getters).
 */
#ifndef vtkMedialSurfaceValidator_h
#define vtkMedialSurfaceValidator_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialSurfaceValidator : public vtkPolyDataAlgorithm
{
public:
  static vtkMedialSurfaceValidator* New();
  vtkTypeMacro(vtkMedialSurfaceValidator, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Points closer than this fraction of the bounding-box diagonal are merged.
  /// 0 merges only exactly coincident points. Default 1e-10.
  vtkSetClampMacro(RelativeMergeTolerance, double, 0.0, 1e-3);
  vtkGetMacro(RelativeMergeTolerance, double);
  ///@}

  ///@{
  /// Flip inconsistent or inward-facing triangles (default on). When off,
  /// such surfaces are refused instead.
  vtkSetMacro(FixOrientation, bool);
  vtkGetMacro(FixOrientation, bool);
  vtkBooleanMacro(FixOrientation, bool);
  ///@}

  ///@{
  /// Resolve crossing shells and a surface passing through itself into the
  /// outer boundary of the solid instead of refusing them. Default off here
  /// (this filter shows what is wrong); on in vtkStructuralMedialAxis and
  /// the command line.
  vtkSetMacro(RepairSelfIntersections, bool);
  vtkGetMacro(RepairSelfIntersections, bool);
  vtkBooleanMacro(RepairSelfIntersections, bool);
  ///@}

  ///@{
  /// The repair's fallback where the crossings cannot be resolved exactly:
  /// wrap the surface with balls of this fraction of the bounding-box
  /// diagonal (details narrower than that are bridged). 0 refuses such a
  /// surface instead. Default 1/150.
  vtkSetClampMacro(WrapAlpha, double, 0.0, 0.1);
  vtkGetMacro(WrapAlpha, double);
  ///@}

  ///@{
  /// How far behind a wall the repair moves a vertex poking through it (a
  /// dent's tip through the far side of a thin part), as a fraction of the
  /// bounding-box diagonal. 0 does not pull such contacts apart: they are
  /// resolved exactly (or refused) as other crossings are. Default 0.001.
  vtkSetClampMacro(ContactGap, double, 0.0, 0.01);
  vtkGetMacro(ContactGap, double);
  ///@}

  /// True when the last update produced a usable surface.
  vtkGetMacro(Valid, bool);
  /// Why the last update refused the surface ("" when valid).
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }
  /// Repairs made by the last update, one per line.
  const char* GetNotes() const { return this->Notes.c_str(); }

  ///@{
  /// Counts from the last update.
  vtkGetMacro(NumberOfMergedPoints, vtkIdType);
  vtkGetMacro(NumberOfDegenerateTriangles, vtkIdType);
  vtkGetMacro(NumberOfDuplicateTriangles, vtkIdType);
  vtkGetMacro(NumberOfBoundaryEdges, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldEdges, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldVertices, vtkIdType);
  vtkGetMacro(NumberOfReorientedTriangles, vtkIdType);
  vtkGetMacro(NumberOfInwardComponents, vtkIdType);
  vtkGetMacro(NumberOfComponents, vtkIdType);
  /// Pairs of triangles of the input that crossed (far apart on the surface
  /// or on separate shells).
  vtkGetMacro(NumberOfCrossingPairs, vtkIdType);
  /// Whether the crossings were repaired, and the input's area removed.
  vtkGetMacro(Repaired, bool);
  vtkGetMacro(RemovedArea, double);
  /// Whether the repair wrapped the surface (the fallback), and the largest
  /// distance from the repaired surface to the input as a fraction of the
  /// bounding-box diagonal (0 when the crossings were resolved).
  vtkGetMacro(Wrapped, bool);
  vtkGetMacro(RepairDeviation, double);
  /// Which repair ran: "resolved crossings", "alpha wrap" or "pulled apart"
  /// (see the class description); empty when none did.
  const char* GetRepairMethod() const { return this->RepairMethod.c_str(); }
  vtkGetMacro(Area, double);
  vtkGetMacro(Volume, double);
  ///@}

protected:
  vtkMedialSurfaceValidator();
  ~vtkMedialSurfaceValidator() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double RelativeMergeTolerance = 1e-10;
  bool FixOrientation = true;
  bool RepairSelfIntersections = false;
  double WrapAlpha = 1.0 / 150.0;
  double ContactGap = 1e-3;

  bool Valid = false;
  bool Repaired = false;
  double RemovedArea = 0.0;
  bool Wrapped = false;
  double RepairDeviation = 0.0;
  std::string RepairMethod;
  vtkIdType NumberOfCrossingPairs = 0;
  std::string ErrorMessage;
  std::string Notes;
  vtkIdType NumberOfMergedPoints = 0;
  vtkIdType NumberOfDegenerateTriangles = 0;
  vtkIdType NumberOfDuplicateTriangles = 0;
  vtkIdType NumberOfBoundaryEdges = 0;
  vtkIdType NumberOfNonManifoldEdges = 0;
  vtkIdType NumberOfNonManifoldVertices = 0;
  vtkIdType NumberOfReorientedTriangles = 0;
  vtkIdType NumberOfInwardComponents = 0;
  vtkIdType NumberOfComponents = 0;
  double Area = 0.0;
  double Volume = 0.0;

private:
  vtkMedialSurfaceValidator(const vtkMedialSurfaceValidator&) = delete;
  void operator=(const vtkMedialSurfaceValidator&) = delete;
};

#endif
