// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkAtlasMedialAxisSimplifier.h"

#include "Simplification/AtlasSimplifier.h"
#include "Support/Parallel.h"
#include "vtkMedialMeshConversion.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <limits>
#include <utility>

vtkStandardNewMacro(vtkAtlasMedialAxisSimplifier);

vtkAtlasMedialAxisSimplifier::vtkAtlasMedialAxisSimplifier()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

int vtkAtlasMedialAxisSimplifier::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{
// The RVD polygons and per-site field data as the core expects them.
std::string ReadRvd(vtkPolyData* input, medialaxis::RestrictedVoronoiDiagram& rvd,
  std::vector<medialaxis::Point3>& sites)
{
  vtkDataArray* positions = input->GetFieldData()->GetArray("SitePositions");
  vtkDataArray* siteIds = input->GetCellData()->GetArray("SiteId");
  vtkDataArray* triangleIds = input->GetCellData()->GetArray("TriangleId"); // optional
  if (!positions || positions->GetNumberOfComponents() != 3 || !siteIds)
  {
    return "input port 1 must be the restricted Voronoi diagram (output 0 of "
           "vtkRestrictedVoronoiDiagram: cell data 'SiteId', field data 'SitePositions')";
  }
  const vtkIdType ns = positions->GetNumberOfTuples();
  sites.resize(static_cast<std::size_t>(ns));
  for (vtkIdType i = 0; i < ns; ++i)
  {
    positions->GetTuple(i, sites[i].data());
  }
  for (auto [name, flags] :
    { std::pair<const char*, std::vector<std::uint8_t>*>{ "SiteConvexFeature", &rvd.ConvexFeature },
      std::pair<const char*, std::vector<std::uint8_t>*>{
        "SiteConcaveFeature", &rvd.ConcaveFeature } })
  {
    if (vtkDataArray* a = input->GetFieldData()->GetArray(name))
    {
      if (a->GetNumberOfTuples() == ns)
      {
        flags->resize(static_cast<std::size_t>(ns));
        for (vtkIdType i = 0; i < ns; ++i)
        {
          (*flags)[i] = a->GetComponent(i, 0) != 0.0 ? 1 : 0;
        }
      }
    }
  }
  // Polygons are the polys after any verts and lines in the cell order.
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  // Exact sizes: grown by doubling, the vertices alone held up to twice
  // their 72 MB on a 268,686-triangle surface at 50,000 samples.
  const auto polygons = static_cast<std::size_t>(input->GetPolys()->GetNumberOfCells());
  rvd.Vertices.reserve(static_cast<std::size_t>(input->GetPolys()->GetNumberOfConnectivityIds()));
  rvd.Offsets.reserve(polygons + 1);
  rvd.PolygonSite.reserve(polygons);
  if (triangleIds)
  {
    rvd.PolygonTriangle.reserve(polygons);
  }
  auto it = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  vtkIdType cell = firstPoly;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    const auto site = static_cast<medialaxis::Index>(siteIds->GetComponent(cell, 0));
    if (site < 0 || site >= ns)
    {
      return "RVD polygon " + std::to_string(cell) + " has SiteId " + std::to_string(site) +
        " outside [0, " + std::to_string(ns) + ")";
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      medialaxis::Point3 p;
      input->GetPoint(ids[k], p.data());
      rvd.Vertices.push_back(p);
    }
    rvd.Offsets.push_back(static_cast<medialaxis::Index>(rvd.Vertices.size()));
    rvd.PolygonSite.push_back(site);
    if (triangleIds)
    {
      rvd.PolygonTriangle.push_back(
        static_cast<medialaxis::Index>(triangleIds->GetComponent(cell, 0)));
    }
  }
  return std::string();
}

}

int vtkAtlasMedialAxisSimplifier::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* matIn = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* rvdIn = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* rvdOut = vtkPolyData::GetData(outputVector, 1);
  output->Initialize();
  rvdOut->Initialize();
  if (!rvdIn)
  {
    vtkErrorMacro(<< "no restricted Voronoi diagram on input port 1");
    return 0;
  }

  medialaxis::AtlasMedialMesh input;
  std::string problem = medialaxis::PolyDataToMedialMesh(matIn, input.Mesh);
  if (problem.empty())
  {
    problem = medialaxis::GetAtlasArrays(matIn, input.AtlasOffsets, input.AtlasSites);
  }
  medialaxis::RestrictedVoronoiDiagram rvd;
  std::vector<medialaxis::Point3> sites;
  if (problem.empty())
  {
    problem = ReadRvd(rvdIn, rvd, sites);
  }
  for (medialaxis::Index s : input.AtlasSites)
  {
    if (problem.empty() && (s < 0 || static_cast<std::size_t>(s) >= sites.size()))
    {
      problem = "Atlas site " + std::to_string(s) +
        " is not a site of the restricted Voronoi "
        "diagram on input port 1 (they must come from the same sampling)";
    }
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< "cannot simplify: " << problem);
    return 0;
  }
  // The Voronoi stage's bounds on the distance to the nearest site, where
  // they still describe these centres (double precision, as it wrote them).
  vtkDataArray* clearance = matIn->GetPointData()->GetArray("SiteClearance");
  if (clearance && clearance->GetNumberOfComponents() == 1 &&
    clearance->GetNumberOfTuples() == matIn->GetNumberOfPoints() &&
    matIn->GetPoints()->GetDataType() == VTK_DOUBLE)
  {
    input.SiteClearance.resize(static_cast<std::size_t>(clearance->GetNumberOfTuples()));
    for (vtkIdType v = 0; v < clearance->GetNumberOfTuples(); ++v)
    {
      input.SiteClearance[static_cast<std::size_t>(v)] = clearance->GetComponent(v, 0);
    }
  }

  medialaxis::AtlasSimplifierOptions options;
  options.TargetNumberOfVertices = static_cast<std::size_t>(this->TargetNumberOfVertices);
  options.MaximumCost = this->MaximumCost >= VTK_DOUBLE_MAX ? HUGE_VAL : this->MaximumCost;
  options.Lambda = this->Lambda;
  options.SpikeThreshold = this->SpikeThreshold;
  options.SpikeSharpness = this->SpikeSharpness;
  options.TopologyGuardVertexCount =
    this->TopologyGuardVertexCount == 0 || this->TopologyGuardVertexCount >= VTK_ID_MAX
    ? std::numeric_limits<std::size_t>::max()
    : static_cast<std::size_t>(this->TopologyGuardVertexCount);
  options.StrictTopologyGuard = this->StrictTopologyGuard;
  options.PreserveSharpFeatures = this->PreserveSharpFeatures;
  options.InvaginatedTerm = this->InvaginatedTerm;
  options.ClampRadiiToAtlas = this->ClampRadiiToAtlas;
  options.AbsorbSpikes = this->AbsorbSpikes;
  options.ErrorBound = this->ErrorBound;
  options.ErrorBands = this->ErrorBands == BandsOn ? medialaxis::ErrorBandMode::On
    : this->ErrorBands == BandsOff                 ? medialaxis::ErrorBandMode::Off
                                                   : medialaxis::ErrorBandMode::Automatic;
  options.HairAngle = this->HairAngle;
  options.FinBudget = this->FinBudget;
  options.PleatAngle = this->PleatAngle;
  options.PreventFolds = this->PreventFolds;
  options.FringeCollapses = this->FringeCollapses == FringeOn ? medialaxis::FringeCollapseMode::On
    : this->FringeCollapses == FringeOff                      ? medialaxis::FringeCollapseMode::Off
                                         : medialaxis::FringeCollapseMode::Automatic;
  options.EulerNeutralSpikeCollapses = this->EulerNeutralSpikeCollapses;
  options.FinalFit = this->FinalFit;
  options.FitIterations = this->FitIterations;
  options.FitSpikeRepair = this->FitSpikeRepair;
  options.FitSheetBoundaryRadii = this->FitSheetBoundaryRadii;
  options.Progress = [this](double f)
  {
    this->UpdateProgress(0.05 + 0.9 * f);
    return !this->GetAbortExecute();
  };
  const medialaxis::AtlasSimplifierResult result = medialaxis::RunWithThreads(this->NumberOfThreads,
    [&] { return medialaxis::SimplifyMedialAxis(std::move(input), rvd, sites, options); });
  if (result.Aborted)
  {
    return 1;
  }

  const medialaxis::AtlasMedialMesh& m = result.Medial;
  medialaxis::MedialMeshToPolyData(m.Mesh, output);
  medialaxis::AddAtlasArrays(output, m.AtlasOffsets, m.AtlasSites);
  vtkNew<vtkUnsignedCharArray> feature;
  feature->SetName("FeatureVertex");
  feature->SetNumberOfTuples(static_cast<vtkIdType>(m.FeatureVertex.size()));
  for (std::size_t v = 0; v < m.FeatureVertex.size(); ++v)
  {
    feature->SetValue(static_cast<vtkIdType>(v), m.FeatureVertex[v]);
  }
  output->GetPointData()->AddArray(feature);
  if (!result.PlacedRadii.empty())
  {
    vtkNew<vtkDoubleArray> placed;
    placed->SetName("PlacedRadius");
    placed->SetNumberOfTuples(static_cast<vtkIdType>(result.PlacedRadii.size()));
    for (std::size_t v = 0; v < result.PlacedRadii.size(); ++v)
    {
      placed->SetValue(static_cast<vtkIdType>(v), result.PlacedRadii[v]);
    }
    output->GetPointData()->AddArray(placed);
  }

  medialaxis::AddStabilityRatios(m.Mesh, output);
  for (const auto& [name, value] :
    { std::pair<const char*, std::size_t>{ "Collapses", result.Collapses },
      { "RejectedCollapses", result.RejectedCollapses },
      { "RelaxedCollapses", result.RelaxedCollapses }, { "MergedFaces", result.MergedFaces },
      { "FinCollapses", result.FinCollapses }, { "ErodedTriangles", result.ErodedTriangles },
      { "EulerNeutralCollapses", result.EulerNeutralCollapses },
      { "SnappedVertices", result.SnappedVertices }, { "ForcedSnaps", result.ForcedSnaps },
      { "FoldingAllowedCollapses", result.FoldingAllowedCollapses },
      { "FoldRepairCollapses", result.FoldRepairCollapses }, { "CollapseBatches", result.Batches },
      { "FringeCollapsesUsed", medialaxis::UsesFringeCollapses(options) ? 1u : 0u },
      { "ErrorBandsUsed", medialaxis::UsesErrorBands(options) ? 1u : 0u },
      { "FitRounds", static_cast<std::size_t>(result.Fit.AcceptedRounds) } })
  {
    medialaxis::AddFieldValue(output, name, static_cast<long long>(value));
  }

  medialaxis::AddFieldDouble(
    output, "QueueInitialisationSeconds", result.QueueInitialisationSeconds);
  medialaxis::AddFieldDouble(output, "FitSeconds", result.FitSeconds);
  medialaxis::AddFieldDouble(output, "ErrorBound", this->ErrorBound);
  medialaxis::AddFieldDouble(output, "FitRMSBefore", result.Fit.InitialRms);
  medialaxis::AddFieldDouble(output, "FitRMSAfter", result.Fit.FinalRms);

  medialaxis::AddCorrespondence(rvdIn, m.AtlasOffsets, m.AtlasSites, sites.size(), rvdOut);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkAtlasMedialAxisSimplifier::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetNumberOfVertices: " << this->TargetNumberOfVertices << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "MaximumCost: " << this->MaximumCost << "\n";
  os << indent << "Lambda: " << this->Lambda << "\n";
  os << indent << "SpikeThreshold: " << this->SpikeThreshold << "\n";
  os << indent << "SpikeSharpness: " << this->SpikeSharpness << "\n";
  os << indent << "TopologyGuardVertexCount: " << this->TopologyGuardVertexCount << "\n";
  os << indent << "StrictTopologyGuard: " << this->StrictTopologyGuard << "\n";
  os << indent << "PreserveSharpFeatures: " << this->PreserveSharpFeatures << "\n";
  os << indent << "InvaginatedTerm: " << this->InvaginatedTerm << "\n";
  os << indent << "ClampRadiiToAtlas: " << this->ClampRadiiToAtlas << "\n";
  os << indent << "AbsorbSpikes: " << this->AbsorbSpikes << "\n";
  os << indent << "ErrorBound: " << this->ErrorBound << "\n";
  os << indent << "ErrorBands: " << this->ErrorBands << "\n";
  os << indent << "HairAngle: " << this->HairAngle << "\n";
  os << indent << "FinBudget: " << this->FinBudget << "\n";
  os << indent << "PleatAngle: " << this->PleatAngle << "\n";
  os << indent << "PreventFolds: " << this->PreventFolds << "\n";
  os << indent << "FringeCollapses: " << this->FringeCollapses << "\n";
  os << indent << "EulerNeutralSpikeCollapses: " << this->EulerNeutralSpikeCollapses << "\n";
  os << indent << "FinalFit: " << this->FinalFit << "\n";
  os << indent << "FitIterations: " << this->FitIterations << "\n";
  os << indent << "FitSpikeRepair: " << this->FitSpikeRepair << "\n";
  os << indent << "FitSheetBoundaryRadii: " << this->FitSheetBoundaryRadii << "\n";
}
