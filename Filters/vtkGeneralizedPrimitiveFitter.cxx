// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkGeneralizedPrimitiveFitter.h"

#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Skeletal/PrimitiveFit.h"
#include "Skeletal/PrimitiveTemplate.h"
#include "vtkPrimitiveCollection.h"
#include "vtkSurfacePreparation.h"

#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkGeneralizedPrimitiveFitter);

namespace
{
struct Element
{
  medialaxis::SkeletalElement Type;
  vtkIdType Id; // point id, edge number or cell id
  std::array<medialaxis::Point3, 3> Corners;
  std::string Name;
};

}

vtkGeneralizedPrimitiveFitter::vtkGeneralizedPrimitiveFitter()
{
  this->SetNumberOfInputPorts(2);
}

int vtkGeneralizedPrimitiveFitter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkGeneralizedPrimitiveFitter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surfaceIn = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* skeleton = vtkPolyData::GetData(inputVector[1]);
  vtkPartitionedDataSetCollection* output = vtkPartitionedDataSetCollection::GetData(outputVector);
  output->Initialize();
  this->NumberOfFailedElements = 0;
  if (!skeleton)
  {
    vtkErrorMacro(<< "input port 1: no skeleton (connect a simplified medial mesh or any "
                     "vtkPolyData of vertices, lines and triangles)");
    return 0;
  }
  medialaxis::TriangleMesh surface;
  const auto report = medialaxis::PrepareSurfaceMesh(surfaceIn, surface);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "input port 0: " << report.Error);
    return 0;
  }

  // The elements: every point, every distinct edge of the lines and
  // triangles, every triangle.
  std::vector<Element> elements;
  auto point = [&](vtkIdType id)
  {
    double p[3];
    skeleton->GetPoint(id, p);
    return medialaxis::Point3{ p[0], p[1], p[2] };
  };
  for (vtkIdType id = 0; id < skeleton->GetNumberOfPoints(); ++id)
  {
    elements.push_back({ medialaxis::SkeletalElement::Vertex, id, { point(id), {}, {} },
      "vertex " + std::to_string(id) });
  }
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  std::vector<vtkIdType> triangles;
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < skeleton->GetNumberOfCells(); ++cell)
  {
    skeleton->GetCellPoints(cell, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    const int type = skeleton->GetCellType(cell);
    if (type == VTK_LINE || type == VTK_POLY_LINE)
    {
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        edges.insert(std::minmax(ids->GetId(k), ids->GetId(k + 1)));
      }
    }
    else if (type == VTK_TRIANGLE)
    {
      for (vtkIdType k = 0; k < 3; ++k)
      {
        edges.insert(std::minmax(ids->GetId(k), ids->GetId((k + 1) % 3)));
      }
      triangles.push_back(cell);
    }
    else if (n > 1)
    {
      vtkErrorMacro(<< "input port 1: cell " << cell
                    << " is neither a vertex, a line nor a triangle (triangulate the skeleton)");
      return 0;
    }
  }
  vtkIdType edgeNumber = 0;
  for (const auto& [a, b] : edges)
  {
    if (a == b)
    {
      continue;
    }
    elements.push_back({ medialaxis::SkeletalElement::Edge, edgeNumber++,
      { point(a), point(b), {} }, "edge " + std::to_string(a) + "-" + std::to_string(b) });
  }
  for (vtkIdType cell : triangles)
  {
    skeleton->GetCellPoints(cell, ids);
    elements.push_back({ medialaxis::SkeletalElement::Triangle, cell,
      { point(ids->GetId(0)), point(ids->GetId(1)), point(ids->GetId(2)) },
      "triangle " + std::to_string(cell) });
  }

  const auto box = medialaxis::BoundingBox(surface.Points);
  double diagonal2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    diagonal2 += (box.second[k] - box.first[k]) * (box.second[k] - box.first[k]);
  }
  const double spacing = this->Spacing * std::sqrt(diagonal2);
  const medialaxis::TriangleLocator locator(surface);
  medialaxis::PrimitiveFitOptions options;
  options.Smoothness = this->Smoothness;
  options.Progressions = this->Progressions;
  options.RefinementTolerance = this->RefinementTolerance * std::sqrt(diagonal2);
  options.ExactRadii = this->ExactRadii;
  std::vector<vtkSmartPointer<vtkPolyData>> meshes(elements.size());
  std::vector<std::string> errors(elements.size());
  const int around = this->AngularResolution;
  const int subdivisions = this->VertexSubdivisions;
  auto fitRange = [&](const tbb::blocked_range<std::size_t>& range)
  {
    for (std::size_t e = range.begin(); e != range.end(); ++e)
    {
      const Element& element = elements[e];
      medialaxis::PrimitiveTemplate shape;
      try
      {
        shape = medialaxis::MakeElementTemplate(
          element.Type, element.Corners, subdivisions, around, spacing);
      }
      catch (const std::invalid_argument& error)
      {
        errors[e] = error.what();
        meshes[e] = vtkSmartPointer<vtkPolyData>::New();
        continue;
      }
      const medialaxis::FittedPrimitive fit =
        medialaxis::FitPrimitiveRefined(surface, locator, shape, options);
      errors[e] = fit.Error;
      meshes[e] = PrimitiveMesh(shape, fit);
    }
  };
  // Each primitive on its own, in parallel (the result does not depend on
  // the threads), a block at a time for progress and abort.
  const std::size_t block = 64;
  for (std::size_t first = 0; first < elements.size(); first += block)
  {
    const std::size_t last = std::min(elements.size(), first + block);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 1), fitRange);
    this->UpdateProgress(0.95 * static_cast<double>(last) / static_cast<double>(elements.size()));
    if (this->GetAbortExecute())
    {
      return 1;
    }
  }

  output->SetNumberOfPartitionedDataSets(static_cast<unsigned int>(elements.size()));
  std::ostringstream failures;
  for (std::size_t e = 0; e < elements.size(); ++e)
  {
    medialaxis::SetPrimitive(output, static_cast<unsigned int>(e), meshes[e], elements[e].Type,
      elements[e].Id, elements[e].Name);
    if (!errors[e].empty())
    {
      if (this->NumberOfFailedElements < 3)
      {
        failures << (this->NumberOfFailedElements ? "; " : "") << elements[e].Name << ": "
                 << errors[e];
      }
      ++this->NumberOfFailedElements;
    }
  }
  if (this->NumberOfFailedElements > 0)
  {
    vtkWarningMacro(<< this->NumberOfFailedElements << " of " << elements.size()
                    << " skeletal elements have no primitive (" << failures.str()
                    << (this->NumberOfFailedElements > 3 ? "; ..." : "")
                    << "): move them inside the surface");
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkGeneralizedPrimitiveFitter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AngularResolution: " << this->AngularResolution << "\n";
  os << indent << "VertexSubdivisions: " << this->VertexSubdivisions << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "Smoothness: " << this->Smoothness << "\n";
  os << indent << "Progressions: " << this->Progressions << "\n";
  os << indent << "RefinementTolerance: " << this->RefinementTolerance << "\n";
  os << indent << "ExactRadii: " << this->ExactRadii << "\n";
  os << indent << "NumberOfFailedElements: " << this->NumberOfFailedElements << "\n";
}
