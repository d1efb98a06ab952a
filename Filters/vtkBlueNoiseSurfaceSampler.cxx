// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkBlueNoiseSurfaceSampler.h"

#include "Sampling/BlueNoiseSampler.h"
#include "Support/Parallel.h"
#include "vtkMedialMeshConversion.h"
#include "vtkSurfacePreparation.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>

vtkStandardNewMacro(vtkBlueNoiseSurfaceSampler);

int vtkBlueNoiseSurfaceSampler::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();

  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(input, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "cannot sample: " << report.Error);
    return 0;
  }

  medialaxis::SamplingOptions options;
  options.NumberOfSamples = static_cast<std::size_t>(this->NumberOfSamples);
  options.Seed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(this->RandomSeed));
  options.RelaxationIterations = this->RelaxationIterations;
  options.CandidateRatio = this->CandidateRatio;
  options.Adaptive = this->Adaptive;
  options.Sizing.SpacingPerThickness = this->ThinPartSpacing;
  options.Sizing.FinestSpacingRatio = this->FinestSpacingRatio;
  options.Sizing.ExtraSampleFraction = this->ThinPartExtraSamples;
  options.Progress = [this](double f)
  {
    this->UpdateProgress(0.05 + 0.9 * f);
    return !this->GetAbortExecute();
  };
  this->UpdateProgress(0.05);
  const medialaxis::SurfaceSamples samples = medialaxis::RunWithThreads(
    this->NumberOfThreads, [&] { return medialaxis::SampleSurface(surface, options); });
  if (samples.Aborted)
  {
    return 1; // aborted by the user: empty output, no error
  }

  const vtkIdType n = static_cast<vtkIdType>(samples.Points.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkNew<vtkIdTypeArray> triangleIds;
  triangleIds->SetName("TriangleId");
  triangleIds->SetNumberOfTuples(n);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(n + 1);
  connectivity->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, samples.Points[i].data());
    normals->SetTypedTuple(i, samples.Normals[i].data());
    triangleIds->SetValue(i, samples.TriangleIds[i]);
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(n, n);
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetVerts(verts);
  output->GetPointData()->SetNormals(normals);
  output->GetPointData()->AddArray(triangleIds);
  if (!samples.LocalThickness.empty())
  {
    vtkNew<vtkDoubleArray> thickness, spacing;
    thickness->SetName("LocalThickness");
    thickness->SetNumberOfTuples(n);
    spacing->SetName("Spacing");
    spacing->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double t = samples.LocalThickness[i];
      thickness->SetValue(i, std::isfinite(t) ? t : -1.0);
      spacing->SetValue(i, samples.Spacing[i]);
    }
    output->GetPointData()->AddArray(thickness);
    output->GetPointData()->AddArray(spacing);
  }
  medialaxis::AddFieldValue(output, "AddedSamples", static_cast<long long>(samples.AddedSamples));
  this->UpdateProgress(1.0);
  return 1;
}

void vtkBlueNoiseSurfaceSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "RelaxationIterations: " << this->RelaxationIterations << "\n";
  os << indent << "CandidateRatio: " << this->CandidateRatio << "\n";
  os << indent << "Adaptive: " << this->Adaptive << "\n";
  os << indent << "ThinPartSpacing: " << this->ThinPartSpacing << "\n";
  os << indent << "FinestSpacingRatio: " << this->FinestSpacingRatio << "\n";
  os << indent << "ThinPartExtraSamples: " << this->ThinPartExtraSamples << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
