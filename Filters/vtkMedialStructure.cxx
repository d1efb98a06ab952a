// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialStructure.h"

#include "Structure/MedialStructure.h"
#include "Structure/TangentComponents.h"
#include "vtkMedialMeshConversion.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkMedialStructure);

namespace
{
// Field-data names of the type counts, in MedialVertexType order.
const char* const TypeCountNames[medialaxis::NumberOfMedialVertexTypes] = { "NumberOfSheetVertices",
  "NumberOfSeamVertices", "NumberOfJunctionVertices", "NumberOfRimVertices",
  "NumberOfFeatureVertices", "NumberOfFilletVertices", "NumberOfCurveVertices",
  "NumberOfIsolatedVertices" };

// Per-vertex flags from a point-data array (0 / non-zero); empty when absent.
std::string ReadFlags(vtkPolyData* input, const char* name, std::vector<std::uint8_t>& flags)
{
  flags.clear();
  vtkDataArray* a = input->GetPointData()->GetArray(name);
  if (!a)
  {
    return "";
  }
  if (a->GetNumberOfComponents() != 1 || a->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return std::string("point data '") + name +
      "' must have one value per medial vertex (remove it to derive it from the radii)";
  }
  flags.resize(static_cast<std::size_t>(a->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    flags[i] = a->GetComponent(i, 0) != 0.0 ? 1 : 0;
  }
  return "";
}

// The vertices named by the fillet centre lines' `MedialVertexId`.
std::string ReadFilletVertices(vtkPolyData* lines, vtkIdType nv, std::vector<std::uint8_t>& flags)
{
  flags.clear();
  if (!lines || lines->GetNumberOfPoints() == 0)
  {
    return "";
  }
  vtkDataArray* ids = lines->GetPointData()->GetArray("MedialVertexId");
  if (!ids || ids->GetNumberOfComponents() != 1)
  {
    return "the fillet centre lines have no point data 'MedialVertexId' (connect output 0 of "
           "vtkFilletDetector)";
  }
  flags.assign(static_cast<std::size_t>(nv), 0);
  for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
  {
    const double v = ids->GetComponent(i, 0);
    if (!(v >= 0.0 && v < static_cast<double>(nv)))
    {
      return "the fillet centre lines' 'MedialVertexId' " + std::to_string(v) +
        " is not a vertex of the medial mesh (were both made from the same mesh?)";
    }
    flags[static_cast<std::size_t>(v)] = 1;
  }
  return "";
}

// Per medial vertex, the connected pieces of its Atlas' restricted Voronoi
// cells (TangentComponents.h), from the cells on `rvd` (cell data SiteId).
std::string ReadTangentComponents(vtkPolyData* mat, vtkPolyData* rvd, std::vector<int>& count)
{
  count.clear();
  if (!rvd)
  {
    return "";
  }
  std::vector<medialaxis::Index> atlasOffsets, atlasSites;
  std::string problem = medialaxis::GetAtlasArrays(mat, atlasOffsets, atlasSites);
  if (!problem.empty())
  {
    return problem + " (the tangent components need the simplifier's Atlas)";
  }
  if (atlasOffsets.size() != static_cast<std::size_t>(mat->GetNumberOfPoints()) + 1)
  {
    return "the medial mesh's Atlas has " + std::to_string(atlasOffsets.size() - 1) +
      " vertices, the mesh " + std::to_string(mat->GetNumberOfPoints());
  }
  vtkDataArray* siteIds = rvd->GetCellData()->GetArray("SiteId");
  if (!siteIds || siteIds->GetNumberOfComponents() != 1 ||
    siteIds->GetNumberOfTuples() != rvd->GetNumberOfCells())
  {
    return "the restricted Voronoi cells have no cell data 'SiteId' (connect output 1 of "
           "vtkAtlasMedialAxisSimplifier or output 0 of vtkRestrictedVoronoiDiagram)";
  }
  std::vector<medialaxis::Point3> vertices;
  std::vector<medialaxis::Index> offsets{ 0 }, polygonSite;
  medialaxis::Index sites = 0;
  for (medialaxis::Index s : atlasSites)
  {
    sites = std::max(sites, s + 1);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < rvd->GetNumberOfCells(); ++c)
  {
    const double site = siteIds->GetComponent(c, 0);
    if (!(site >= 0.0 && site < 1e15))
    {
      return "the restricted Voronoi cells' 'SiteId' " + std::to_string(site) + " is not a site";
    }
    rvd->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      medialaxis::Point3 p;
      rvd->GetPoint(ids->GetId(k), p.data());
      vertices.push_back(p);
    }
    offsets.push_back(static_cast<medialaxis::Index>(vertices.size()));
    polygonSite.push_back(static_cast<medialaxis::Index>(site));
    sites = std::max(sites, polygonSite.back() + 1);
  }
  double bounds[6];
  rvd->GetBounds(bounds);
  const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
    std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
  const medialaxis::SiteAdjacency adjacency = medialaxis::ComputeSiteAdjacency(
    vertices, offsets, polygonSite, static_cast<std::size_t>(sites), 1e-9 * diagonal);
  count = medialaxis::CountTangentComponents(atlasOffsets, atlasSites, adjacency);
  return "";
}
}

vtkMedialStructure::vtkMedialStructure()
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(2);
}

int vtkMedialStructure::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port > 0)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

vtkIdType vtkMedialStructure::GetNumberOfVerticesOfType(int type) const
{
  return type >= 0 && type < medialaxis::NumberOfMedialVertexTypes ? this->TypeCounts[type] : 0;
}

int vtkMedialStructure::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* fillets = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* cells = vtkPolyData::GetData(inputVector[2]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* seams = vtkPolyData::GetData(outputVector, 1);
  output->Initialize();
  seams->Initialize();
  this->NumberOfSheets = this->NumberOfSeams = this->TypeDisagreements = 0;
  std::fill(std::begin(this->TypeCounts), std::end(this->TypeCounts), 0);

  medialaxis::MedialMesh mesh;
  std::string problem = medialaxis::PolyDataToMedialMesh(input, mesh);
  if (problem.empty())
  {
    problem = medialaxis::ValidateMedialMesh(mesh).Message;
  }
  medialaxis::MedialStructureOptions options;
  options.MinimumSheetFraction = this->MinimumSheetFraction;
  if (problem.empty())
  {
    problem = ReadFlags(input, "FeatureVertex", options.FeatureVertex);
  }
  if (problem.empty())
  {
    problem = ReadFilletVertices(fillets, input->GetNumberOfPoints(), options.FilletVertex);
  }
  std::vector<int> components;
  if (problem.empty())
  {
    problem = ReadTangentComponents(input, cells, components);
    options.TangentComponents = components;
    options.ByTangentComponents = this->ClassifyByTangentComponents;
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< "medial structure: " << problem);
    return 0;
  }
  const medialaxis::MedialStructure s = medialaxis::ClassifyMedialStructure(mesh, options);
  this->UpdateProgress(0.8);

  output->ShallowCopy(input);
  vtkNew<vtkIntArray> type;
  type->SetName("MedialType");
  type->SetNumberOfTuples(static_cast<vtkIdType>(s.VertexType.size()));
  for (std::size_t v = 0; v < s.VertexType.size(); ++v)
  {
    type->SetValue(static_cast<vtkIdType>(v), static_cast<int>(s.VertexType[v]));
  }
  output->GetPointData()->AddArray(type);
  if (!components.empty())
  {
    vtkNew<vtkIntArray> k;
    k->SetName("TangentComponents");
    k->SetNumberOfTuples(static_cast<vtkIdType>(components.size()));
    for (std::size_t v = 0; v < components.size(); ++v)
    {
      k->SetValue(static_cast<vtkIdType>(v), components[v]);
    }
    output->GetPointData()->AddArray(k);
  }
  // Cells: vertices, then lines, then the triangles in the order read.
  vtkNew<vtkIdTypeArray> sheetIds;
  sheetIds->SetName("SheetId");
  sheetIds->SetNumberOfTuples(output->GetNumberOfCells());
  sheetIds->FillValue(-1);
  const vtkIdType firstTriangle = input->GetNumberOfVerts() + input->GetNumberOfLines();
  for (std::size_t f = 0; f < s.FaceSheet.size(); ++f)
  {
    sheetIds->SetValue(firstTriangle + static_cast<vtkIdType>(f), s.FaceSheet[f]);
  }
  output->GetCellData()->AddArray(sheetIds);

  vtkNew<vtkFieldData> fields;
  fields->DeepCopy(input->GetFieldData());
  output->SetFieldData(fields);
  using Sheet = medialaxis::MedialSheet;
  medialaxis::AddFieldPerItem(output, "SheetArea", s.Sheets, [](const Sheet& x) { return x.Area; });
  medialaxis::AddFieldPerItem(
    output, "SheetMeanRadius", s.Sheets, [](const Sheet& x) { return x.MeanRadius; });
  medialaxis::AddFieldPerItem(
    output, "SheetMinimumRadius", s.Sheets, [](const Sheet& x) { return x.MinimumRadius; });
  medialaxis::AddFieldPerItem(
    output, "SheetMaximumRadius", s.Sheets, [](const Sheet& x) { return x.MaximumRadius; });
  medialaxis::AddFieldPerItem(
    output, "SheetTriangles", s.Sheets, [](const Sheet& x) { return x.Triangles; });
  if (!components.empty())
  {
    medialaxis::AddFieldValue(output, "TypeDisagreements", static_cast<long long>(s.Disagreements));
    medialaxis::AddFieldDouble(output, "TangentComponentAgreement",
      s.ComparedVertices > 0
        ? 1.0 - static_cast<double>(s.Disagreements) / static_cast<double>(s.ComparedVertices)
        : 1.0);
  }
  this->TypeDisagreements = static_cast<vtkIdType>(s.Disagreements);
  this->NumberOfSheets = static_cast<vtkIdType>(s.Sheets.size());
  this->NumberOfSeams = static_cast<vtkIdType>(s.NumberOfSeams);
  medialaxis::AddFieldValue(output, "NumberOfSheets", this->NumberOfSheets);
  medialaxis::AddFieldValue(output, "NumberOfSeams", this->NumberOfSeams);
  for (int t = 0; t < medialaxis::NumberOfMedialVertexTypes; ++t)
  {
    this->TypeCounts[t] = static_cast<vtkIdType>(s.TypeCounts[t]);
    medialaxis::AddFieldValue(output, TypeCountNames[t], this->TypeCounts[t]);
  }

  seams->SetPoints(input->GetPoints());
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIdTypeArray> seamIds;
  seamIds->SetName("SeamId");
  for (std::size_t e = 0; e < s.SeamEdges.size(); ++e)
  {
    const vtkIdType ids[2] = { s.SeamEdges[e][0], s.SeamEdges[e][1] };
    lines->InsertNextCell(2, ids);
    seamIds->InsertNextValue(s.SeamOfEdge[e]);
  }
  seams->SetLines(lines);
  seams->GetCellData()->AddArray(seamIds);
  seams->GetCellData()->SetActiveScalars("SeamId");
  medialaxis::AddFieldValue(seams, "NumberOfSeams", this->NumberOfSeams);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialStructure::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSheets: " << this->NumberOfSheets << "\n";
  os << indent << "NumberOfSeams: " << this->NumberOfSeams << "\n";
  os << indent << "MinimumSheetFraction: " << this->MinimumSheetFraction << "\n";
  os << indent << "ClassifyByTangentComponents: " << this->ClassifyByTangentComponents << "\n";
  os << indent << "TypeDisagreements: " << this->TypeDisagreements << "\n";
  for (int t = 0; t < medialaxis::NumberOfMedialVertexTypes; ++t)
  {
    os << indent << TypeCountNames[t] << ": " << this->TypeCounts[t] << "\n";
  }
}
