// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkRestrictedVoronoiDiagram.h"

#include "Support/Parallel.h"
#include "Voronoi/RestrictedVoronoi.h"
#include "vtkSurfacePreparation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <limits>

vtkStandardNewMacro(vtkRestrictedVoronoiDiagram);

namespace
{
// The polygons' offsets and connectivity (each polygon has its own points,
// in order) in `Ids`, vtkTypeInt32Array or vtkTypeInt64Array.
template <typename Ids>
void FillPolygonCells(
  const medialaxis::RestrictedVoronoiDiagram& rvd, Ids* offsets, Ids* connectivity)
{
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(rvd.Offsets.size()));
  std::copy(rvd.Offsets.begin(), rvd.Offsets.end(), offsets->GetPointer(0));
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(rvd.Vertices.size()));
  for (vtkIdType v = 0; v < connectivity->GetNumberOfTuples(); ++v)
  {
    connectivity->SetValue(v, static_cast<typename Ids::ValueType>(v));
  }
}
}

vtkRestrictedVoronoiDiagram::vtkRestrictedVoronoiDiagram()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

int vtkRestrictedVoronoiDiagram::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkPointSet");
  return 1;
}

int vtkRestrictedVoronoiDiagram::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPointSet* sitesIn = vtkPointSet::GetData(inputVector[1]);
  vtkPolyData* rvdOut = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* sitesOut = vtkPolyData::GetData(outputVector, 1);
  rvdOut->Initialize();
  sitesOut->Initialize();

  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(input, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "cannot compute the restricted Voronoi diagram: " << report.Error);
    return 0;
  }
  if (!sitesIn || sitesIn->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "no sites on input port 1: connect the output of a sampler");
    return 0;
  }
  const vtkIdType ns = sitesIn->GetNumberOfPoints();
  std::vector<medialaxis::Point3> sites(static_cast<std::size_t>(ns));
  for (vtkIdType i = 0; i < ns; ++i)
  {
    sitesIn->GetPoint(i, sites[i].data());
    if (!(std::isfinite(sites[i][0]) && std::isfinite(sites[i][1]) && std::isfinite(sites[i][2])))
    {
      vtkErrorMacro(<< "site " << i << " has NaN or infinite coordinates");
      return 0;
    }
  }

  medialaxis::RestrictedVoronoiOptions options;
  options.FeatureAngle = vtkMath::RadiansFromDegrees(this->FeatureAngle);
  options.FeatureNormalFiltering = this->FeatureNormalFiltering;
  options.Progress = [this](double f)
  {
    this->UpdateProgress(0.05 + 0.85 * f);
    return !this->GetAbortExecute();
  };
  const medialaxis::RestrictedVoronoiDiagram rvd = medialaxis::RunWithThreads(this->NumberOfThreads,
    [&] { return medialaxis::ComputeRestrictedVoronoi(surface, sites, options); });
  if (rvd.Aborted)
  {
    return 1;
  }

  // Port 0: the polygons.
  const vtkIdType np = static_cast<vtkIdType>(rvd.NumberOfPolygons());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(rvd.Vertices.size()));
  for (std::size_t v = 0; v < rvd.Vertices.size(); ++v)
  {
    points->SetPoint(static_cast<vtkIdType>(v), rvd.Vertices[v].data());
  }
  // 32-bit cell storage where the ids fit: half the room of vtkIdType for
  // the largest array the pipeline hands on (3.3 million polygon vertices on
  // a 268,686-triangle surface at 50,000 samples).
  vtkNew<vtkCellArray> polys;
  if (rvd.Vertices.size() < static_cast<std::size_t>(std::numeric_limits<vtkTypeInt32>::max()))
  {
    vtkNew<vtkTypeInt32Array> offsets, connectivity;
    FillPolygonCells(rvd, offsets.GetPointer(), connectivity.GetPointer());
    polys->SetData(offsets, connectivity);
  }
  else
  {
    vtkNew<vtkTypeInt64Array> offsets, connectivity;
    FillPolygonCells(rvd, offsets.GetPointer(), connectivity.GetPointer());
    polys->SetData(offsets, connectivity);
  }
  vtkNew<vtkIdTypeArray> siteIds, triangleIds;
  siteIds->SetName("SiteId");
  siteIds->SetNumberOfTuples(np);
  std::copy(rvd.PolygonSite.begin(), rvd.PolygonSite.end(), siteIds->GetPointer(0));
  triangleIds->SetName("TriangleId");
  triangleIds->SetNumberOfTuples(np);
  std::copy(rvd.PolygonTriangle.begin(), rvd.PolygonTriangle.end(), triangleIds->GetPointer(0));
  rvdOut->SetPoints(points);
  rvdOut->SetPolys(polys);
  rvdOut->GetCellData()->AddArray(siteIds);
  rvdOut->GetCellData()->SetActiveScalars("SiteId");
  rvdOut->GetCellData()->AddArray(triangleIds);

  // The per-site values the simplifier needs travel with the polygons too,
  // as field data, so that the RVD alone describes every cell.
  {
    vtkNew<vtkDoubleArray> positions;
    positions->SetName("SitePositions");
    positions->SetNumberOfComponents(3);
    positions->SetNumberOfTuples(ns);
    vtkNew<vtkUnsignedCharArray> convexSites, concaveSites;
    convexSites->SetName("SiteConvexFeature");
    convexSites->SetNumberOfTuples(ns);
    concaveSites->SetName("SiteConcaveFeature");
    concaveSites->SetNumberOfTuples(ns);
    for (vtkIdType i = 0; i < ns; ++i)
    {
      positions->SetTypedTuple(i, sites[i].data());
      convexSites->SetValue(i, rvd.ConvexFeature[i]);
      concaveSites->SetValue(i, rvd.ConcaveFeature[i]);
    }
    rvdOut->GetFieldData()->AddArray(positions);
    rvdOut->GetFieldData()->AddArray(convexSites);
    rvdOut->GetFieldData()->AddArray(concaveSites);
  }

  // Port 1: the sites with per-cell values.
  sitesOut->SetPoints(sitesIn->GetPoints());
  sitesOut->GetPointData()->PassData(sitesIn->GetPointData());
  if (auto* sitesPoly = vtkPolyData::SafeDownCast(sitesIn))
  {
    sitesOut->SetVerts(sitesPoly->GetVerts());
  }
  vtkNew<vtkDoubleArray> area, reach, centroid;
  area->SetName("CellArea");
  area->SetNumberOfTuples(ns);
  reach->SetName("CellRadius");
  reach->SetNumberOfTuples(ns);
  centroid->SetName("CellCentroid");
  centroid->SetNumberOfComponents(3);
  centroid->SetNumberOfTuples(ns);
  vtkNew<vtkUnsignedCharArray> convex, concave;
  convex->SetName("ConvexFeature");
  convex->SetNumberOfTuples(ns);
  concave->SetName("ConcaveFeature");
  concave->SetNumberOfTuples(ns);
  vtkNew<vtkIntArray> components;
  components->SetName("CellComponents");
  components->SetNumberOfTuples(ns);
  for (vtkIdType i = 0; i < ns; ++i)
  {
    area->SetValue(i, rvd.CellArea[i]);
    reach->SetValue(i, rvd.CellRadius[i]);
    centroid->SetTypedTuple(i, rvd.CellCentroid[i].data());
    convex->SetValue(i, rvd.ConvexFeature[i]);
    concave->SetValue(i, rvd.ConcaveFeature[i]);
    components->SetValue(i, rvd.CellComponents[i]);
  }
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(area), static_cast<vtkDataArray*>(reach),
         static_cast<vtkDataArray*>(centroid), static_cast<vtkDataArray*>(convex),
         static_cast<vtkDataArray*>(concave), static_cast<vtkDataArray*>(components) })
  {
    sitesOut->GetPointData()->AddArray(a);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkRestrictedVoronoiDiagram::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "FeatureNormalFiltering: " << this->FeatureNormalFiltering << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
