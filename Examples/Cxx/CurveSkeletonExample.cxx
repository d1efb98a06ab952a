// SPDX-License-Identifier: GPL-3.0-or-later
// A curve skeleton in a VTK C++ application: read a surface (or make a torus),
// compute its Structural MAT, thin it to centre lines with a radius at every
// node and one loop per handle, and write the skeleton (.vtp, .swc, .json)
// and the surface segmented by branch.
//
//   CurveSkeletonExample [--output DIR] [mesh.obj|.off|.ply|.stl|.vtp|.vtk]
#include "vtkAnalyticShapeSource.h"
#include "vtkCurveSkeletonWriter.h"
#include "vtkMedialCurveSkeleton.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfaceFileReader.h"

#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  std::string outputDir = "output", input;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
    {
      outputDir = argv[++i];
    }
    else if (!arg.empty() && arg[0] != '-')
    {
      input = arg;
    }
    else
    {
      std::cerr << "usage: CurveSkeletonExample [--output DIR] [mesh]\n";
      return 2;
    }
  }

  vtkSmartPointer<vtkPolyDataAlgorithm> surface;
  if (input.empty())
  {
    auto torus = vtkSmartPointer<vtkAnalyticShapeSource>::New();
    torus->SetShapeToTorus();
    surface = torus;
  }
  else
  {
    auto reader = vtkSmartPointer<vtkSurfaceFileReader>::New();
    reader->SetFileName(input.c_str());
    surface = reader;
  }

  vtkNew<vtkStructuralMedialAxis> medialAxis;
  medialAxis->SetInputConnection(surface->GetOutputPort());
  medialAxis->SetGenerateEnvelope(false);
  vtkNew<vtkMedialCurveSkeleton> curve;
  curve->SetInputConnection(0, surface->GetOutputPort());
  curve->SetMedialAxisConnection(medialAxis->GetOutputPort(0));
  curve->Update();
  vtkPolyData* skeleton = curve->GetSkeleton();
  if (skeleton->GetNumberOfPoints() == 0)
  {
    std::cerr << "no curve skeleton (see the messages above)\n";
    return 1;
  }
  auto count = [skeleton](const char* name)
  { return static_cast<long>(skeleton->GetFieldData()->GetArray(name)->GetTuple1(0)); };
  std::cout << "curve skeleton: " << count("Nodes") << " nodes, " << count("Branches")
            << " branches, " << count("Junctions") << " junctions, " << count("CycleRank")
            << " loops\n";

  vtksys::SystemTools::MakeDirectory(outputDir);
  vtkNew<vtkXMLPolyDataWriter> vtp;
  vtp->SetInputData(skeleton);
  vtp->SetFileName((outputDir + "/curve_skeleton.vtp").c_str());
  vtp->Write();
  vtp->SetInputData(curve->GetSegmentation());
  vtp->SetFileName((outputDir + "/segmentation.vtp").c_str());
  vtp->Write();
  for (const char* name : { "/curve_skeleton.swc", "/curve_skeleton.json" })
  {
    vtkNew<vtkCurveSkeletonWriter> writer;
    writer->SetInputData(skeleton);
    writer->SetFileName((outputDir + name).c_str());
    if (!writer->Write())
    {
      std::cerr << writer->GetErrorMessage() << "\n";
      return 1;
    }
  }
  std::cout << "wrote " << outputDir << "/curve_skeleton.{vtp,swc,json} and segmentation.vtp\n";
  return 0;
}
