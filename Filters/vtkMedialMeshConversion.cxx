// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialMeshConversion.h"

#include "Geometry/Vec3.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

namespace medialaxis
{
void MedialMeshToPolyData(const MedialMesh& mesh, vtkPolyData* output)
{
  const vtkIdType nv = static_cast<vtkIdType>(mesh.Centers.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(RadiusArrayName);
  radius->SetNumberOfTuples(nv);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    points->SetPoint(i, mesh.Centers[i].data());
    radius->SetValue(i, mesh.Radii[i]);
  }

  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(
    static_cast<vtkIdType>(mesh.Faces.size()), 3 * static_cast<vtkIdType>(mesh.Faces.size()));
  for (const auto& f : mesh.Faces)
  {
    const vtkIdType ids[3] = { f[0], f[1], f[2] };
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkCellArray> lines;
  for (const auto& e : EdgesNotOnFaces(mesh))
  {
    const vtkIdType ids[2] = { e[0], e[1] };
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkCellArray> verts;
  for (Index i : IsolatedVertices(mesh))
  {
    const vtkIdType id = i;
    verts->InsertNextCell(1, &id);
  }

  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(polys);
  output->SetLines(lines);
  output->SetVerts(verts);
  output->GetPointData()->SetScalars(radius);
}

void AddFieldValue(vtkPolyData* output, const char* name, long long value)
{
  vtkNew<vtkIdTypeArray> a;
  a->SetName(name);
  a->InsertNextValue(static_cast<vtkIdType>(value));
  output->GetFieldData()->AddArray(a);
}

void AddFieldDouble(vtkPolyData* output, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  output->GetFieldData()->AddArray(a);
}

double GetFieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetComponent(0, 0) : 0.0;
}

void AddFieldArray(vtkPolyData* output, const char* name, const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    a->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  output->GetFieldData()->AddArray(a);
}

void AddAtlasArrays(
  vtkPolyData* output, const std::vector<Index>& offsets, const std::vector<Index>& sites)
{
  vtkNew<vtkIdTypeArray> siteArray, offsetArray, count;
  siteArray->SetName("AtlasSites");
  siteArray->SetNumberOfTuples(static_cast<vtkIdType>(sites.size()));
  std::copy(sites.begin(), sites.end(), siteArray->GetPointer(0));
  offsetArray->SetName("AtlasOffsets");
  offsetArray->SetNumberOfTuples(static_cast<vtkIdType>(offsets.size()));
  std::copy(offsets.begin(), offsets.end(), offsetArray->GetPointer(0));
  count->SetName("AtlasCount");
  count->SetNumberOfTuples(static_cast<vtkIdType>(offsets.size()) - 1);
  for (std::size_t v = 0; v + 1 < offsets.size(); ++v)
  {
    count->SetValue(static_cast<vtkIdType>(v), offsets[v + 1] - offsets[v]);
  }
  output->GetFieldData()->AddArray(siteArray);
  output->GetFieldData()->AddArray(offsetArray);
  output->GetPointData()->AddArray(count);
}

std::string GetAtlasArrays(
  vtkPolyData* input, std::vector<Index>& offsets, std::vector<Index>& sites)
{
  offsets.clear();
  sites.clear();
  vtkDataArray* siteArray = input->GetFieldData()->GetArray("AtlasSites");
  vtkDataArray* offsetArray = input->GetFieldData()->GetArray("AtlasOffsets");
  if (!siteArray || !offsetArray)
  {
    return "medial mesh has no Atlas (field data 'AtlasSites' and 'AtlasOffsets'): "
           "compute it with vtkVoronoiMedialAxis";
  }
  const vtkIdType nv = input->GetNumberOfPoints();
  if (offsetArray->GetNumberOfTuples() != nv + 1)
  {
    return "'AtlasOffsets' has " + std::to_string(offsetArray->GetNumberOfTuples()) +
      " values for " + std::to_string(nv) + " vertices (expected one more)";
  }
  offsets.resize(static_cast<std::size_t>(nv + 1));
  for (vtkIdType i = 0; i <= nv; ++i)
  {
    offsets[i] = static_cast<Index>(offsetArray->GetComponent(i, 0));
    if (offsets[i] < 0 || offsets[i] > siteArray->GetNumberOfTuples() ||
      (i > 0 && offsets[i] < offsets[i - 1]))
    {
      offsets.clear();
      return "'AtlasOffsets' is not a non-decreasing list within 'AtlasSites'";
    }
  }
  sites.resize(static_cast<std::size_t>(siteArray->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < siteArray->GetNumberOfTuples(); ++i)
  {
    sites[i] = static_cast<Index>(siteArray->GetComponent(i, 0));
  }
  return std::string();
}

std::string PolyDataToMedialMesh(vtkPolyData* input, MedialMesh& mesh)
{
  mesh = MedialMesh();
  if (!input)
  {
    return "no medial mesh given";
  }
  const vtkIdType nv = input->GetNumberOfPoints();
  vtkDataArray* radius = input->GetPointData()->GetArray(RadiusArrayName);
  if (nv > 0 && !radius)
  {
    return "medial mesh has no point-data array named 'Radius'";
  }
  if (radius && radius->GetNumberOfComponents() != 1)
  {
    return "medial mesh 'Radius' array must have one component, not " +
      std::to_string(radius->GetNumberOfComponents());
  }
  if (input->GetNumberOfStrips() > 0)
  {
    return "medial mesh has triangle strips; only triangles, lines and vertices are allowed";
  }
  mesh.Centers.resize(nv);
  mesh.Radii.resize(nv);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    input->GetPoint(i, mesh.Centers[i].data());
    mesh.Radii[i] = radius->GetComponent(i, 0);
  }

  std::size_t badPolys = 0, badLines = 0;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCurrentCell(n, ids);
    if (n != 3)
    {
      ++badPolys;
      continue;
    }
    mesh.Faces.push_back({ ids[0], ids[1], ids[2] });
  }
  auto lines = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    lines->GetCurrentCell(n, ids);
    if (n < 2)
    {
      ++badLines;
      continue;
    }
    for (vtkIdType k = 0; k + 1 < n; ++k) // a polyline contributes all its segments
    {
      mesh.Edges.push_back({ ids[k], ids[k + 1] });
    }
  }
  if (badPolys)
  {
    mesh = MedialMesh();
    return "medial mesh has " + std::to_string(badPolys) + " polygon(s) that are not triangles";
  }
  if (badLines)
  {
    mesh = MedialMesh();
    return "medial mesh has " + std::to_string(badLines) + " line cell(s) with fewer than 2 points";
  }
  const MedialMeshCheck check = ValidateMedialMesh(mesh);
  if (!check.IsValid())
  {
    mesh = MedialMesh();
    return check.Message;
  }
  // An edge that is both a triangle edge and a separate line cell is a
  // duplicate edge in the VTK form.
  const std::size_t onFaces = mesh.Edges.size() - EdgesNotOnFaces(mesh).size();
  if (onFaces)
  {
    mesh = MedialMesh();
    return "medial mesh has " + std::to_string(onFaces) +
      " line cell(s) duplicating an edge of a triangle";
  }
  return std::string();
}

void AddStabilityRatios(const MedialMesh& m, vtkPolyData* output)
{
  auto ratio = [&m](vtkIdType a, vtkIdType b)
  { return StabilityRatio(m.Centers[a], m.Radii[a], m.Centers[b], m.Radii[b]); };
  // In the cell order verts, lines, polys.
  vtkNew<vtkDoubleArray> stability;
  stability->SetName("StabilityRatio");
  stability->SetNumberOfTuples(output->GetNumberOfCells());
  vtkIdType cell = 0;
  for (vtkIdType i = 0; i < output->GetNumberOfVerts(); ++i)
  {
    stability->SetValue(cell++, 1.0);
  }
  for (vtkCellArray* cells : { output->GetLines(), output->GetPolys() })
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      double smallest = 1.0;
      for (vtkIdType k = 0; k < (n == 2 ? 1 : n); ++k)
      {
        smallest = std::min(smallest, ratio(ids[k], ids[(k + 1) % n]));
      }
      stability->SetValue(cell++, smallest);
    }
  }
  output->GetCellData()->AddArray(stability);
}

void AddCorrespondence(vtkPolyData* rvdIn, const std::vector<Index>& atlasOffsets,
  const std::vector<Index>& atlasSites, std::size_t numberOfSites, vtkPolyData* rvdOut)
{
  std::vector<vtkIdType> vertexOfSite(numberOfSites, -1);
  for (std::size_t v = 0; v + 1 < atlasOffsets.size(); ++v)
  {
    for (Index k = atlasOffsets[v]; k < atlasOffsets[v + 1]; ++k)
    {
      const Index site = atlasSites[k];
      if (site >= 0 && static_cast<std::size_t>(site) < numberOfSites && vertexOfSite[site] < 0)
      {
        vertexOfSite[site] = static_cast<vtkIdType>(v);
      }
    }
  }
  rvdOut->ShallowCopy(rvdIn);
  vtkDataArray* siteIds = rvdIn->GetCellData()->GetArray("SiteId");
  vtkNew<vtkIdTypeArray> vertexIds;
  vertexIds->SetName("MedialVertexId");
  vertexIds->SetNumberOfTuples(rvdIn->GetNumberOfCells());
  for (vtkIdType c = 0; c < rvdIn->GetNumberOfCells(); ++c)
  {
    const auto site = siteIds ? static_cast<vtkIdType>(siteIds->GetComponent(c, 0)) : -1;
    vertexIds->SetValue(
      c, site >= 0 && site < static_cast<vtkIdType>(numberOfSites) ? vertexOfSite[site] : -1);
  }
  vtkNew<vtkCellData> cellData;
  cellData->ShallowCopy(rvdIn->GetCellData());
  rvdOut->GetCellData()->ShallowCopy(cellData);
  rvdOut->GetCellData()->AddArray(vertexIds);
}
}
