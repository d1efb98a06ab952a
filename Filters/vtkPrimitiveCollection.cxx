// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkPrimitiveCollection.h"

#include "vtkCellArray.h"
#include "vtkCompositeDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

namespace medialaxis
{
vtkSmartPointer<vtkPolyData> PrimitiveMesh(
  const PrimitiveTemplate& shape, const FittedPrimitive& fit)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  if (fit.Radius.empty())
  {
    return mesh;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const std::vector<Point3> surface = PrimitivePoints(shape, fit.Radius);
  points->SetNumberOfPoints(static_cast<vtkIdType>(surface.size()));
  vtkNew<vtkDoubleArray> radius, maximum;
  radius->SetName("Radius");
  maximum->SetName("MaximumRadius");
  radius->SetNumberOfTuples(points->GetNumberOfPoints());
  maximum->SetNumberOfTuples(points->GetNumberOfPoints());
  for (std::size_t j = 0; j < surface.size(); ++j)
  {
    points->SetPoint(static_cast<vtkIdType>(j), surface[j].data());
    radius->SetValue(static_cast<vtkIdType>(j), fit.Radius[j]);
    maximum->SetValue(static_cast<vtkIdType>(j), fit.MaximumRadius[j]);
  }
  vtkNew<vtkCellArray> triangles;
  for (const Triangle& t : shape.Triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  mesh->GetPointData()->AddArray(radius);
  mesh->GetPointData()->AddArray(maximum);
  mesh->GetPointData()->SetActiveScalars("Radius");
  return mesh;
}

void SetPrimitive(vtkPartitionedDataSetCollection* output, unsigned int index, vtkPolyData* mesh,
  SkeletalElement type, vtkIdType id, const std::string& name)
{
  vtkNew<vtkIntArray> typeArray;
  typeArray->SetName("ElementType");
  typeArray->InsertNextValue(static_cast<int>(type));
  vtkNew<vtkIdTypeArray> idArray;
  idArray->SetName("ElementId");
  idArray->InsertNextValue(id);
  mesh->GetFieldData()->AddArray(typeArray);
  mesh->GetFieldData()->AddArray(idArray);
  vtkNew<vtkPartitionedDataSet> partitioned;
  partitioned->SetPartition(0, mesh);
  output->SetPartitionedDataSet(index, partitioned);
  output->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name.c_str());
}
}
