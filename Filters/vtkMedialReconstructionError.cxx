// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialReconstructionError.h"

#include "Envelope/EnvelopeDistance.h"
#include "Envelope/ReconstructionError.h"
#include "Mesh/TriangleAdjacency.h"
#include "Support/Parallel.h"
#include "vtkMedialMeshConversion.h"
#include "vtkSurfacePreparation.h"

#include "vtkCellArray.h"
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
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <string>

vtkStandardNewMacro(vtkMedialReconstructionError);

namespace
{
using namespace medialaxis;

vtkSmartPointer<vtkDoubleArray> PointArray(const char* name, const std::vector<double>& values)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  return a;
}

void AddStatistics(vtkPolyData* output, const ReconstructionErrorResult& r)
{
  const double diagonal = r.Diagonal;
  auto add = [&](const std::string& name, double value)
  {
    AddFieldDouble(output, name.c_str(), value);
    AddFieldDouble(
      output, (name + "Percent").c_str(), diagonal > 0.0 ? 100.0 * value / diagonal : 0.0);
  };
  add("HausdorffSurfaceToEnvelope", r.SurfaceToEnvelope.Hausdorff);
  add("HausdorffSurfaceToEnvelopeLowerBound", r.SurfaceToEnvelope.HausdorffLowerBound);
  add("HausdorffEnvelopeToSurface", r.EnvelopeToSurface.Hausdorff);
  add("Hausdorff", r.Hausdorff);
  add("MeanSurfaceToEnvelope", r.SurfaceToEnvelope.Mean);
  add("MeanEnvelopeToSurface", r.EnvelopeToSurface.Mean);
  add("Mean", r.Mean);
  add("RMSSurfaceToEnvelope", r.SurfaceToEnvelope.RMS);
  add("RMSEnvelopeToSurface", r.EnvelopeToSurface.RMS);
  add("RMS", r.RMS);
  add("LargestInsideBoundGap", r.LargestBoundGap);
  AddFieldDouble(output, "BoundingBoxDiagonal", diagonal);
  AddFieldValue(output, "SurfaceSamples", static_cast<long long>(r.SurfaceToEnvelope.Samples));
  AddFieldValue(output, "EnvelopeSamples", static_cast<long long>(r.EnvelopeToSurface.Samples));
  AddFieldValue(output, "EnvelopeCandidates", static_cast<long long>(r.EnvelopeCandidates));
  AddFieldValue(output, "InsidePoints", static_cast<long long>(r.InsidePoints));
  AddFieldValue(output, "UncertifiedInsidePoints", static_cast<long long>(r.UncertifiedPoints));
  vtkNew<vtkDoubleArray> farthest;
  farthest->SetName("FarthestEnvelopePoint");
  farthest->SetNumberOfComponents(3);
  farthest->InsertNextTuple(r.EnvelopeFarthestPoint.data());
  output->GetFieldData()->AddArray(farthest);
}

}

vtkMedialReconstructionError::vtkMedialReconstructionError()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

int vtkMedialReconstructionError::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialReconstructionError::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* medialInput = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* samplesOutput = vtkPolyData::GetData(outputVector, 1);
  output->Initialize();
  samplesOutput->Initialize();
  this->Hausdorff = this->HausdorffPercent = 0.0;
  this->HausdorffSurfaceToEnvelope = this->HausdorffEnvelopeToSurface = 0.0;

  vtkNew<vtkPolyData> prepared;
  const auto report = PrepareSurfacePolyData(input, prepared);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "cannot measure the reconstruction error: " << report.Error);
    return 0;
  }
  // Port 1: a medial mesh (point data Radius), or any closed surface that
  // reconstructs the input (e.g. a skeletal diagram's union).
  const bool reconstructed = medialInput && medialInput->GetNumberOfPoints() > 0 &&
    !medialInput->GetPointData()->GetArray(RadiusArrayName) && medialInput->GetNumberOfPolys() > 0;
  MedialMesh medial;
  TriangleMesh reconstruction;
  if (reconstructed)
  {
    reconstruction = OutwardTriangleMesh(medialInput);
    // Distances to an open surface are still distances, but its inside is
    // undefined: say so rather than report signs that mean nothing.
    const TriangleAdjacency adjacency = ComputeTriangleAdjacency(reconstruction, 0.0);
    std::size_t openEdges = 0;
    for (const auto& across : adjacency.Neighbour)
    {
      openEdges += static_cast<std::size_t>(std::count(across.begin(), across.end(), Index(-1)));
    }
    if (openEdges > 0)
    {
      vtkWarningMacro(<< "the surface on input port 1 is not closed (" << openEdges
                      << " triangle sides with no single neighbour): its distances are measured, "
                         "but SignedDistance and InsidePoints mean nothing for it; close it, or "
                         "connect a medial mesh with point data 'Radius'");
    }
  }
  else
  {
    const std::string error = PolyDataToMedialMesh(medialInput, medial);
    if (!error.empty())
    {
      vtkErrorMacro(<< "cannot measure the reconstruction error: input port 1: " << error);
      return 0;
    }
    if (medial.NumberOfVertices() == 0)
    {
      vtkErrorMacro(<< "cannot measure the reconstruction error: the medial mesh on input port 1 "
                       "has no points (connect a medial mesh with point data 'Radius')");
      return 0;
    }
  }
  const TriangleMesh surface = OutwardTriangleMesh(prepared); // prepared: triangles, outward
  this->UpdateProgress(0.05);

  ReconstructionErrorOptions options;
  options.NumberOfSamples = static_cast<std::size_t>(this->NumberOfSamples);
  options.NumberOfEnvelopeSamples = static_cast<std::size_t>(this->NumberOfEnvelopeSamples);
  options.RandomSeed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(this->RandomSeed));
  options.MaximumSearches = static_cast<std::size_t>(this->MaximumSearches);
  options.Progress = [this](double f)
  {
    this->UpdateProgress(0.05 + 0.9 * f);
    return !this->GetAbortExecute();
  };
  const ReconstructionErrorResult result = RunWithThreads(this->NumberOfThreads,
    [&]
    {
      if (reconstructed)
      {
        return ComputeSurfaceDistanceError(surface, reconstruction, options);
      }
      const MedialEnvelope envelope(medial);
      if (envelope.Empty())
      {
        return ReconstructionErrorResult();
      }
      return ComputeReconstructionError(surface, envelope, options);
    });
  if (result.Aborted)
  {
    return 1;
  }
  if (result.Diagonal == 0.0 && result.VertexDistance.empty())
  {
    vtkErrorMacro(<< "cannot measure the reconstruction error: the medial mesh has no primitive");
    return 0;
  }

  output->ShallowCopy(prepared);
  output->GetPointData()->AddArray(PointArray("Distance", result.VertexDistance));
  output->GetPointData()->AddArray(PointArray("SignedDistance", result.VertexSignedDistance));
  output->GetPointData()->AddArray(PointArray("DistanceLowerBound", result.VertexLowerBound));
  output->GetPointData()->SetActiveScalars("Distance");
  AddStatistics(output, result);

  const vtkIdType ns = static_cast<vtkIdType>(result.EnvelopeSamples.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(ns);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(ns + 1);
  connectivity->SetNumberOfTuples(ns);
  vtkNew<vtkUnsignedCharArray> kind;
  kind->SetName("PrimitiveKind");
  kind->SetNumberOfTuples(ns);
  vtkNew<vtkIdTypeArray> primitive;
  primitive->SetName("PrimitiveId");
  primitive->SetNumberOfTuples(ns);
  for (vtkIdType i = 0; i < ns; ++i)
  {
    points->SetPoint(i, result.EnvelopeSamples[i].data());
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
    const PrimitiveRef ref =
      reconstructed ? PrimitiveRef{ PrimitiveKind::Sphere, -1 } : result.EnvelopeSamplePrimitive[i];
    kind->SetValue(i, static_cast<unsigned char>(ref.Kind));
    primitive->SetValue(i, ref.Id);
  }
  offsets->SetValue(ns, ns);
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  samplesOutput->SetPoints(points);
  samplesOutput->SetVerts(verts);
  samplesOutput->GetPointData()->AddArray(PointArray("Distance", result.EnvelopeSampleDistance));
  if (!reconstructed)
  {
    samplesOutput->GetPointData()->AddArray(kind);
    samplesOutput->GetPointData()->AddArray(primitive);
  }
  samplesOutput->GetPointData()->SetActiveScalars("Distance");
  AddStatistics(samplesOutput, result);

  this->Hausdorff = result.Hausdorff;
  this->HausdorffPercent = result.Diagonal > 0.0 ? 100.0 * result.Hausdorff / result.Diagonal : 0.0;
  this->HausdorffSurfaceToEnvelope = result.SurfaceToEnvelope.Hausdorff;
  this->HausdorffEnvelopeToSurface = result.EnvelopeToSurface.Hausdorff;
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialReconstructionError::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "NumberOfEnvelopeSamples: " << this->NumberOfEnvelopeSamples << "\n";
  os << indent << "MaximumSearches: " << this->MaximumSearches << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Hausdorff: " << this->Hausdorff << " (" << this->HausdorffPercent << "%)\n";
}
