// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMedialStructure
 * @brief   Sheets, seams, junctions, rims, features and fillets of a medial mesh, as data.
 *
 * Input port 0: a medial mesh (point data `Radius`; triangles and lines), e.g.
 * the output of vtkStructuralMedialAxis or vtkAtlasMedialAxisSimplifier.
 * Where it has point data `FeatureVertex` (the simplifier's, with feature
 * preservation on), that marks the feature vertices; otherwise a radius of 0
 * does. Input port 1 (optional): fillet centre lines (output 0 of
 * vtkFilletDetector, point data `MedialVertexId`), whose vertices are fillet
 * vertices. Input port 2 (optional): the restricted Voronoi cells of the
 * sites (output 1 of vtkAtlasMedialAxisSimplifier, cell data `SiteId`); with
 * them and the mesh's Atlas (field data `AtlasSites` / `AtlasOffsets`), each
 * vertex's tangent components are counted as MATFP counts them: the
 * connected pieces of its Atlas' cells, one per side of the surface its ball
 * touches.
 *
 * Rules, per vertex, the first that holds: on no edge and no triangle:
 * isolated (7); a feature vertex: feature (4); on a fillet centre line:
 * fillet (5); on three or more seam edges, or where an edge of no triangle meets a triangle:
 * junction (2); on a seam edge: seam (1); on edges only: curve (6); on a sheet's free boundary (an
 * edge of one triangle): rim (3); otherwise sheet (0). With ClassifyByTangentComponents, sheet,
 * seam, junction and rim vertices are typed by their tangent components instead: 1 rim, 2 sheet, 3
 * seam, 4 or more junction.
 *
 * Seam edges are edges of three or more triangles of two sheets or more (a
 * sheet meeting only itself there is folded); sheets are triangles joined
 * across edges of two triangles, unless both ends are feature vertices.
 * Sheets smaller than MinimumSheetFraction of the whole join the largest
 * sheet they touch, and their triangles are not counted on edges.
 *
 * Output 0: the input with point data `MedialType` (the numbers above) and,
 * with the cells, `TangentComponents`; cell data `SheetId` (numbered in the
 * order of their first triangle; -1 on lines);
 * field data with one tuple per sheet: `SheetArea`, `SheetMeanRadius`
 * (area-weighted), `SheetMinimumRadius`, `SheetMaximumRadius`,
 * `SheetTriangles`; the counts `NumberOfSheets`, `NumberOfSeams` and
 * `NumberOf<Type>Vertices` for every type; with the cells,
 * `TypeDisagreements` and `TangentComponentAgreement` (the share of sheet,
 * seam, junction and rim vertices both rules type alike).
 * Output 1: the seams, one line cell per seam edge on the same points, with
 * cell data `SeamId` (chains of seam edges through vertices on exactly two
 * of them; junctions end them).
 */
#ifndef vtkMedialStructure_h
#define vtkMedialStructure_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialStructure : public vtkPolyDataAlgorithm
{
public:
  static vtkMedialStructure* New();
  vtkTypeMacro(vtkMedialStructure, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The optional fillet centre lines (output 0 of vtkFilletDetector).
  void SetFilletLinesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  /// The optional restricted Voronoi cells of the Atlas' sites (output 1 of
  /// vtkAtlasMedialAxisSimplifier).
  void SetCellsConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }

  ///@{
  /// Sheets with less than this fraction of the medial mesh's total area
  /// that hang on other sheets (by an edge or a vertex) are flaps, debris of
  /// the discrete mesh along rims and at junctions: they join the largest
  /// sheet they touch, and their triangles make no seam. 0 keeps every
  /// sheet. Default 0.001.
  vtkSetClampMacro(MinimumSheetFraction, double, 0.0, 0.5);
  vtkGetMacro(MinimumSheetFraction, double);
  ///@}

  ///@{
  /// With the cells on port 2: whether the tangent components, rather than
  /// the mesh's edges, tell sheet, seam, junction and rim vertices apart
  /// (MATFP's rule). Default off: the mesh's rule agrees with the sheets and
  /// seams output; the other is then its cross-check.
  vtkSetMacro(ClassifyByTangentComponents, bool);
  vtkGetMacro(ClassifyByTangentComponents, bool);
  vtkBooleanMacro(ClassifyByTangentComponents, bool);
  ///@}

  ///@{
  /// Counts from the last update. TypeDisagreements: sheet, seam, junction
  /// and rim vertices the two rules type differently (0 without cells).
  vtkGetMacro(NumberOfSheets, vtkIdType);
  vtkGetMacro(NumberOfSeams, vtkIdType);
  vtkGetMacro(TypeDisagreements, vtkIdType);
  ///@}
  /// Vertices of a type (0 sheet ... 7 isolated, see the class comment) in
  /// the last update.
  vtkIdType GetNumberOfVerticesOfType(int type) const;

protected:
  vtkMedialStructure();
  ~vtkMedialStructure() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double MinimumSheetFraction = 0.001;
  bool ClassifyByTangentComponents = false;
  vtkIdType NumberOfSheets = 0;
  vtkIdType TypeDisagreements = 0;
  vtkIdType NumberOfSeams = 0;
  vtkIdType TypeCounts[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };

private:
  vtkMedialStructure(const vtkMedialStructure&) = delete;
  void operator=(const vtkMedialStructure&) = delete;
};

#endif
