// SPDX-License-Identifier: GPL-3.0-or-later
// Embedding MedialAxis in a VTK C++ application: read a surface (or make a
// filleted test part), check and repair it, and write it as .vtp.
//
//   PrepareSurfaceExample [--output DIR] [mesh.obj|.off|.ply|.stl|.vtp|.vtk]
#include "vtkAnalyticShapeSource.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkSurfaceFileReader.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  std::string outputDir = "output";
  std::string input;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--help" || arg == "-h")
    {
      std::cout << "usage: " << argv[0] << " [--output DIR] [surface file]\n"
                << "Without a file, a box with rounded edges is generated.\n";
      return 0;
    }
    else
    {
      input = arg;
    }
  }

  vtkSmartPointer<vtkAlgorithm> source;
  std::string stem;
  if (input.empty())
  {
    auto shape = vtkSmartPointer<vtkAnalyticShapeSource>::New();
    shape->SetShapeToRoundedBox();
    shape->SetXLength(3.0);
    shape->SetYLength(2.0);
    shape->SetZLength(1.0);
    shape->SetFilletRadius(0.2);
    source = shape;
    stem = "rounded_box";
  }
  else
  {
    auto reader = vtkSmartPointer<vtkSurfaceFileReader>::New();
    reader->SetFileName(input.c_str());
    source = reader;
    stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(input);
  }

  vtkNew<vtkMedialSurfaceValidator> validator;
  validator->SetInputConnection(source->GetOutputPort());
  validator->Update();
  if (!validator->GetValid())
  {
    std::cerr << "surface is invalid: " << validator->GetErrorMessage() << "\n";
    return 3;
  }
  vtkPolyData* surface = validator->GetOutput();
  std::cout << "surface is valid: " << surface->GetNumberOfPoints() << " points, "
            << surface->GetNumberOfPolys() << " triangles, " << validator->GetNumberOfComponents()
            << " shell(s), area " << validator->GetArea() << ", volume " << validator->GetVolume()
            << "\n"
            << validator->GetNotes();

  vtksys::SystemTools::MakeDirectory(outputDir);
  const std::string path = outputDir + "/" + stem + "_prepared.vtp";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(surface);
  writer->SetFileName(path.c_str());
  if (writer->Write() != 1)
  {
    std::cerr << "cannot write " << path << "\n";
    return 4;
  }
  std::cout << "wrote " << path << "\n";
  return 0;
}
