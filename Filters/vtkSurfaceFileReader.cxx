// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkSurfaceFileReader.h"

#include "Format/ObjCheck.h"
#include "vtkErrorEventText.h"

#include "vtkOFFReader.h"

#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include "vtksys/SystemTools.hxx"

#include <fstream>
#include <string>

vtkStandardNewMacro(vtkSurfaceFileReader);

namespace
{
std::string Extension(const char* fileName)
{
  return vtksys::SystemTools::LowerCase(
    vtksys::SystemTools::GetFilenameLastExtension(fileName ? fileName : ""));
}

// Collects the inner reader's error text so it can be reported as ours.
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    if (data && this->Text.empty())
    {
      this->Text = medialaxis::ErrorEventMessage(data);
    }
  }
  std::string Text;
};
}

vtkSurfaceFileReader::vtkSurfaceFileReader()
{
  this->SetNumberOfInputPorts(0);
}

bool vtkSurfaceFileReader::IsSupportedExtension(const char* fileName)
{
  const std::string ext = Extension(fileName);
  return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl" || ext == ".vtp" ||
    ext == ".vtk";
}

int vtkSurfaceFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->ErrorMessage.clear();
  auto fail = [this](const std::string& message)
  {
    this->ErrorMessage = message;
    vtkErrorMacro(<< message);
    return 0;
  };
  const std::string name = this->FileName ? this->FileName : "";
  if (name.empty())
  {
    return fail("no file name given");
  }
  if (!vtksys::SystemTools::FileExists(name, true))
  {
    return fail(name + ": no such file");
  }
  const std::string ext = Extension(name.c_str());
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".obj")
  {
    std::ifstream text(name);
    const std::string problem = medialaxis::CheckObjText(text);
    if (!problem.empty())
    {
      return fail(name + ": " + problem);
    }
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(name.c_str());
    reader = r;
  }
  else if (ext == ".off")
  {
    auto r = vtkSmartPointer<vtkOFFReader>::New();
    r->SetFileName(name.c_str());
    reader = r;
  }
  else if (ext == ".ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(name.c_str());
    reader = r;
  }
  else if (ext == ".stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(name.c_str());
    reader = r;
  }
  else if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(name.c_str());
    reader = r;
  }
  else if (ext == ".vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(name.c_str());
    reader = r;
  }
  else
  {
    return fail(
      name + ": unknown file extension '" + ext + "' (supported: .obj .off .ply .stl .vtp .vtk)");
  }

  vtkNew<ErrorCollector> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->Update();
  vtkPolyData* read = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!errors->Text.empty())
  {
    return fail(name + ": " + errors->Text);
  }
  if (!read || read->GetNumberOfPoints() == 0)
  {
    return fail(name + ": the file holds no points");
  }
  output->ShallowCopy(read);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkSurfaceFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
