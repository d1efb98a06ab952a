// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkFilletDetector.h"

#include "Fillets/FilletDetector.h"
#include "vtkMedialMeshConversion.h"
#include "vtkSurfacePreparation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkFilletDetector);

namespace
{
constexpr double DegreesToRadians = 3.14159265358979323846 / 180.0;

vtkSmartPointer<vtkDoubleArray> NamedDoubles(const char* name)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  return array;
}

void AddCounts(vtkPolyData* output, const medialaxis::FilletDetectionResult& result)
{
  medialaxis::AddFieldValue(
    output, "NumberOfFillets", static_cast<long long>(result.Fillets.size()));
  medialaxis::AddFieldValue(output, "BoundaryEdges", static_cast<long long>(result.BoundaryEdges));
  medialaxis::AddFieldValue(
    output, "CentreLineEdges", static_cast<long long>(result.CentreLineEdges));
}

// One polyline per fillet over its own copies of the centre points.
void CentreLinesToPolyData(const medialaxis::FilletDetectionResult& result, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  auto radius = NamedDoubles("Radius");
  vtkNew<vtkIdTypeArray> vertexIds;
  vertexIds->SetName("MedialVertexId");
  vtkNew<vtkIntArray> filletIds;
  filletIds->SetName("FilletId");
  auto meanRadius = NamedDoubles("MeanRadius");
  auto minimumRadius = NamedDoubles("MinimumRadius");
  auto maximumRadius = NamedDoubles("MaximumRadius");
  auto variation = NamedDoubles("RadiusVariation");
  auto length = NamedDoubles("Length");
  auto area = NamedDoubles("SurfaceArea");
  auto arc = NamedDoubles("ArcAngle");
  for (std::size_t f = 0; f < result.Fillets.size(); ++f)
  {
    const medialaxis::Fillet& fillet = result.Fillets[f];
    const vtkIdType first = points->GetNumberOfPoints();
    for (std::size_t k = 0; k < fillet.Vertices.size(); ++k)
    {
      points->InsertNextPoint(fillet.Centres[k].data());
      radius->InsertNextValue(fillet.Radii[k]);
      vertexIds->InsertNextValue(static_cast<vtkIdType>(fillet.Vertices[k]));
    }
    const vtkIdType n = static_cast<vtkIdType>(fillet.Vertices.size());
    lines->InsertNextCell(n + (fillet.Closed ? 1 : 0));
    for (vtkIdType k = 0; k < n; ++k)
    {
      lines->InsertCellPoint(first + k);
    }
    if (fillet.Closed)
    {
      lines->InsertCellPoint(first);
    }
    filletIds->InsertNextValue(static_cast<int>(f));
    meanRadius->InsertNextValue(fillet.MeanRadius);
    minimumRadius->InsertNextValue(fillet.MinimumRadius);
    maximumRadius->InsertNextValue(fillet.MaximumRadius);
    variation->InsertNextValue(fillet.RadiusVariation);
    length->InsertNextValue(fillet.Length);
    area->InsertNextValue(fillet.SurfaceArea);
    arc->InsertNextValue(vtkMath::DegreesFromRadians(fillet.ArcAngle));
  }
  output->SetPoints(points);
  output->SetLines(lines);
  // FilletId (cell data) is the only active scalars, so that ParaView
  // colours the centre lines by fillet on Apply.
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->AddArray(vertexIds);
  for (vtkDataArray* array : std::vector<vtkDataArray*>{
         filletIds, meanRadius, minimumRadius, maximumRadius, variation, length, area, arc })
  {
    output->GetCellData()->AddArray(array);
  }
  output->GetCellData()->SetActiveScalars("FilletId");
}
}

vtkFilletDetector::vtkFilletDetector()
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(2);
}

int vtkFilletDetector::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkFilletDetector::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* matIn = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* rvd = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* surfaceIn = vtkPolyData::GetData(inputVector[2]);
  vtkPolyData* lines = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* surfaceOut = vtkPolyData::GetData(outputVector, 1);
  lines->Initialize();
  surfaceOut->Initialize();
  if (!matIn || !rvd || !surfaceIn)
  {
    vtkErrorMacro(<< "needs the medial mesh on input port 0, the restricted Voronoi diagram on "
                     "port 1 and the surface on port 2");
    return 0;
  }
  medialaxis::MedialMesh medial;
  std::vector<medialaxis::Index> atlasOffsets, atlasSites;
  std::string problem = medialaxis::PolyDataToMedialMesh(matIn, medial);
  if (problem.empty())
  {
    problem = medialaxis::GetAtlasArrays(matIn, atlasOffsets, atlasSites);
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< "input port 0: " << problem
                  << " (connect the output of vtkAtlasMedialAxisSimplifier)");
    return 0;
  }
  // Where the final fit changed the radii on the sheets' boundary, the
  // rolling balls are the radii the collapses placed.
  if (vtkDataArray* placed = matIn->GetPointData()->GetArray("PlacedRadius"))
  {
    if (placed->GetNumberOfComponents() != 1 ||
      placed->GetNumberOfTuples() != static_cast<vtkIdType>(medial.Radii.size()))
    {
      vtkErrorMacro(<< "input port 0: point data 'PlacedRadius' must have one value per medial "
                       "vertex (remove it to use 'Radius')");
      return 0;
    }
    for (std::size_t v = 0; v < medial.Radii.size(); ++v)
    {
      medial.Radii[v] = placed->GetComponent(static_cast<vtkIdType>(v), 0);
    }
  }
  vtkDataArray* siteArray = rvd->GetCellData()->GetArray("SiteId");
  vtkDataArray* triangleArray = rvd->GetCellData()->GetArray("TriangleId");
  if (!siteArray || !triangleArray)
  {
    vtkErrorMacro(<< "input port 1 has no cell data 'SiteId' and 'TriangleId': connect the "
                     "restricted Voronoi diagram (output 0 of vtkRestrictedVoronoiDiagram)");
    return 0;
  }
  const vtkIdType polygons = rvd->GetNumberOfCells();
  std::vector<medialaxis::Index> polygonSite(polygons), polygonTriangle(polygons);
  for (vtkIdType c = 0; c < polygons; ++c)
  {
    polygonSite[c] = static_cast<medialaxis::Index>(siteArray->GetComponent(c, 0));
    polygonTriangle[c] = static_cast<medialaxis::Index>(triangleArray->GetComponent(c, 0));
  }
  this->UpdateProgress(0.1);

  // The same preparation the diagram's filter made, so triangle ids agree.
  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(surfaceIn, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "input port 2: " << report.Error);
    return 0;
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }
  this->UpdateProgress(0.4);

  medialaxis::FilletDetectorOptions options;
  options.RadiusTolerance = this->RadiusTolerance;
  options.FaceTolerance = this->FaceTolerance;
  options.NormalTolerance = this->NormalTolerance * DegreesToRadians;
  options.MinimumConsistentFraction = this->MinimumConsistentFraction;
  options.MinimumArcAngle = this->MinimumArcAngle * DegreesToRadians;
  options.MinimumRadius = 0.01 * this->MinimumRadius;
  options.MinimumLength = 0.01 * this->MinimumLength;
  options.SplitAngle = this->SplitAngle * DegreesToRadians;
  medialaxis::FilletDetectionResult result;
  try
  {
    result = medialaxis::DetectFillets(
      surface, medial, atlasOffsets, atlasSites, polygonSite, polygonTriangle, options);
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro(<< "the inputs do not belong together: " << e.what());
    return 0;
  }
  this->UpdateProgress(0.9);

  CentreLinesToPolyData(result, lines);
  AddCounts(lines, result);
  medialaxis::TriangleMeshToPolyData(surface, surfaceOut);
  vtkNew<vtkIntArray> filletOfTriangle;
  filletOfTriangle->SetName("FilletId");
  filletOfTriangle->SetNumberOfValues(static_cast<vtkIdType>(result.TriangleFillet.size()));
  for (std::size_t t = 0; t < result.TriangleFillet.size(); ++t)
  {
    filletOfTriangle->SetValue(static_cast<vtkIdType>(t), result.TriangleFillet[t]);
  }
  surfaceOut->GetCellData()->AddArray(filletOfTriangle);
  surfaceOut->GetCellData()->SetActiveScalars("FilletId");
  AddCounts(surfaceOut, result);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkFilletDetector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RadiusTolerance: " << this->RadiusTolerance << "\n";
  os << indent << "FaceTolerance: " << this->FaceTolerance << "\n";
  os << indent << "NormalTolerance: " << this->NormalTolerance << "\n";
  os << indent << "MinimumConsistentFraction: " << this->MinimumConsistentFraction << "\n";
  os << indent << "MinimumArcAngle: " << this->MinimumArcAngle << "\n";
  os << indent << "MinimumRadius: " << this->MinimumRadius << "\n";
  os << indent << "MinimumLength: " << this->MinimumLength << "\n";
  os << indent << "SplitAngle: " << this->SplitAngle << "\n";
}
