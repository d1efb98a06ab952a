// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkUnsignedDistanceSource.h"

#include "Support/Parallel.h"
#include "Udf/UnsignedDistanceField.h"
#include "vtkSurfacePreparation.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

vtkStandardNewMacro(vtkUnsignedDistanceSource);

vtkUnsignedDistanceSource::vtkUnsignedDistanceSource()
{
  this->SetNumberOfInputPorts(1);
}

int vtkUnsignedDistanceSource::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

// The dimensions are known before the surface is: the extent is set here,
// the origin and spacing (from the surface's bounds) in RequestData.
int vtkUnsignedDistanceSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6] = { 0, 0, 0, 0, 0, 0 };
  for (int a = 0; a < 3; ++a)
  {
    extent[2 * a + 1] = std::max(this->SamplingDimensions[a], 2) - 1;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  return 1;
}

int vtkUnsignedDistanceSource::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  if (!input || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro(<< "the input has no polygons: an unsigned distance needs a triangle surface");
    return 0;
  }
  const medialaxis::TriangleMesh surface = medialaxis::OutwardTriangleMesh(input);
  medialaxis::Box bounds;
  for (const medialaxis::Point3& p : surface.Points)
  {
    bounds.Extend(p);
  }
  medialaxis::RegularField field = medialaxis::GridAroundBox(bounds,
    { this->SamplingDimensions[0], this->SamplingDimensions[1], this->SamplingDimensions[2] },
    this->Padding);
  if (field.Spacing[0] <= 0.0)
  {
    vtkErrorMacro(<< "the input surface has no extent (all its points coincide)");
    return 0;
  }
  const bool complete = medialaxis::RunWithThreads(this->NumberOfThreads,
    [&]
    {
      return medialaxis::SampleUnsignedDistance(surface, field,
        [this](double fraction)
        {
          this->UpdateProgress(fraction);
          return this->GetAbortExecute() != 0;
        });
    });
  if (!complete)
  {
    return 1;
  }
  output->SetDimensions(field.Dimensions.data());
  output->SetOrigin(field.Origin.data());
  output->SetSpacing(field.Spacing.data());
  vtkNew<vtkFloatArray> values;
  values->SetName("UnsignedDistance");
  values->SetNumberOfTuples(static_cast<vtkIdType>(field.Values.size()));
  std::copy(field.Values.begin(), field.Values.end(), values->GetPointer(0));
  output->GetPointData()->SetScalars(values);
  return 1;
}

void vtkUnsignedDistanceSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplingDimensions: " << this->SamplingDimensions[0] << " "
     << this->SamplingDimensions[1] << " " << this->SamplingDimensions[2] << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
