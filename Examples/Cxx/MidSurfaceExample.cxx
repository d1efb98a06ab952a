// SPDX-License-Identifier: GPL-3.0-or-later
// The mid-surface of a thin-walled part in a VTK C++ application: read a
// surface (or make a T-plate: a plate with a rib, walls 0.1 thick), compute
// its medial axis with the CAD settings, extract the walls' mid-surface and
// write it with its thickness.
//
//   MidSurfaceExample [--output DIR] [--wall-thickness T] [mesh.obj|.off|.ply|.stl|.vtp|.vtk]
#include "vtkAnalyticShapeSource.h"
#include "vtkMidSurfaceExtractor.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfaceFileReader.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  std::string outputDir = "output", input;
  double wallThickness = 0.0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--wall-thickness" && i + 1 < argc)
    {
      wallThickness = std::atof(argv[++i]);
    }
    else if (!arg.empty() && arg[0] != '-')
    {
      input = arg;
    }
    else
    {
      std::cerr << "usage: MidSurfaceExample [--output DIR] [--wall-thickness T] [mesh]\n";
      return 2;
    }
  }

  vtkSmartPointer<vtkPolyDataAlgorithm> surface;
  if (input.empty())
  {
    auto part = vtkSmartPointer<vtkAnalyticShapeSource>::New();
    part->SetShapeToTPlate();
    part->SetXLength(2.0);
    part->SetYLength(2.0);
    part->SetZLength(1.0);
    part->SetThickness(0.1);
    surface = part;
  }
  else
  {
    auto reader = vtkSmartPointer<vtkSurfaceFileReader>::New();
    reader->SetFileName(input.c_str());
    surface = reader;
  }

  vtkNew<vtkStructuralMedialAxis> medialAxis;
  medialAxis->SetInputConnection(surface->GetOutputPort());
  medialAxis->SetPresetToCAD();
  vtkNew<vtkMidSurfaceExtractor> midSurface;
  midSurface->SetInputConnection(0, surface->GetOutputPort());
  midSurface->SetMedialAxisConnection(medialAxis->GetOutputPort(0));
  midSurface->SetWallThickness(wallThickness);
  midSurface->Update();
  vtkPolyData* result = midSurface->GetOutput();
  if (result->GetNumberOfPolys() == 0)
  {
    std::cerr << "no mid-surface (see the messages above)\n";
    return 1;
  }

  std::cout << "mid-surface: " << midSurface->GetNumberOfWalls() << " walls, wall thickness "
            << midSurface->GetEstimatedWallThickness() << ", "
            << midSurface->GetNumberOfJunctionEdges() << " junction edges\n";
  vtkFieldData* fields = result->GetFieldData();
  for (vtkIdType w = 0; w < midSurface->GetNumberOfWalls(); ++w)
  {
    std::cout << "  wall " << w << ": area " << fields->GetArray("WallArea")->GetTuple1(w)
              << ", thickness " << fields->GetArray("WallMeanThickness")->GetTuple1(w) << "\n";
  }

  vtksys::SystemTools::MakeDirectory(outputDir);
  const std::string path = outputDir + "/mid_surface.vtp";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(result);
  writer->SetFileName(path.c_str());
  if (writer->Write() != 1)
  {
    std::cerr << "cannot write " << path << "\n";
    return 1;
  }
  std::cout << "wrote " << path << "\n";
  return 0;
}
