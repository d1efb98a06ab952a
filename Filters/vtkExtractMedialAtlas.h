// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkExtractMedialAtlas
 * @brief   The surface cells one medial sphere stands for: its whole Atlas.
 *
 * Every vertex of a Structural MAT corresponds to a set of surface cells,
 * its Atlas (paper "Structural MAT", section 4.2). This filter shows the
 * Atlas of one picked vertex: the polygons of the restricted Voronoi
 * diagram whose site belongs to it.
 *
 * Input port 0: a medial mesh with its Atlas (field data `AtlasSites` /
 * `AtlasOffsets`, as written by vtkVoronoiMedialAxis and
 * vtkAtlasMedialAxisSimplifier). Input port 1: the restricted Voronoi
 * diagram of the same sites (cell data `SiteId`; output 0 of
 * vtkRestrictedVoronoiDiagram or output 1 of the simplifier).
 *
 * Output: those polygons, with their point and cell data, and field data
 * `MedialVertexId`, `SphereCenter`, `SphereRadius` and `AtlasArea` (the
 * polygons' total area). In ParaView, read the point id of a sphere with
 * Hover Points On or the spreadsheet view and enter it as MedialVertexId.
 * An id outside the medial mesh is an error (empty output).
 */
#ifndef vtkExtractMedialAtlas_h
#define vtkExtractMedialAtlas_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkExtractMedialAtlas : public vtkPolyDataAlgorithm
{
public:
  static vtkExtractMedialAtlas* New();
  vtkTypeMacro(vtkExtractMedialAtlas, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Point id of the medial vertex whose Atlas is extracted (default 0).
  vtkSetClampMacro(MedialVertexId, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MedialVertexId, vtkIdType);
  ///@}

protected:
  vtkExtractMedialAtlas();
  ~vtkExtractMedialAtlas() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType MedialVertexId = 0;

private:
  vtkExtractMedialAtlas(const vtkExtractMedialAtlas&) = delete;
  void operator=(const vtkExtractMedialAtlas&) = delete;
};

#endif
