// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkQMatSimplifier.h"

#include "Simplification/QMatSimplifier.h"
#include "vtkMedialMeshConversion.h"

#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <cmath>
#include <utility>

vtkStandardNewMacro(vtkQMatSimplifier);

vtkQMatSimplifier::vtkQMatSimplifier()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkQMatSimplifier::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkQMatSimplifier::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();

  medialaxis::AtlasMedialMesh medial;
  std::string problem = medialaxis::PolyDataToMedialMesh(input, medial.Mesh);
  // Atlases are optional (a mesh read from a .ma file has none).
  const bool hasAtlas = problem.empty() && input->GetFieldData()->GetArray("AtlasSites");
  if (hasAtlas)
  {
    problem = medialaxis::GetAtlasArrays(input, medial.AtlasOffsets, medial.AtlasSites);
  }
  else
  {
    medial.AtlasOffsets.clear();
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< "cannot simplify: " << problem);
    return 0;
  }

  medialaxis::QMatSimplifierOptions options;
  options.TargetNumberOfVertices = static_cast<std::size_t>(this->TargetNumberOfVertices);
  options.MaximumCost = this->MaximumCost >= VTK_DOUBLE_MAX ? HUGE_VAL : this->MaximumCost;
  options.K = this->K;
  options.BoundaryWeight = this->BoundaryWeight;
  options.TopologyGuardVertexCount = static_cast<std::size_t>(this->TopologyGuardVertexCount);
  options.StrictTopologyGuard = this->StrictTopologyGuard;
  options.PreventFolds = this->PreventFolds;
  options.EulerNeutralCollapses = this->EulerNeutralCollapses;
  options.SpikeRatio = this->SpikeRatio;
  options.Progress = [this](double f)
  {
    this->UpdateProgress(0.05 + 0.9 * f);
    return !this->GetAbortExecute();
  };
  const medialaxis::QMatSimplifierResult result =
    medialaxis::SimplifyMedialAxisQMat(medial, options);
  if (result.Aborted)
  {
    return 1;
  }

  const medialaxis::AtlasMedialMesh& m = result.Medial;
  medialaxis::MedialMeshToPolyData(m.Mesh, output);
  if (hasAtlas)
  {
    medialaxis::AddAtlasArrays(output, m.AtlasOffsets, m.AtlasSites);
  }
  medialaxis::AddStabilityRatios(m.Mesh, output);
  for (const auto& [name, value] :
    { std::pair<const char*, std::size_t>{ "Collapses", result.Collapses },
      { "RejectedCollapses", result.RejectedCollapses },
      { "RelaxedCollapses", result.RelaxedCollapses },
      { "FoldingAllowedCollapses", result.FoldingAllowedCollapses },
      { "MergedFaces", result.MergedFaces },
      { "EulerNeutralCollapses", result.EulerNeutralCollapses },
      { "FacesWithoutTangentPlanes", result.FacesWithoutTangentPlanes },
      { "NestedCones", result.NestedCones }, { "CollapseBatches", result.Batches } })
  {
    medialaxis::AddFieldValue(output, name, static_cast<long long>(value));
  }
  medialaxis::AddFieldDouble(
    output, "QueueInitialisationSeconds", result.QueueInitialisationSeconds);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkQMatSimplifier::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetNumberOfVertices: " << this->TargetNumberOfVertices << "\n";
  os << indent << "MaximumCost: " << this->MaximumCost << "\n";
  os << indent << "K: " << this->K << "\n";
  os << indent << "BoundaryWeight: " << this->BoundaryWeight << "\n";
  os << indent << "TopologyGuardVertexCount: " << this->TopologyGuardVertexCount << "\n";
  os << indent << "StrictTopologyGuard: " << this->StrictTopologyGuard << "\n";
  os << indent << "PreventFolds: " << this->PreventFolds << "\n";
  os << indent << "EulerNeutralCollapses: " << this->EulerNeutralCollapses << "\n";
  os << indent << "SpikeRatio: " << this->SpikeRatio << "\n";
}
