// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkDistanceGridContour.h"

#include "Mesh/TriangleAdjacency.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>

namespace medialaxis
{
TriangleMesh ContourDistanceGrid(const DistanceGrid& grid)
{
  TriangleMesh mesh;
  if (grid.Values.empty())
  {
    return mesh;
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(grid.Dimensions.data());
  image->SetOrigin(grid.Origin.data());
  image->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
  vtkNew<vtkFloatArray> values;
  values->SetName("Distance");
  values->SetNumberOfTuples(static_cast<vtkIdType>(grid.Values.size()));
  std::copy(grid.Values.begin(), grid.Values.end(), values->GetPointer(0));
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  vtkPolyData* surface = contour->GetOutput();

  mesh.Points.resize(static_cast<std::size_t>(surface->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    surface->GetPoint(i, mesh.Points[i].data());
  }
  vtkCellArray* polys = surface->GetPolys();
  mesh.Triangles.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    if (npts == 3)
    {
      mesh.Triangles.push_back({ ids[0], ids[1], ids[2] });
    }
  }
  OrientOutward(mesh);
  return mesh;
}
}
