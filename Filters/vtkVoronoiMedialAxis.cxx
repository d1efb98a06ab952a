// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkVoronoiMedialAxis.h"

#include "Support/Parallel.h"
#include "Voronoi/VoronoiMedialAxis.h"
#include "vtkMedialMeshConversion.h"
#include "vtkSurfacePreparation.h"

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
#include "vtkPointSet.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkVoronoiMedialAxis);

vtkVoronoiMedialAxis::vtkVoronoiMedialAxis()
{
  this->SetNumberOfInputPorts(2);
}

int vtkVoronoiMedialAxis::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkPointSet");
  return 1;
}

int vtkVoronoiMedialAxis::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPointSet* sitesIn = vtkPointSet::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();

  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(input, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "cannot compute the medial axis: " << report.Error);
    return 0;
  }
  if (!sitesIn || sitesIn->GetNumberOfPoints() < 4)
  {
    vtkErrorMacro(<< "input port 1 needs at least 4 sites (got "
                  << (sitesIn ? sitesIn->GetNumberOfPoints() : 0)
                  << "): connect the sites output of vtkRestrictedVoronoiDiagram");
    return 0;
  }
  const vtkIdType ns = sitesIn->GetNumberOfPoints();
  std::vector<medialaxis::Point3> sites(static_cast<std::size_t>(ns));
  std::vector<medialaxis::Index> siteTriangles;
  for (vtkIdType i = 0; i < ns; ++i)
  {
    sitesIn->GetPoint(i, sites[i].data());
    if (!(std::isfinite(sites[i][0]) && std::isfinite(sites[i][1]) && std::isfinite(sites[i][2])))
    {
      vtkErrorMacro(<< "site " << i << " has NaN or infinite coordinates");
      return 0;
    }
  }
  // The sampler's TriangleId saves a nearest-triangle search per site.
  if (vtkDataArray* t = sitesIn->GetPointData()->GetArray("TriangleId"))
  {
    siteTriangles.resize(sites.size());
    for (vtkIdType i = 0; i < ns; ++i)
    {
      siteTriangles[i] = static_cast<medialaxis::Index>(t->GetComponent(i, 0));
    }
  }
  std::vector<std::uint8_t> concave;
  if (vtkDataArray* c = sitesIn->GetPointData()->GetArray("ConcaveFeature"))
  {
    concave.resize(sites.size());
    for (vtkIdType i = 0; i < ns; ++i)
    {
      concave[i] = c->GetComponent(i, 0) != 0.0 ? 1 : 0;
    }
  }
  else if (this->ConcaveFiltering)
  {
    vtkWarningMacro(<< "the sites have no 'ConcaveFeature' array: concave filtering skipped "
                       "(connect the sites output of vtkRestrictedVoronoiDiagram)");
  }

  medialaxis::VoronoiMedialAxisOptions options;
  // The restricted Voronoi diagram's cell radii bound the distance from any
  // surface point to the sites: the repair then skips provably inside edges.
  if (vtkDataArray* r = sitesIn->GetPointData()->GetArray("CellRadius"))
  {
    for (vtkIdType i = 0; i < ns; ++i)
    {
      options.CoveringRadius = std::max(options.CoveringRadius, r->GetComponent(i, 0));
    }
  }
  options.ConcaveFiltering = this->ConcaveFiltering;
  options.RepairThinParts = this->RepairThinParts;
  options.RepairTopology = this->RepairTopology;
  options.ConcaveFilterAlpha = this->ConcaveFilterAlpha;
  options.RelativeWeldTolerance = this->RelativeWeldTolerance;
  options.Progress = [this](double f)
  {
    this->UpdateProgress(0.05 + 0.9 * f);
    return !this->GetAbortExecute();
  };
  const medialaxis::VoronoiMedialAxisResult result = medialaxis::RunWithThreads(
    this->NumberOfThreads,
    [&] {
      return medialaxis::ComputeVoronoiMedialAxis(surface, sites, siteTriangles, concave, options);
    });
  if (result.Aborted)
  {
    return 1;
  }

  medialaxis::MedialMeshToPolyData(result.Mesh, output);
  medialaxis::AddAtlasArrays(output, result.AtlasOffsets, result.AtlasSites);
  vtkNew<vtkIdTypeArray> sitePair;
  sitePair->SetName("SitePair");
  sitePair->SetNumberOfComponents(2);
  sitePair->SetNumberOfTuples(output->GetNumberOfCells());
  const vtkIdType others = output->GetNumberOfVerts() + output->GetNumberOfLines();
  for (vtkIdType c = 0; c < others; ++c)
  {
    sitePair->SetTypedComponent(c, 0, -1);
    sitePair->SetTypedComponent(c, 1, -1);
  }
  for (std::size_t f = 0; f < result.FaceSitePair.size(); ++f)
  {
    sitePair->SetTypedComponent(others + static_cast<vtkIdType>(f), 0, result.FaceSitePair[f][0]);
    sitePair->SetTypedComponent(others + static_cast<vtkIdType>(f), 1, result.FaceSitePair[f][1]);
  }
  output->GetCellData()->AddArray(sitePair);
  if (result.SiteClearance.size() == result.Mesh.Centers.size())
  {
    vtkNew<vtkDoubleArray> clearance;
    clearance->SetName("SiteClearance");
    clearance->SetNumberOfTuples(static_cast<vtkIdType>(result.SiteClearance.size()));
    for (std::size_t v = 0; v < result.SiteClearance.size(); ++v)
    {
      clearance->SetValue(static_cast<vtkIdType>(v), result.SiteClearance[v]);
    }
    output->GetPointData()->AddArray(clearance);
  }
  for (const auto& [name, value] :
    { std::pair<const char*, std::size_t>{ "DelaunayCells", result.DelaunayCells },
      { "InsideCells", result.InsideCells },
      { "AmbiguousInsideTests", result.AmbiguousInsideTests },
      { "WeldedCells", result.WeldedCells }, { "FilteredTriangles", result.FilteredFaces },
      { "DroppedPockets", result.DroppedPockets }, { "SpanningCells", result.SpanningCells },
      { "OpenedVoids", result.OpenedVoids }, { "EdgesAcrossSurface", result.EdgesAcrossSurface },
      { "JoinedPieces", result.JoinedPieces }, { "CutLoops", result.CutLoops },
      { "FilledHoles", result.FilledHoles }, { "MissingLoops", result.MissingLoops } })
  {
    medialaxis::AddFieldValue(output, name, static_cast<long long>(value));
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkVoronoiMedialAxis::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ConcaveFiltering: " << this->ConcaveFiltering << "\n";
  os << indent << "RepairThinParts: " << this->RepairThinParts << "\n";
  os << indent << "RepairTopology: " << this->RepairTopology << "\n";
  os << indent << "ConcaveFilterAlpha: " << this->ConcaveFilterAlpha << "\n";
  os << indent << "RelativeWeldTolerance: " << this->RelativeWeldTolerance << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
