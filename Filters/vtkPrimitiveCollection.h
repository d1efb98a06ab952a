// SPDX-License-Identifier: GPL-3.0-or-later
// The VTK form of fitted generalized primitives, shared by
// vtkGeneralizedPrimitiveFitter and vtkMedialSkeletalDiagram: one closed
// mesh per skeletal element in a vtkPartitionedDataSetCollection. Private to
// the module: not wrapped.
#ifndef vtkPrimitiveCollection_h
#define vtkPrimitiveCollection_h

#include "Skeletal/PrimitiveFit.h"
#include "Skeletal/PrimitiveTemplate.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>

class vtkPartitionedDataSetCollection;
class vtkPolyData;

namespace medialaxis
{
/// The primitive's closed mesh with point data `Radius` and `MaximumRadius`
/// (empty when the fit failed).
vtkSmartPointer<vtkPolyData> PrimitiveMesh(
  const PrimitiveTemplate& shape, const FittedPrimitive& fit);

/// Puts `mesh` as partitioned dataset `index` of `output`, named `name`,
/// with field data `ElementType` and `ElementId`.
void SetPrimitive(vtkPartitionedDataSetCollection* output, unsigned int index, vtkPolyData* mesh,
  SkeletalElement type, vtkIdType id, const std::string& name);
}

#endif
