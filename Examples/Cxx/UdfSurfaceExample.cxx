// SPDX-License-Identifier: GPL-3.0-or-later
// An open surface from an unsigned distance field in a VTK C++ application:
// read a field (.vti), or make one from an open surface (a hemisphere, or
// the surface file given with --surface), extract the surface inside its
// epsilon-shell and write it.
//
//   UdfSurfaceExample [--output DIR] [--resolution N] [--snap]
//                     [--surface mesh.vtp|.obj|.stl|...] [field.vti]
#include "vtkSurfaceFileReader.h"
#include "vtkUnsignedDistanceSource.h"
#include "vtkUnsignedDistanceSurfaceExtractor.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  std::string outputDir = "output", field, surfaceFile;
  int resolution = 96;
  bool snap = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--resolution" && i + 1 < argc)
    {
      resolution = std::atoi(argv[++i]);
    }
    else if (arg == "--surface" && i + 1 < argc)
    {
      surfaceFile = argv[++i];
    }
    else if (arg == "--snap")
    {
      snap = true;
    }
    else if (!arg.empty() && arg[0] != '-')
    {
      field = arg;
    }
    else
    {
      std::cerr << "usage: UdfSurfaceExample [--output DIR] [--resolution N] [--snap] "
                   "[--surface mesh] [field.vti]\n";
      return 2;
    }
  }

  // The field: read, or sampled from an open surface.
  vtkSmartPointer<vtkImageData> image;
  if (!field.empty())
  {
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(field.c_str());
    reader->Update();
    image = reader->GetOutput();
  }
  else
  {
    vtkSmartPointer<vtkPolyData> surface;
    if (!surfaceFile.empty())
    {
      vtkNew<vtkSurfaceFileReader> reader;
      reader->SetFileName(surfaceFile.c_str());
      reader->Update();
      surface = reader->GetOutput();
    }
    else
    {
      vtkNew<vtkSphereSource> sphere; // the upper half: open, one boundary
      sphere->SetThetaResolution(96);
      sphere->SetPhiResolution(48);
      sphere->SetEndPhi(90.0);
      vtkNew<vtkTriangleFilter> triangles;
      triangles->SetInputConnection(sphere->GetOutputPort());
      triangles->Update();
      surface = triangles->GetOutput();
    }
    vtkNew<vtkUnsignedDistanceSource> distance;
    distance->SetInputData(surface);
    distance->SetSamplingDimensions(resolution, resolution, resolution);
    distance->Update();
    image = distance->GetOutput();
  }

  vtkNew<vtkUnsignedDistanceSurfaceExtractor> extractor;
  extractor->SetInputData(image);
  extractor->SetSnapToZeroSet(snap);
  extractor->Update();
  vtkPolyData* extracted = extractor->GetOutput(0);
  if (extracted->GetNumberOfPolys() == 0)
  {
    std::cerr << "no surface extracted (see the errors above)\n";
    return 1;
  }
  auto value = [&](const char* name)
  { return static_cast<long long>(extracted->GetFieldData()->GetArray(name)->GetTuple1(0)); };
  std::cout << "surface: " << extracted->GetNumberOfPolys() << " triangles, "
            << value("BoundaryLoops") << " boundary loops, " << value("JunctionEdges")
            << " junction edges; epsilon " << extractor->GetUsedEpsilon() << ", "
            << extractor->GetUsedSamples() << " samples, " << extractor->GetUsedSpheres()
            << " spheres\n";

  vtksys::SystemTools::MakeDirectory(outputDir);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(extracted);
  writer->SetFileName((outputDir + "/udf_surface.vtp").c_str());
  writer->Write();
  writer->SetInputData(extractor->GetOutput(1));
  writer->SetFileName((outputDir + "/udf_shell.vtp").c_str());
  writer->Write();
  std::cout << "wrote " << outputDir << "/udf_surface.vtp and udf_shell.vtp\n";
  return 0;
}
