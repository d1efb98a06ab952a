// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkCurveSkeletonWriter.h"

#include "Skeleton/SkeletonExport.h"
#include "vtkCurveSkeletonConversion.h"

#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtksys/FStream.hxx"
#include "vtksys/SystemTools.hxx"

vtkStandardNewMacro(vtkCurveSkeletonWriter);

vtkCurveSkeletonWriter::vtkCurveSkeletonWriter() = default;

vtkCurveSkeletonWriter::~vtkCurveSkeletonWriter()
{
  this->SetFileName(nullptr);
}

int vtkCurveSkeletonWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkCurveSkeletonWriter::WriteData()
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
  medialaxis::CurveSkeleton skeleton;
  const std::string problem =
    medialaxis::PolyDataToCurveSkeleton(vtkPolyData::SafeDownCast(this->GetInput()), skeleton);
  if (!problem.empty())
  {
    fail(std::string("cannot write ") + this->FileName + ": " + problem);
    return;
  }
  const bool json = this->FileFormat == FormatJson ||
    (this->FileFormat == FormatFromExtension &&
      vtksys::SystemTools::LowerCase(
        vtksys::SystemTools::GetFilenameLastExtension(this->FileName)) == ".json");
  const std::string text =
    json ? medialaxis::SkeletonToJson(skeleton) : medialaxis::SkeletonToSwc(skeleton, this->Header);
  vtksys::ofstream file(this->FileName, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!file || !(file << text) || !file.flush())
  {
    fail(std::string(this->FileName) + ": cannot write the file");
    return;
  }
  this->UpdateProgress(1.0);
}

void vtkCurveSkeletonWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FileFormat: " << this->FileFormat << "\n";
  os << indent << "Header: " << this->Header << "\n";
}
