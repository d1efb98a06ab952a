// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialCurveSkeleton.h"

#include "Skeleton/CurveSkeleton.h"
#include "vtkCurveSkeletonConversion.h"
#include "vtkMedialMeshConversion.h"
#include "vtkSurfacePreparation.h"

#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <string>

vtkStandardNewMacro(vtkMedialCurveSkeleton);

vtkMedialCurveSkeleton::vtkMedialCurveSkeleton()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

int vtkMedialCurveSkeleton::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    // Optional for the pipeline, so that a missing medial mesh gets the
    // error below, which says what to connect.
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkMedialCurveSkeleton::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surfaceIn = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* medialIn = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* skeletonOut = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* segmentation = vtkPolyData::GetData(outputVector, 1);
  skeletonOut->Initialize();
  segmentation->Initialize();

  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(surfaceIn, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "input port 0: " << report.Error);
    return 0;
  }
  medialaxis::MedialMesh medial;
  const std::string problem = medialIn
    ? medialaxis::PolyDataToMedialMesh(medialIn, medial)
    : "no medial mesh (connect the surface's medial mesh, e.g. vtkStructuralMedialAxis's output)";
  if (!problem.empty())
  {
    vtkErrorMacro(<< "input port 1: " << problem);
    return 0;
  }

  medialaxis::CurveSkeletonOptions options;
  options.PruneScale = this->PruneScale;
  options.SmoothingIterations = this->SmoothingIterations;
  options.NodeSpacing = this->NodeSpacing;
  options.Progress = [this](double f)
  {
    this->UpdateProgress(0.9 * f);
    return !this->GetAbortExecute();
  };
  const medialaxis::CurveSkeleton skeleton =
    medialaxis::ComputeCurveSkeleton(medial, surface, options);
  if (!skeleton.Problem.empty()) // not this surface's medial mesh
  {
    vtkErrorMacro(<< "input port 1: " << skeleton.Problem);
    return 0;
  }
  if (skeleton.Aborted)
  {
    return 1;
  }
  if (skeleton.UncollapsedTriangles > 0)
  {
    vtkWarningMacro(<< skeleton.UncollapsedTriangles
                    << " triangles of the medial mesh enclose a void and were left out: the "
                       "skeleton may have loops the solid has no handles for");
  }
  medialaxis::CurveSkeletonToPolyData(skeleton, skeletonOut);

  medialaxis::TriangleMeshToPolyData(surface, segmentation);
  const std::vector<medialaxis::Index> node = medialaxis::SegmentSurface(skeleton, surface);
  vtkNew<vtkIdTypeArray> branch, nodeId;
  branch->SetName("BranchId");
  branch->SetNumberOfTuples(static_cast<vtkIdType>(node.size()));
  nodeId->SetName("NodeId");
  nodeId->SetNumberOfTuples(static_cast<vtkIdType>(node.size()));
  for (std::size_t p = 0; p < node.size(); ++p)
  {
    nodeId->SetValue(static_cast<vtkIdType>(p), node[p]);
    branch->SetValue(static_cast<vtkIdType>(p), node[p] >= 0 ? skeleton.NodeBranch[node[p]] : -1);
  }
  segmentation->GetPointData()->AddArray(branch);
  segmentation->GetPointData()->AddArray(nodeId);
  segmentation->GetPointData()->SetActiveScalars("BranchId");
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialCurveSkeleton::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PruneScale: " << this->PruneScale << "\n";
  os << indent << "SmoothingIterations: " << this->SmoothingIterations << "\n";
  os << indent << "NodeSpacing: " << this->NodeSpacing << "\n";
}
