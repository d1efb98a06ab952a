// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialAxisReader.h"

#include "Format/MaFormat.h"
#include "vtkMedialMeshConversion.h"

#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtksys/FStream.hxx"

vtkStandardNewMacro(vtkMedialAxisReader);

vtkMedialAxisReader::vtkMedialAxisReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkMedialAxisReader::CanReadFile(const char* fileName)
{
  vtksys::ifstream file(fileName ? fileName : "");
  return file.good() ? 1 : 0;
}

int vtkMedialAxisReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->ErrorMessage.clear();
  const std::string name = this->FileName ? this->FileName : "";
  if (name.empty())
  {
    this->ErrorMessage = "no file name given";
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  vtksys::ifstream file(name.c_str(), std::ios::in | std::ios::binary);
  if (!file)
  {
    this->ErrorMessage = name + ": cannot open the file";
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  const medialaxis::MaReadResult result = medialaxis::ParseMa(file);
  this->UpdateProgress(0.8);
  if (!result.Ok())
  {
    this->ErrorMessage = name + ": " + result.Error;
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  medialaxis::MedialMeshToPolyData(result.Mesh, output);
  medialaxis::AddFieldValue(
    output, "DuplicateEdges", static_cast<long long>(result.DuplicateEdges));
  medialaxis::AddFieldValue(
    output, "DuplicateFaces", static_cast<long long>(result.DuplicateFaces));
  if (result.DuplicateEdges || result.DuplicateFaces)
  {
    vtkWarningMacro(<< name << ": dropped " << result.DuplicateFaces << " duplicate face(s) and "
                    << result.DuplicateEdges << " duplicate edge(s)");
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialAxisReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
