// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkStructuralMedialAxis.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Simplification/AtlasSimplifier.h"

#include "vtkMedialMeshConversion.h"
#include "vtkStructuralMedialAxisSearches.h"
#include "vtkSurfacePreparation.h"

#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkBlueNoiseSurfaceSampler.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkQMatSimplifier.h"
#include "vtkRestrictedVoronoiDiagram.h"
#include "vtkSlabReconstructor.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkVoronoiMedialAxis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkStructuralMedialAxis);

vtkStructuralMedialAxis::vtkStructuralMedialAxis()
{
  this->SetNumberOfOutputPorts(4);
  this->SetPresetToOrganic();
}

void vtkStructuralMedialAxis::SetPresetToCAD()
{
  this->SetNumberOfSamples(50000);
  this->SetTargetNumberOfVertices(5000);
  this->SetPreserveSharpFeatures(true);
  this->SetAdaptiveSampling(false);
}

void vtkStructuralMedialAxis::SetPresetToOrganic()
{
  this->SetNumberOfSamples(10000);
  this->SetTargetNumberOfVertices(1000);
  this->SetPreserveSharpFeatures(false);
  this->SetAdaptiveSampling(true);
}

int vtkStructuralMedialAxis::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{
using medialaxis::ErrorTargetResult;
using medialaxis::FringeChoice;
using medialaxis::GetFieldValue;
using medialaxis::SimplifyToErrorTarget;
using medialaxis::SimplifyWithTheCloserFringeSetting;
using medialaxis::StageObserver;

// When the medial axis misses handles of the surface, the sites are drawn
// again, denser on thin parts (medialaxis::DenserOnThinParts) or, sampled
// uniformly, twice as many, until none is missed or the rounds run out.
void SampleMissedHandlesAgain(vtkBlueNoiseSurfaceSampler* sampler, vtkVoronoiMedialAxis* voronoi)
{
  medialaxis::SizingOptions sizing;
  sizing.SpacingPerThickness = sampler->GetThinPartSpacing();
  for (int round = 1; GetFieldValue(voronoi->GetOutput(), "MissingLoops") > 0 &&
       medialaxis::DenserOnThinParts(sizing, round);
       ++round)
  {
    if (sampler->GetAdaptive())
    {
      sampler->SetThinPartSpacing(sizing.SpacingPerThickness);
      sampler->SetThinPartExtraSamples(sizing.ExtraSampleFraction);
    }
    else
    {
      sampler->SetNumberOfSamples(2 * sampler->GetNumberOfSamples());
    }
    voronoi->Update();
  }
}

// A stage's surface error names places in the local frame; the same check
// on the input itself gives them in the input's coordinates.
std::string InInputFrame(const std::string& message, vtkPolyData* local, vtkPolyData* input)
{
  vtkNew<vtkPolyData> unused;
  const std::string localError = medialaxis::PrepareSurfacePolyData(local, unused).Error;
  const std::string inputError = medialaxis::PrepareSurfacePolyData(input, unused).Error;
  const std::size_t at = localError.empty() ? std::string::npos : message.find(localError);
  if (at == std::string::npos || inputError.empty())
  {
    return message;
  }
  return message.substr(0, at) + inputError + message.substr(at + localError.size());
}

// The chain runs on the surface moved to the origin and scaled by a power of
// two to a box about one unit across, and its results are moved back. Far
// from the origin (an offset of 1e6) circumcentres and distances then keep
// their precision, and at any scale (1e-30, 1e30) the chain does exactly
// the arithmetic it does at unit size: scaling by a power of two is exact.
struct LocalFrame
{
  double Centre[3] = { 0.0, 0.0, 0.0 };
  double Scale = 1.0; // a power of two

  explicit LocalFrame(vtkPoints* points)
  {
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      for (int k = 0; k < 3; ++k)
      {
        if (!std::isfinite(p[k]))
        {
          return; // left to the stages to refuse, in the input's own terms
        }
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
    const double diagonal = std::sqrt(
      std::pow(hi[0] - lo[0], 2) + std::pow(hi[1] - lo[1], 2) + std::pow(hi[2] - lo[2], 2));
    if (!(diagonal > 0.0) || !std::isfinite(diagonal))
    {
      return;
    }
    for (int k = 0; k < 3; ++k)
    {
      this->Centre[k] = 0.5 * lo[k] + 0.5 * hi[k];
    }
    this->Scale = std::ldexp(1.0, -std::ilogb(diagonal));
  }

  vtkSmartPointer<vtkPoints> ToLocal(vtkPoints* points) const
  {
    auto local = vtkSmartPointer<vtkPoints>::New();
    local->SetDataTypeToDouble();
    local->SetNumberOfPoints(points->GetNumberOfPoints());
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      for (int k = 0; k < 3; ++k)
      {
        p[k] = (p[k] - this->Centre[k]) * this->Scale;
      }
      local->SetPoint(i, p);
    }
    return local;
  }

  void ToWorld(vtkDataArray* positions) const
  {
    for (vtkIdType i = 0; positions && i < positions->GetNumberOfTuples(); ++i)
    {
      double p[3];
      positions->GetTuple(i, p);
      for (int k = 0; k < 3; ++k)
      {
        p[k] = p[k] / this->Scale + this->Centre[k];
      }
      positions->SetTuple(i, p);
    }
  }

  // Lengths scale with 1 / Scale, areas with its square.
  void ScaleBack(vtkDataArray* values, int power) const
  {
    const double factor = std::pow(this->Scale, -power);
    for (vtkIdType i = 0; values && i < values->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < values->GetNumberOfComponents(); ++c)
      {
        values->SetComponent(i, c, values->GetComponent(i, c) * factor);
      }
    }
  }

  // A stage's output moved back: its points, and its arrays that are
  // positions, lengths or areas, deep-copied first (stages share them).
  void ToWorld(vtkPolyData* data) const
  {
    if (this->Scale == 1.0 && this->Centre[0] == 0.0 && this->Centre[1] == 0.0 &&
      this->Centre[2] == 0.0)
    {
      return;
    }
    if (data->GetPoints())
    {
      vtkNew<vtkPoints> points; // double: far from the origin float would round
      points->SetDataTypeToDouble();
      points->GetData()->DeepCopy(data->GetPoints()->GetData());
      this->ToWorld(points->GetData());
      data->SetPoints(points);
    }
    // Positions become double: far from the origin float would round them.
    auto copied = [](vtkFieldData* fields, const char* name, bool position) -> vtkDataArray*
    {
      vtkDataArray* shared = fields->GetArray(name);
      if (!shared)
      {
        return nullptr;
      }
      vtkSmartPointer<vtkDataArray> copy = position
        ? vtkSmartPointer<vtkDataArray>(vtkSmartPointer<vtkDoubleArray>::New())
        : vtk::TakeSmartPointer(shared->NewInstance());
      copy->DeepCopy(shared);
      copy->SetName(name);
      fields->AddArray(copy); // replaces the shared array of that name
      return copy;
    };
    this->ScaleBack(copied(data->GetPointData(), "Radius", false), 1);
    this->ScaleBack(copied(data->GetPointData(), "PlacedRadius", false), 1);
    this->ScaleBack(copied(data->GetPointData(), "CellArea", false), 2);
    this->ScaleBack(copied(data->GetPointData(), "CellRadius", false), 1);
    this->ToWorld(copied(data->GetPointData(), "CellCentroid", true));
    this->ToWorld(copied(data->GetFieldData(), "SitePositions", true));
  }
};
}

int vtkStructuralMedialAxis::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* mat = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* correspondence = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* sitesOut = vtkPolyData::GetData(outputVector, 2);
  vtkPolyData* envelopeOut = vtkPolyData::GetData(outputVector, 3);
  mat->Initialize();
  correspondence->Initialize();
  sitesOut->Initialize();
  envelopeOut->Initialize();
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro(<< "surface has no polygons (it has " << (input ? input->GetNumberOfLines() : 0)
                  << " line and " << (input ? input->GetNumberOfVerts() : 0)
                  << " vertex cells): give a closed triangle surface");
    return 0;
  }

  // The stages run on a copy in the local frame, so that this filter's input
  // pipeline is not re-executed by them.
  const LocalFrame frame(input->GetPoints());
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(input);
  if (input->GetPoints())
  {
    surface->SetPoints(frame.ToLocal(input->GetPoints()));
  }
  // Crossing shells and a surface passing through itself: resolved first,
  // each piece remembering the input cell it comes from.
  vtkNew<vtkIdTypeArray> inputCellOfTriangle;
  medialaxis::SurfacePreparationReport repair;
  double repairSeconds = 0.0;
  if (this->RepairSelfIntersections)
  {
    const auto begin = std::chrono::steady_clock::now();
    medialaxis::SurfacePreparationOptions options;
    options.RepairSelfIntersections = true;
    vtkNew<vtkPolyData> prepared;
    repair = medialaxis::PrepareSurfacePolyData(surface, prepared, options);
    // Other defects are left to the stages, which name themselves.
    if (!repair.Ok() && repair.CrossingShells + repair.CrossingFarApart > 0)
    {
      vtkErrorMacro(<< "stage SelfIntersectionRepair failed: "
                    << InInputFrame(repair.Error, surface, input));
      return 0;
    }
    for (const std::string& note : repair.Notes)
    {
      if (medialaxis::IsMovedSurfaceNote(note))
      {
        vtkWarningMacro(<< note);
      }
    }
    if (repair.Repaired)
    {
      vtkNew<vtkStaticCellLocator> locator;
      locator->SetDataSet(surface);
      locator->BuildLocator();
      vtkNew<vtkGenericCell> cell;
      inputCellOfTriangle->SetNumberOfTuples(prepared->GetNumberOfCells());
      for (vtkIdType c = 0; c < prepared->GetNumberOfCells(); ++c)
      {
        // A piece of an input triangle: its centroid lies on it.
        double centroid[3] = { 0, 0, 0 }, closest[3], distance2;
        const vtkIdType* ids;
        vtkIdType count;
        prepared->GetCellPoints(c, count, ids);
        for (vtkIdType k = 0; k < count; ++k)
        {
          const double* p = prepared->GetPoint(ids[k]);
          for (int a = 0; a < 3; ++a)
          {
            centroid[a] += p[a] / static_cast<double>(count);
          }
        }
        vtkIdType found = -1;
        int subId;
        locator->FindClosestPoint(centroid, closest, cell, found, subId, distance2);
        inputCellOfTriangle->SetValue(c, found);
      }
      surface->ShallowCopy(prepared);
    }
    repairSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  }
  vtkNew<vtkBlueNoiseSurfaceSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(this->NumberOfSamples);
  sampler->SetRandomSeed(this->RandomSeed);
  sampler->SetAdaptive(this->AdaptiveSampling);
  sampler->SetNumberOfThreads(this->NumberOfThreads);
  vtkNew<vtkRestrictedVoronoiDiagram> rvd;
  rvd->SetInputData(0, surface);
  rvd->SetInputConnection(1, sampler->GetOutputPort());
  rvd->SetFeatureAngle(this->FeatureAngle);
  rvd->SetFeatureNormalFiltering(this->FeatureNormalFiltering);
  rvd->SetNumberOfThreads(this->NumberOfThreads);
  vtkNew<vtkVoronoiMedialAxis> voronoi;
  voronoi->SetInputData(0, surface);
  voronoi->SetInputConnection(1, rvd->GetOutputPort(1));
  voronoi->SetConcaveFiltering(this->ConcaveFiltering);
  voronoi->SetNumberOfThreads(this->NumberOfThreads);
  vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
  simplifier->SetInputConnection(0, voronoi->GetOutputPort());
  simplifier->SetInputConnection(1, rvd->GetOutputPort(0));
  simplifier->SetTargetNumberOfVertices(this->TargetNumberOfVertices);
  simplifier->SetNumberOfThreads(this->NumberOfThreads);
  simplifier->SetPreserveSharpFeatures(this->PreserveSharpFeatures);
  simplifier->SetFringeCollapses(this->FringeCollapses);
  simplifier->SetErrorBands(this->ErrorBands);
  simplifier->SetHairAngle(this->HairAngle);
  simplifier->SetFinBudget(this->FinBudget);
  simplifier->SetPleatAngle(this->PleatAngle);
  simplifier->SetEulerNeutralSpikeCollapses(this->EulerNeutralSpikeCollapses);
  simplifier->SetClampRadiiToAtlas(this->ClampRadiiToAtlas);
  simplifier->SetAbsorbSpikes(this->AbsorbSpikes);
  simplifier->SetFinalFit(this->FinalFit);
  simplifier->SetFitSpikeRepair(this->FitSpikeRepair);
  simplifier->SetFitSheetBoundaryRadii(this->FitSheetBoundaryRadii);
  simplifier->SetLambda(this->Lambda);
  simplifier->SetSpikeThreshold(this->SpikeThreshold);
  vtkNew<vtkQMatSimplifier> qmat;
  qmat->SetInputConnection(voronoi->GetOutputPort());
  qmat->SetTargetNumberOfVertices(this->TargetNumberOfVertices);
  vtkAlgorithm* simplification =
    this->Strategy == QMat ? static_cast<vtkAlgorithm*>(qmat) : simplifier;

  // Shares of the whole run, from measured stage times (50,000 samples ->
  // 5,000 spheres on 2 cores: about 10%, 6%, 19% and 65%).
  struct Stage
  {
    const char* Name;
    vtkAlgorithm* Algorithm;
    double Share;
  };
  const Stage stages[] = { { "Sampling", sampler, 0.10 }, { "RestrictedVoronoi", rvd, 0.06 },
    { "VoronoiMedialAxis", voronoi, 0.19 }, { "Simplification", simplification, 0.65 } };
  double start = 0.0, total = 0.0;
  std::vector<std::pair<std::string, double>> times;
  ErrorTargetResult errorTargetResult;
  FringeChoice fringeChoice;
  // Below the count where the simplifier's automatic setting turns fringe
  // collapses off.
  const auto strictLinkConditionCount =
    static_cast<vtkIdType>(medialaxis::AtlasSimplifierOptions().StrictLinkConditionVertexCount);
  const bool chooseFringe = this->Strategy == Structural && !this->PreserveSharpFeatures &&
    this->FringeCollapses == vtkAtlasMedialAxisSimplifier::FringeAutomatic &&
    this->MaximumError <= 0.0 && this->TargetNumberOfVertices < strictLinkConditionCount;
  for (const Stage& stage : stages)
  {
    StageObserver observer{ this, stage.Algorithm, start, stage.Share, {} };
    vtkNew<vtkCallbackCommand> progress, error;
    progress->SetCallback(&StageObserver::OnProgress);
    progress->SetClientData(&observer);
    error->SetCallback(&StageObserver::OnError);
    error->SetClientData(&observer);
    const unsigned long progressTag =
      stage.Algorithm->AddObserver(vtkCommand::ProgressEvent, progress);
    const unsigned long errorTag = stage.Algorithm->AddObserver(vtkCommand::ErrorEvent, error);
    const auto begin = std::chrono::steady_clock::now();
    const bool errorTarget = stage.Algorithm == simplification && this->MaximumError > 0.0;
    if (errorTarget)
    {
      errorTargetResult = SimplifyToErrorTarget(this, simplifier, qmat, simplification, surface,
        voronoi->GetOutput()->GetNumberOfPoints(), observer);
    }
    const bool fringeTarget = stage.Algorithm == simplification && chooseFringe;
    if (fringeTarget)
    {
      SimplifyWithTheCloserFringeSetting(this, simplifier, surface, observer, fringeChoice);
    }
    const int ok = errorTarget ? errorTargetResult.Ok
      : fringeTarget           ? fringeChoice.Ok
                               : stage.Algorithm->GetExecutive()->Update();
    if (ok && observer.Error.empty() && stage.Algorithm == voronoi)
    {
      SampleMissedHandlesAgain(sampler, voronoi); // its errors reach the observer
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    stage.Algorithm->RemoveObserver(progressTag);
    stage.Algorithm->RemoveObserver(errorTag);
    if (this->GetAbortExecute())
    {
      mat->Initialize();
      return 1;
    }
    if (!ok || !observer.Error.empty())
    {
      vtkErrorMacro(<< "stage " << stage.Name << " failed: "
                    << (observer.Error.empty() ? "no output"
                                               : InInputFrame(observer.Error, surface, input)));
      return 0;
    }
    times.emplace_back(stage.Name, seconds);
    total += seconds;
    start += stage.Share;
  }

  if (this->Strategy == QMat)
  {
    mat->ShallowCopy(qmat->GetOutput(0));
    std::vector<medialaxis::Index> offsets, atlasSites;
    medialaxis::GetAtlasArrays(mat, offsets, atlasSites);
    medialaxis::AddCorrespondence(rvd->GetOutput(0), offsets, atlasSites,
      static_cast<std::size_t>(sampler->GetOutput()->GetNumberOfPoints()), correspondence);
  }
  else
  {
    mat->ShallowCopy(chooseFringe ? fringeChoice.Mat.Get() : simplifier->GetOutput(0));
    correspondence->ShallowCopy(chooseFringe
        ? static_cast<vtkDataObject*>(fringeChoice.Correspondence.Get())
        : simplifier->GetOutputDataObject(1));
  }
  sitesOut->ShallowCopy(rvd->GetOutputDataObject(1));
  vtkNew<vtkPolyData> localMat; // for the envelope, built in the local frame
  localMat->ShallowCopy(mat);
  frame.ToWorld(mat);
  frame.ToWorld(correspondence);
  if (repair.Repaired)
  {
    // Each Voronoi cell lies on a triangle of the repaired surface, a piece
    // of an input cell.
    vtkDataArray* triangleIds = correspondence->GetCellData()->GetArray("TriangleId");
    vtkNew<vtkIdTypeArray> inputIds;
    inputIds->SetName("InputTriangleId");
    inputIds->SetNumberOfTuples(correspondence->GetNumberOfCells());
    for (vtkIdType c = 0; c < correspondence->GetNumberOfCells(); ++c)
    {
      const vtkIdType t = triangleIds ? static_cast<vtkIdType>(triangleIds->GetTuple1(c)) : -1;
      inputIds->SetValue(c,
        t >= 0 && t < inputCellOfTriangle->GetNumberOfTuples() ? inputCellOfTriangle->GetValue(t)
                                                               : -1);
    }
    vtkNew<vtkPolyData> tagged; // the correspondence may share arrays with a stage
    tagged->ShallowCopy(correspondence);
    vtkNew<vtkCellData> cellData;
    cellData->ShallowCopy(correspondence->GetCellData());
    cellData->AddArray(inputIds);
    tagged->GetCellData()->ShallowCopy(cellData);
    correspondence->ShallowCopy(tagged);
  }
  frame.ToWorld(sitesOut);
  // Per-stage times and counts travel with the medial mesh.
  vtkNew<vtkFieldData> fields;
  fields->DeepCopy(mat->GetFieldData()); // the simplifier's arrays are shared
  mat->SetFieldData(fields);
  for (const auto& [name, seconds] : times)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName((name + "Seconds").c_str());
    a->InsertNextValue(seconds);
    fields->AddArray(a);
  }
  vtkNew<vtkDoubleArray> totalArray;
  totalArray->SetName("TotalSeconds");
  totalArray->InsertNextValue(total);
  fields->AddArray(totalArray);
  vtkPolyData* initial = voronoi->GetOutput();
  medialaxis::AddFieldValue(mat, "Sites", sampler->GetOutput()->GetNumberOfPoints());
  const long long addedSamples = sampler->GetOutput()->GetNumberOfPoints() - this->NumberOfSamples;
  const auto missingLoops = static_cast<long long>(GetFieldValue(initial, "MissingLoops"));
  medialaxis::AddFieldValue(mat, "AddedSamples", addedSamples);
  medialaxis::AddFieldValue(mat, "MissingLoops", missingLoops);
  if (missingLoops > 0)
  {
    vtkWarningMacro(<< "the medial axis misses " << missingLoops
                    << " handle(s) of the surface: parts thinner than the sampling can follow; "
                       "use more samples");
  }
  medialaxis::AddFieldValue(mat, "InitialVertices", initial->GetNumberOfPoints());
  medialaxis::AddFieldValue(mat, "InitialTriangles", initial->GetNumberOfPolys());
  if (repair.Repaired)
  {
    medialaxis::AddFieldValue(
      mat, "RepairedCrossingPairs", static_cast<long long>(repair.SelfIntersections));
    medialaxis::AddFieldDouble(
      mat, "RepairRemovedAreaFraction", repair.RemovedArea / (repair.Area + repair.RemovedArea));
    medialaxis::AddFieldDouble(mat, "RepairSeconds", repairSeconds);
    medialaxis::AddFieldValue(mat, "RepairWrapped", repair.RepairMethod == "alpha wrap" ? 1 : 0);
    medialaxis::AddFieldValue(
      mat, "RepairPulledApart", repair.RepairMethod == "pulled apart" ? 1 : 0);
    medialaxis::AddFieldDouble(mat, "RepairDeviationFraction", repair.RepairDeviation);
  }
  if (this->MaximumError > 0.0)
  {
    if (errorTargetResult.Hausdorff > this->MaximumError)
    {
      vtkWarningMacro(<< "MaximumError " << 100.0 * this->MaximumError
                      << "% is not reached: the initial medial mesh from " << this->NumberOfSamples
                      << " samples is already " << 100.0 * errorTargetResult.Hausdorff
                      << "% from the surface; use more samples");
    }
    medialaxis::AddFieldDouble(mat, "MaximumError", this->MaximumError);
    medialaxis::AddFieldDouble(mat, "ErrorTargetHausdorff", errorTargetResult.Hausdorff);
    medialaxis::AddFieldValue(mat, "ErrorTargetEvaluations", errorTargetResult.Evaluations);
  }
  if (chooseFringe)
  {
    // Both runs' distances (fractions of the diagonal); FringeCollapsesUsed
    // says which was kept.
    medialaxis::AddFieldDouble(mat, "HausdorffWithoutFringeCollapses", fringeChoice.HausdorffOff);
    medialaxis::AddFieldDouble(mat, "HausdorffWithFringeCollapses", fringeChoice.HausdorffOn);
  }

  if (this->GenerateEnvelope)
  {
    // The union of the medial primitives, for display (fast, overlapping).
    vtkNew<vtkSlabReconstructor> envelope;
    envelope->SetInputData(localMat);
    envelope->SetModeToPrimitives();
    envelope->SetNumberOfThreads(this->NumberOfThreads);
    const auto begin = std::chrono::steady_clock::now();
    envelope->Update();
    medialaxis::AddFieldDouble(mat, "EnvelopeSeconds",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
    envelopeOut->ShallowCopy(envelope->GetOutput());
    frame.ToWorld(envelopeOut);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkStructuralMedialAxis::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "AdaptiveSampling: " << this->AdaptiveSampling << "\n";
  os << indent << "TargetNumberOfVertices: " << this->TargetNumberOfVertices << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "PreserveSharpFeatures: " << this->PreserveSharpFeatures << "\n";
  os << indent << "FringeCollapses: " << this->FringeCollapses << "\n";
  os << indent << "EulerNeutralSpikeCollapses: " << this->EulerNeutralSpikeCollapses << "\n";
  os << indent << "ClampRadiiToAtlas: " << this->ClampRadiiToAtlas << "\n";
  os << indent << "ErrorBands: " << this->ErrorBands << "\n";
  os << indent << "HairAngle: " << this->HairAngle << "\n";
  os << indent << "FinBudget: " << this->FinBudget << "\n";
  os << indent << "PleatAngle: " << this->PleatAngle << "\n";
  os << indent << "AbsorbSpikes: " << this->AbsorbSpikes << "\n";
  os << indent << "FinalFit: " << this->FinalFit << "\n";
  os << indent << "FitSpikeRepair: " << this->FitSpikeRepair << "\n";
  os << indent << "FitSheetBoundaryRadii: " << this->FitSheetBoundaryRadii << "\n";
  os << indent << "Strategy: " << (this->Strategy == QMat ? "QMat" : "Structural") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "FeatureNormalFiltering: " << this->FeatureNormalFiltering << "\n";
  os << indent << "ConcaveFiltering: " << this->ConcaveFiltering << "\n";
  os << indent << "Lambda: " << this->Lambda << "\n";
  os << indent << "SpikeThreshold: " << this->SpikeThreshold << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "GenerateEnvelope: " << this->GenerateEnvelope << "\n";
  os << indent << "RepairSelfIntersections: " << this->RepairSelfIntersections << "\n";
}
