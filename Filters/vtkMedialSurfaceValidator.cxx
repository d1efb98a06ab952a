// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialSurfaceValidator.h"

#include "vtkMedialMeshConversion.h"
#include "vtkSurfacePreparation.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

vtkStandardNewMacro(vtkMedialSurfaceValidator);

vtkMedialSurfaceValidator::vtkMedialSurfaceValidator() = default;

namespace
{
void AddValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}
}

int vtkMedialSurfaceValidator::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);

  medialaxis::SurfacePreparationOptions options;
  options.RelativeMergeTolerance = this->RelativeMergeTolerance;
  options.FixOrientation = this->FixOrientation;
  options.RepairSelfIntersections = this->RepairSelfIntersections;
  options.WrapAlpha = this->WrapAlpha;
  options.ContactGap = this->ContactGap;
  const auto report = medialaxis::PrepareSurfacePolyData(input, output, options);
  this->UpdateProgress(1.0);

  this->Valid = report.Ok();
  this->ErrorMessage = report.Error;
  this->Notes.clear();
  for (const auto& note : report.Notes)
  {
    this->Notes += note + "\n";
  }
  this->NumberOfMergedPoints = static_cast<vtkIdType>(report.MergedPoints);
  this->NumberOfDegenerateTriangles = static_cast<vtkIdType>(report.DegenerateTriangles);
  this->NumberOfDuplicateTriangles = static_cast<vtkIdType>(report.DuplicateTriangles);
  this->NumberOfBoundaryEdges = static_cast<vtkIdType>(report.BoundaryEdges);
  this->NumberOfNonManifoldEdges = static_cast<vtkIdType>(report.NonManifoldEdges);
  this->NumberOfNonManifoldVertices = static_cast<vtkIdType>(report.NonManifoldVertices);
  this->NumberOfReorientedTriangles = static_cast<vtkIdType>(report.ReorientedTriangles);
  this->NumberOfInwardComponents = static_cast<vtkIdType>(report.InwardComponents);
  this->NumberOfComponents = static_cast<vtkIdType>(report.Components);
  this->Area = report.Area;
  this->Volume = report.Volume;
  this->Repaired = report.Repaired;
  this->RemovedArea = report.RemovedArea;
  this->Wrapped = report.RepairMethod == "alpha wrap";
  this->RepairDeviation = report.RepairDeviation;
  this->RepairMethod = report.RepairMethod;
  this->NumberOfCrossingPairs =
    static_cast<vtkIdType>(report.CrossingShells + report.CrossingFarApart);

  if (!report.Ok())
  {
    output->Initialize();
    vtkErrorMacro(<< report.Error);
    return 0;
  }

  for (const auto& note : report.Notes)
  {
    if (medialaxis::IsMovedSurfaceNote(note))
    {
      vtkWarningMacro(<< note);
    }
  }
  vtkFieldData* fd = output->GetFieldData();
  medialaxis::AddFieldValue(output, "NumberOfMergedPoints", this->NumberOfMergedPoints);
  medialaxis::AddFieldValue(
    output, "NumberOfDegenerateTriangles", this->NumberOfDegenerateTriangles);
  medialaxis::AddFieldValue(output, "NumberOfDuplicateTriangles", this->NumberOfDuplicateTriangles);
  medialaxis::AddFieldValue(
    output, "NumberOfReorientedTriangles", this->NumberOfReorientedTriangles);
  medialaxis::AddFieldValue(output, "NumberOfInwardComponents", this->NumberOfInwardComponents);
  medialaxis::AddFieldValue(output, "NumberOfComponents", this->NumberOfComponents);
  medialaxis::AddFieldValue(output, "NumberOfCrossingPairs", this->NumberOfCrossingPairs);
  medialaxis::AddFieldValue(output, "Repaired", this->Repaired ? 1 : 0);
  AddValue(fd, "RemovedArea", this->RemovedArea);
  medialaxis::AddFieldValue(output, "Wrapped", this->Wrapped ? 1 : 0);
  AddValue(fd, "RepairDeviation", this->RepairDeviation);
  AddValue(fd, "Area", this->Area);
  AddValue(fd, "Volume", this->Volume);
  if (!this->Notes.empty())
  {
    vtkNew<vtkStringArray> notes;
    notes->SetName("Notes");
    for (const auto& note : report.Notes)
    {
      notes->InsertNextValue(note);
    }
    fd->AddArray(notes);
  }
  return 1;
}

void vtkMedialSurfaceValidator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RelativeMergeTolerance: " << this->RelativeMergeTolerance << "\n";
  os << indent << "FixOrientation: " << this->FixOrientation << "\n";
  os << indent << "RepairSelfIntersections: " << this->RepairSelfIntersections << "\n";
  os << indent << "WrapAlpha: " << this->WrapAlpha << "\n";
  os << indent << "ContactGap: " << this->ContactGap << "\n";
  os << indent << "Repaired: " << this->Repaired << "\n";
  os << indent << "Wrapped: " << this->Wrapped << "\n";
  os << indent << "RepairDeviation: " << this->RepairDeviation << "\n";
  os << indent << "RepairMethod: " << this->RepairMethod << "\n";
  os << indent << "Valid: " << this->Valid << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
