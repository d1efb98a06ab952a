// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMidSurfaceExtractor.h"

#include "Structure/MidSurface.h"
#include "vtkMedialMeshConversion.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfacePreparation.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>

vtkStandardNewMacro(vtkMidSurfaceExtractor);

vtkMidSurfaceExtractor::vtkMidSurfaceExtractor()
{
  this->SetNumberOfInputPorts(2);
}

int vtkMidSurfaceExtractor::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkMidSurfaceExtractor::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surfaceIn = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* medialIn = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->EstimatedWallThickness = 0.0;
  this->NumberOfWalls = this->NumberOfWallSheets = this->NumberOfJunctionEdges = 0;

  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(surfaceIn, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "input port 0: " << report.Error);
    return 0;
  }
  vtkNew<vtkStructuralMedialAxis> computed;
  if (!medialIn)
  {
    // No medial mesh given: the CAD preset's, from the same surface.
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(surfaceIn);
    computed->SetInputData(copy);
    computed->SetPresetToCAD();
    // Its progress is the first half of this filter's.
    vtkNew<vtkCallbackCommand> progress;
    progress->SetClientData(this);
    progress->SetCallback(
      [](vtkObject*, unsigned long, void* self, void* amount)
      {
        static_cast<vtkMidSurfaceExtractor*>(self)->UpdateProgress(
          0.5 * *static_cast<double*>(amount));
      });
    computed->AddObserver(vtkCommand::ProgressEvent, progress);
    computed->Update();
    medialIn = computed->GetOutput();
    if (medialIn->GetNumberOfPoints() == 0)
    {
      vtkErrorMacro(<< "the medial axis of the surface could not be computed (see the errors of "
                       "vtkStructuralMedialAxis above)");
      return 0;
    }
  }
  this->UpdateProgress(0.5);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  medialaxis::MedialMesh mesh;
  std::string problem = medialaxis::PolyDataToMedialMesh(medialIn, mesh);
  if (problem.empty())
  {
    problem = medialaxis::ValidateMedialMesh(mesh).Message;
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< "input port 1 (the medial mesh): " << problem);
    return 0;
  }
  const medialaxis::MedialStructure structure = medialaxis::ClassifyMedialStructure(mesh);
  medialaxis::MidSurfaceOptions options;
  options.Walls.WallThickness = this->WallThickness;
  options.Walls.MaximumNormalDeviation = this->MaximumNormalDeviation * M_PI / 180.0;
  options.Walls.MinimumParallelFraction = this->MinimumParallelFraction;
  options.ExtendToLateralFaces = this->ExtendToLateralFaces;
  const medialaxis::MidSurface mid =
    medialaxis::ExtractMidSurface(mesh, structure, surface, options);
  this->UpdateProgress(0.9);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mid.Mesh.Points.size()));
  vtkNew<vtkDoubleArray> thickness;
  thickness->SetName("Thickness");
  thickness->SetNumberOfTuples(points->GetNumberOfPoints());
  vtkNew<vtkIdTypeArray> source;
  source->SetName("MedialVertexId");
  source->SetNumberOfTuples(points->GetNumberOfPoints());
  vtkNew<vtkUnsignedCharArray> pointType;
  pointType->SetName("PointType");
  pointType->SetNumberOfTuples(points->GetNumberOfPoints());
  for (std::size_t i = 0; i < mid.Mesh.Points.size(); ++i)
  {
    pointType->SetValue(static_cast<vtkIdType>(i), static_cast<unsigned char>(mid.PointType[i]));
    points->SetPoint(static_cast<vtkIdType>(i), mid.Mesh.Points[i].data());
    thickness->SetValue(static_cast<vtkIdType>(i), mid.Thickness[i]);
    source->SetValue(static_cast<vtkIdType>(i), mid.MedialVertex[i]);
  }
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkIdTypeArray> wallIds;
  wallIds->SetName("WallId");
  for (std::size_t f = 0; f < mid.Mesh.Triangles.size(); ++f)
  {
    const auto& t = mid.Mesh.Triangles[f];
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
    wallIds->InsertNextValue(mid.WallOfTriangle[f]);
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
  output->GetPointData()->AddArray(thickness);
  output->GetPointData()->SetActiveScalars("Thickness");
  output->GetPointData()->AddArray(source);
  output->GetPointData()->AddArray(pointType);
  output->GetCellData()->AddArray(wallIds);
  using Wall = medialaxis::MidSurfaceWall;
  medialaxis::AddFieldPerItem(output, "WallArea", mid.Walls, [](const Wall& w) { return w.Area; });
  medialaxis::AddFieldPerItem(
    output, "WallMeanThickness", mid.Walls, [](const Wall& w) { return w.MeanThickness; });
  medialaxis::AddFieldPerItem(
    output, "WallMinimumThickness", mid.Walls, [](const Wall& w) { return w.MinimumThickness; });
  medialaxis::AddFieldPerItem(
    output, "WallMaximumThickness", mid.Walls, [](const Wall& w) { return w.MaximumThickness; });

  this->EstimatedWallThickness = mid.WallThickness;
  this->NumberOfWalls = static_cast<vtkIdType>(mid.Walls.size());
  this->NumberOfWallSheets = static_cast<vtkIdType>(mid.WallSheets);
  this->NumberOfJunctionEdges = static_cast<vtkIdType>(mid.JunctionEdges);
  medialaxis::AddFieldDouble(output, "WallThickness", mid.WallThickness);
  medialaxis::AddFieldValue(output, "NumberOfWalls", this->NumberOfWalls);
  medialaxis::AddFieldValue(output, "NumberOfWallSheets", this->NumberOfWallSheets);
  medialaxis::AddFieldValue(output, "JunctionEdges", this->NumberOfJunctionEdges);
  medialaxis::AddFieldValue(output, "BoundaryEdges", static_cast<long long>(mid.BoundaryEdges));
  medialaxis::AddFieldValue(output, "FoldedEdges", static_cast<long long>(mid.FoldedEdges));
  if (mid.WallSheets == 0)
  {
    vtkWarningMacro(<< "no sheet of the medial axis lies between two parallel sides thinner than "
                    << mid.WallThickness
                    << ": the part has no thin walls at these settings (raise WallThickness or "
                       "MaximumNormalDeviation)");
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMidSurfaceExtractor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "WallThickness: " << this->WallThickness << "\n";
  os << indent << "MaximumNormalDeviation: " << this->MaximumNormalDeviation << "\n";
  os << indent << "MinimumParallelFraction: " << this->MinimumParallelFraction << "\n";
  os << indent << "ExtendToLateralFaces: " << this->ExtendToLateralFaces << "\n";
  os << indent << "EstimatedWallThickness: " << this->EstimatedWallThickness << "\n";
  os << indent << "NumberOfWalls: " << this->NumberOfWalls << "\n";
  os << indent << "NumberOfWallSheets: " << this->NumberOfWallSheets << "\n";
  os << indent << "NumberOfJunctionEdges: " << this->NumberOfJunctionEdges << "\n";
}
