// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkSurfacePreparation.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

namespace medialaxis
{
void TriangleMeshToPolyData(const TriangleMesh& mesh, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.Points.size()));
  for (std::size_t i = 0; i < mesh.Points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.Points[i].data());
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(mesh.Triangles.size()),
    3 * static_cast<vtkIdType>(mesh.Triangles.size()));
  for (const Triangle& t : mesh.Triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(polys);
}

SurfacePreparationReport PrepareSurfacePolyData(
  vtkPolyData* input, vtkPolyData* output, const SurfacePreparationOptions& options)
{
  output->Initialize();
  TriangleMesh prepared;
  const SurfacePreparationReport report = PrepareSurfaceMesh(input, prepared, options);
  if (report.Ok())
  {
    TriangleMeshToPolyData(prepared, output);
  }
  return report;
}

SurfacePreparationReport PrepareSurfaceMesh(
  vtkPolyData* input, TriangleMesh& prepared, const SurfacePreparationOptions& options)
{
  SurfacePreparationReport report;
  prepared = TriangleMesh();
  if (!input || input->GetNumberOfPoints() == 0)
  {
    report.Error = "surface is empty: it has no points";
    return report;
  }
  if (input->GetNumberOfPolys() == 0 && input->GetNumberOfStrips() == 0)
  {
    report.Error = "surface has no polygons (it has " + std::to_string(input->GetNumberOfLines()) +
      " line and " + std::to_string(input->GetNumberOfVerts()) +
      " vertex cells): a closed triangle mesh is needed";
    return report;
  }

  // Polygons and strips become triangles with VTK's own triangulator, which
  // handles non-convex polygons; the result is checked below like any soup.
  vtkNew<vtkPolyData> shell;
  shell->SetPoints(input->GetPoints());
  shell->SetPolys(input->GetPolys());
  shell->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(shell);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* triangles = triangulate->GetOutput();

  TriangleMesh soup;
  soup.Points.resize(static_cast<std::size_t>(triangles->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < triangles->GetNumberOfPoints(); ++i)
  {
    triangles->GetPoint(i, soup.Points[i].data());
  }
  soup.Triangles.reserve(static_cast<std::size_t>(triangles->GetNumberOfPolys()));
  auto it = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
  std::size_t notTriangles = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n == 3)
    {
      soup.Triangles.push_back({ ids[0], ids[1], ids[2] });
    }
    else
    {
      ++notTriangles; // polygons VTK could not triangulate (e.g. degenerate)
    }
  }

  report = PrepareSurface(soup, prepared, options);
  if (notTriangles)
  {
    report.Notes.push_back(
      std::to_string(notTriangles) + " polygon(s) could not be triangulated and were dropped");
  }
  return report;
}
}
