// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkOFFReader.h"

#include "Format/OffFormat.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtksys/FStream.hxx"

vtkStandardNewMacro(vtkOFFReader);

vtkOFFReader::vtkOFFReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkOFFReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->ErrorMessage.clear();
  const std::string name = this->FileName ? this->FileName : "";
  auto fail = [this](const std::string& message)
  {
    this->ErrorMessage = message;
    vtkErrorMacro(<< message);
    return 0;
  };
  if (name.empty())
  {
    return fail("no file name given");
  }
  vtksys::ifstream file(name.c_str(), std::ios::in | std::ios::binary);
  if (!file)
  {
    return fail(name + ": cannot open the file");
  }
  const medialaxis::OffReadResult result = medialaxis::ParseOff(file);
  this->UpdateProgress(0.8);
  if (!result.Ok())
  {
    return fail(name + ": " + result.Error);
  }

  const auto& mesh = result.Mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.Points.size()));
  for (std::size_t i = 0; i < mesh.Points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.Points[i].data());
  }
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.Offsets.size()));
  std::copy(mesh.Offsets.begin(), mesh.Offsets.end(), offsets->GetPointer(0));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(mesh.Connectivity.size()));
  std::copy(mesh.Connectivity.begin(), mesh.Connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
