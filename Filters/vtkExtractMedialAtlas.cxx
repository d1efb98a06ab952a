// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkExtractMedialAtlas.h"

#include "vtkMedialMeshConversion.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMergePoints.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkExtractMedialAtlas);

vtkExtractMedialAtlas::vtkExtractMedialAtlas()
{
  this->SetNumberOfInputPorts(2);
}

int vtkExtractMedialAtlas::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkExtractMedialAtlas::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* mat = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* rvd = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  if (!mat || !rvd)
  {
    vtkErrorMacro(<< "needs the medial mesh on input port 0 and the restricted Voronoi diagram "
                     "on input port 1");
    return 0;
  }
  std::vector<medialaxis::Index> offsets, sites;
  const std::string problem = medialaxis::GetAtlasArrays(mat, offsets, sites);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "input port 0: " << problem);
    return 0;
  }
  const vtkIdType nv = mat->GetNumberOfPoints();
  if (this->MedialVertexId >= nv)
  {
    vtkErrorMacro(<< "MedialVertexId " << this->MedialVertexId
                  << " is not a vertex of the medial mesh (it has " << nv
                  << " vertices: use an id from 0 to " << nv - 1 << ")");
    return 0;
  }
  vtkDataArray* siteIds = rvd->GetCellData()->GetArray("SiteId");
  if (!siteIds)
  {
    vtkErrorMacro(<< "input port 1 has no cell data 'SiteId': connect the restricted Voronoi "
                     "diagram (output 0 of vtkRestrictedVoronoiDiagram)");
    return 0;
  }

  std::vector<medialaxis::Index> atlas(sites.begin() + offsets[this->MedialVertexId],
    sites.begin() + offsets[this->MedialVertexId + 1]);
  std::sort(atlas.begin(), atlas.end());
  vtkNew<vtkIdList> cells;
  const vtkIdType nc = rvd->GetNumberOfCells();
  for (vtkIdType c = 0; c < nc; ++c)
  {
    const auto site = static_cast<medialaxis::Index>(siteIds->GetComponent(c, 0));
    if (std::binary_search(atlas.begin(), atlas.end(), site))
    {
      cells->InsertNextId(c);
    }
    if (c % 65536 == 0)
    {
      this->UpdateProgress(static_cast<double>(c) / static_cast<double>(nc));
      if (this->GetAbortExecute())
      {
        return 1;
      }
    }
  }
  // Points shared by neighbouring polygons stay shared (merged by locator).
  vtkNew<vtkPoints> points;
  if (rvd->GetPoints())
  {
    points->SetDataType(rvd->GetPoints()->GetDataType()); // keep double precision
  }
  vtkNew<vtkMergePoints> locator;
  locator->InitPointInsertion(points, rvd->GetBounds());
  output->SetPoints(points);
  output->AllocateEstimate(cells->GetNumberOfIds(), 8);
  output->GetPointData()->CopyAllocate(rvd->GetPointData());
  output->GetCellData()->CopyAllocate(rvd->GetCellData());
  output->CopyCells(rvd, cells, locator);
  output->Squeeze();

  // Area by Newell's formula: robust where a tiny polygon repeats a point
  // (vtkPolygon::ComputeArea gives NaN there).
  double area = 0.0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    output->GetCellPoints(c, ids);
    double twice[3] = { 0.0, 0.0, 0.0 }, p[3], q[3];
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      output->GetPoint(ids->GetId(k), p);
      output->GetPoint(ids->GetId((k + 1) % ids->GetNumberOfIds()), q);
      twice[0] += p[1] * q[2] - p[2] * q[1];
      twice[1] += p[2] * q[0] - p[0] * q[2];
      twice[2] += p[0] * q[1] - p[1] * q[0];
    }
    area += 0.5 * std::sqrt(twice[0] * twice[0] + twice[1] * twice[1] + twice[2] * twice[2]);
  }
  medialaxis::AddFieldValue(output, "MedialVertexId", this->MedialVertexId);
  vtkNew<vtkDoubleArray> center, radius, areaArray;
  center->SetName("SphereCenter");
  center->SetNumberOfComponents(3);
  center->InsertNextTuple(mat->GetPoint(this->MedialVertexId));
  radius->SetName("SphereRadius");
  vtkDataArray* radii = mat->GetPointData()->GetArray(medialaxis::RadiusArrayName);
  radius->InsertNextValue(radii ? radii->GetComponent(this->MedialVertexId, 0) : 0.0);
  areaArray->SetName("AtlasArea");
  areaArray->InsertNextValue(area);
  output->GetFieldData()->AddArray(center);
  output->GetFieldData()->AddArray(radius);
  output->GetFieldData()->AddArray(areaArray);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkExtractMedialAtlas::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MedialVertexId: " << this->MedialVertexId << "\n";
}
