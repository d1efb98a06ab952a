// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialSkeletalDiagram.h"

#include "Skeletal/PrimitiveUnion.h"
#include "Skeletal/SkeletalDiagram.h"
#include "vtkDistanceGridContour.h"
#include "vtkMedialMeshConversion.h"
#include "vtkPrimitiveCollection.h"
#include "vtkSurfacePreparation.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialSkeletalDiagram);

vtkMedialSkeletalDiagram::vtkMedialSkeletalDiagram()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
}

vtkPolyData* vtkMedialSkeletalDiagram::GetSkeleton()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(0));
}

vtkPartitionedDataSetCollection* vtkMedialSkeletalDiagram::GetPrimitives()
{
  return vtkPartitionedDataSetCollection::SafeDownCast(this->GetOutputDataObject(1));
}

vtkPolyData* vtkMedialSkeletalDiagram::GetReconstruction()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(2));
}

int vtkMedialSkeletalDiagram::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialSkeletalDiagram::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(
    vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkPartitionedDataSetCollection" : "vtkPolyData");
  return 1;
}

vtkTypeBool vtkMedialSkeletalDiagram::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkMedialSkeletalDiagram::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surfaceIn = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* medialIn = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* skeleton = vtkPolyData::GetData(outputVector, 0);
  auto* primitives = vtkPartitionedDataSetCollection::GetData(outputVector, 1);
  vtkPolyData* reconstruction = vtkPolyData::GetData(outputVector, 2);
  skeleton->Initialize();
  primitives->Initialize();
  reconstruction->Initialize();
  this->ReachedError = 0.0;
  this->NumberOfElements = 0;

  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(surfaceIn, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "input port 0: " << report.Error);
    return 0;
  }
  medialaxis::MedialMesh medial;
  std::string problem = medialIn ? medialaxis::PolyDataToMedialMesh(medialIn, medial)
                                 : "no medial mesh (connect the surface's simplified MAT)";
  if (problem.empty())
  {
    problem = medialaxis::ValidateMedialMesh(medial).Message;
  }
  if (problem.empty() && medial.NumberOfVertices() == 0)
  {
    problem = "the medial mesh is empty";
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< "input port 1: " << problem);
    return 0;
  }

  medialaxis::SkeletalDiagramOptions options;
  options.MaximumError = this->MaximumError;
  options.MaximumElements = this->MaximumElements;
  options.InitialSites = this->InitialSites;
  options.AngularResolution = this->AngularResolution;
  options.VertexSubdivisions = this->VertexSubdivisions;
  options.Spacing = this->Spacing;
  options.Fit.ExactRadii = this->ExactRadii;
  options.Progress = [this](double amount)
  {
    this->UpdateProgress((this->Reconstruct ? 0.6 : 0.95) * amount);
    return !this->GetAbortExecute();
  };
  const medialaxis::SkeletalDiagram diagram =
    medialaxis::BuildSkeletalDiagram(surface, medial, options);

  // The skeleton: its vertices, then the bends of its edges; an edge is a
  // polyline through its bends.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> vertexIds;
  vertexIds->SetName("MedialVertexId");
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(medialaxis::RadiusArrayName);
  auto addPoint = [&](medialaxis::Index medialVertex)
  {
    vertexIds->InsertNextValue(medialVertex);
    radius->InsertNextValue(medial.Radii[medialVertex]);
    return points->InsertNextPoint(medial.Centers[medialVertex].data());
  };
  for (medialaxis::Index site : diagram.Sites)
  {
    addPoint(site);
  }
  vtkNew<vtkCellArray> lines, triangles;
  for (std::size_t e = 0; e < diagram.Edges.size(); ++e)
  {
    std::vector<vtkIdType> ids = { diagram.Edges[e][0] };
    for (medialaxis::Index bend : diagram.EdgeBends[e])
    {
      ids.push_back(addPoint(bend));
    }
    ids.push_back(diagram.Edges[e][1]);
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  for (const auto& t : diagram.Triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  skeleton->SetPoints(points);
  skeleton->SetLines(lines);
  skeleton->SetPolys(triangles);
  skeleton->GetPointData()->AddArray(vertexIds);
  skeleton->GetPointData()->AddArray(radius);
  skeleton->GetPointData()->SetActiveScalars(medialaxis::RadiusArrayName);
  const double diagonal = diagram.Diagonal > 0.0 ? diagram.Diagonal : 1.0;
  medialaxis::AddFieldValue(skeleton, "Vertices", static_cast<long long>(diagram.Points.size()));
  medialaxis::AddFieldDouble(skeleton, "Error", diagram.Error / diagonal);
  medialaxis::AddFieldDouble(skeleton, "MeanError", diagram.MeanError / diagonal);
  medialaxis::AddFieldValue(skeleton, "Insertions", diagram.Insertions);
  medialaxis::AddFieldValue(skeleton, "FailedElements", diagram.FailedElements);
  medialaxis::AddFieldValue(skeleton, "OmittedTriangles", diagram.OmittedTriangles);
  medialaxis::AddFieldValue(
    skeleton, "ContinuousParameters", static_cast<long long>(diagram.ContinuousParameters()));

  // One partitioned dataset per element; a bent edge's primitive is its
  // pieces' meshes, one closed shell each, in one polydata.
  const std::size_t elements = diagram.NumberOfElements();
  std::vector<std::vector<vtkSmartPointer<vtkPolyData>>> pieces(elements);
  for (std::size_t k = 0; k < diagram.Primitives.size(); ++k)
  {
    pieces[diagram.PieceElement[k]].push_back(
      medialaxis::PrimitiveMesh(diagram.Templates[k], diagram.Primitives[k]));
  }
  primitives->SetNumberOfPartitionedDataSets(static_cast<unsigned int>(elements));
  for (std::size_t e = 0; e < elements; ++e)
  {
    const std::size_t vertices = diagram.Points.size(), edges = diagram.Edges.size();
    medialaxis::SkeletalElement type;
    vtkIdType id;
    std::string name;
    if (e < vertices)
    {
      type = medialaxis::SkeletalElement::Vertex;
      id = static_cast<vtkIdType>(e);
      name = "vertex " + std::to_string(e);
    }
    else if (e < vertices + edges)
    {
      type = medialaxis::SkeletalElement::Edge;
      id = static_cast<vtkIdType>(e - vertices);
      const auto& edge = diagram.Edges[e - vertices];
      name = "edge " + std::to_string(edge[0]) + "-" + std::to_string(edge[1]);
    }
    else
    {
      type = medialaxis::SkeletalElement::Triangle;
      id = static_cast<vtkIdType>(e - vertices - edges);
      name = "triangle " + std::to_string(id);
    }
    vtkSmartPointer<vtkPolyData> mesh = pieces[e].size() == 1 ? pieces[e][0] : nullptr;
    if (!mesh)
    {
      vtkNew<vtkAppendPolyData> append;
      for (vtkPolyData* piece : pieces[e])
      {
        if (piece->GetNumberOfCells() > 0)
        {
          append->AddInputData(piece);
        }
      }
      mesh = vtkSmartPointer<vtkPolyData>::New();
      if (append->GetNumberOfInputConnections(0) > 0)
      {
        append->Update();
        mesh->ShallowCopy(append->GetOutput());
      }
    }
    medialaxis::SetPrimitive(primitives, static_cast<unsigned int>(e), mesh, type, id, name);
  }
  if (this->Reconstruct && !diagram.Aborted)
  {
    std::vector<medialaxis::TriangleMesh> pieces;
    for (std::size_t e = 0; e < diagram.Primitives.size(); ++e)
    {
      pieces.push_back(medialaxis::PrimitiveSurface(diagram.Templates[e], diagram.Primitives[e]));
    }
    const medialaxis::PrimitiveUnion united(pieces);
    if (!united.Empty())
    {
      const medialaxis::Box& b = united.Bounds();
      const double spacing = std::max({ b.Hi[0] - b.Lo[0], b.Hi[1] - b.Lo[1], b.Hi[2] - b.Lo[2] }) /
        this->ReconstructionResolution;
      const medialaxis::DistanceGrid grid = medialaxis::SamplePrimitiveUnion(united, spacing,
        [this](double f)
        {
          this->UpdateProgress(0.6 + 0.35 * f);
          return !this->GetAbortExecute();
        });
      if (grid.Aborted)
      {
        return 1;
      }
      medialaxis::TriangleMesh contour = medialaxis::ContourDistanceGrid(grid);
      // A part of the union the grid cuts off from the skeleton's vertices
      // (the middle of an edge's thin primitive) still holds some of its
      // element.
      medialaxis::KeepComponentsAroundSkeleton(contour, medialaxis::ElementPoints(diagram, 16));
      medialaxis::TriangleMeshToPolyData(contour, reconstruction);
      medialaxis::AddFieldDouble(reconstruction, "GridSpacing", spacing);
    }
  }
  this->ReachedError = diagram.Error / diagonal;
  this->NumberOfElements = static_cast<vtkIdType>(diagram.NumberOfElements());
  if (diagram.FailedElements > 0)
  {
    vtkWarningMacro(<< diagram.FailedElements << " of " << diagram.NumberOfElements()
                    << " skeletal elements leave the surface and have no primitive (medial "
                       "vertices outside the surface on every route: is the medial mesh that of "
                       "this surface?)");
  }
  if (diagram.Error > options.MaximumError * diagonal && !diagram.Aborted)
  {
    vtkWarningMacro(<< "the surface lies up to " << 100.0 * diagram.Error / diagonal
                    << "% of the diagonal from the primitives, more than MaximumError ("
                    << 100.0 * options.MaximumError << "%), with " << diagram.NumberOfElements()
                    << " elements: raise MaximumElements to add sites");
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialSkeletalDiagram::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "MaximumElements: " << this->MaximumElements << "\n";
  os << indent << "InitialSites: " << this->InitialSites << "\n";
  os << indent << "AngularResolution: " << this->AngularResolution << "\n";
  os << indent << "VertexSubdivisions: " << this->VertexSubdivisions << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "ExactRadii: " << this->ExactRadii << "\n";
  os << indent << "Reconstruct: " << this->Reconstruct << "\n";
  os << indent << "ReconstructionResolution: " << this->ReconstructionResolution << "\n";
  os << indent << "ReachedError: " << this->ReachedError << "\n";
  os << indent << "NumberOfElements: " << this->NumberOfElements << "\n";
}
