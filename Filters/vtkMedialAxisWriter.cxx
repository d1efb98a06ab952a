// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkMedialAxisWriter.h"

#include "Format/MaFormat.h"
#include "vtkMedialMeshConversion.h"

#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtksys/FStream.hxx"

vtkStandardNewMacro(vtkMedialAxisWriter);

vtkMedialAxisWriter::vtkMedialAxisWriter() = default;

vtkMedialAxisWriter::~vtkMedialAxisWriter()
{
  this->SetFileName(nullptr);
}

int vtkMedialAxisWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkMedialAxisWriter::WriteData()
{
  this->ErrorMessage.clear();
  auto fail = [this](const std::string& message)
  {
    this->ErrorMessage = message;
    vtkErrorMacro(<< message);
    this->SetErrorCode(1);
  };
  if (!this->FileName || !*this->FileName)
  {
    fail("no file name given");
    return;
  }
  medialaxis::MedialMesh mesh;
  const std::string problem =
    medialaxis::PolyDataToMedialMesh(vtkPolyData::SafeDownCast(this->GetInput()), mesh);
  if (!problem.empty())
  {
    fail(std::string("cannot write ") + this->FileName + ": " + problem);
    return;
  }
  vtksys::ofstream file(this->FileName, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!file || !medialaxis::WriteMa(file, mesh))
  {
    fail(std::string(this->FileName) + ": cannot write the file");
    return;
  }
  this->UpdateProgress(1.0);
}

void vtkMedialAxisWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
