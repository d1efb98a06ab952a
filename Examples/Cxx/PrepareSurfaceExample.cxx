// SPDX-License-Identifier: GPL-3.0-or-later
// Embedding MedialAxis in a VTK C++ application: read a surface (or make a
// filleted test part), check and repair it, sample it, split it into
// restricted Voronoi cells, compute its initial medial mesh and simplify it;
// write each result (.vtp, and the medial meshes also as .ma).
//
//   PrepareSurfaceExample [--output DIR] [--samples N] [--target V] [--organic]
//                         [mesh.obj|.off|.ply|.stl|.vtp|.vtk]
#include "vtkAnalyticShapeSource.h"
#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkBlueNoiseSurfaceSampler.h"
#include "vtkMedialAxisWriter.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkRestrictedVoronoiDiagram.h"
#include "vtkSurfaceFileReader.h"
#include "vtkVoronoiMedialAxis.h"

#include "vtkAlgorithmOutput.h"
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
  vtkIdType samples = 10000;
  vtkIdType target = 1000;
  bool cad = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--samples" && i + 1 < argc)
    {
      samples = std::stoll(argv[++i]);
    }
    else if (arg == "--target" && i + 1 < argc)
    {
      target = std::stoll(argv[++i]);
    }
    else if (arg == "--organic")
    {
      cad = false;
    }
    else if (arg == "--help" || arg == "-h")
    {
      std::cout << "usage: " << argv[0]
                << " [--output DIR] [--samples N] [--target V] [--organic] [surface file]\n"
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

  vtkNew<vtkBlueNoiseSurfaceSampler> sampler;
  sampler->SetInputConnection(validator->GetOutputPort());
  sampler->SetNumberOfSamples(samples);
  vtkNew<vtkRestrictedVoronoiDiagram> rvd;
  rvd->SetInputConnection(0, validator->GetOutputPort());
  rvd->SetInputConnection(1, sampler->GetOutputPort());
  vtkNew<vtkVoronoiMedialAxis> voronoi;
  voronoi->SetInputConnection(0, validator->GetOutputPort());
  voronoi->SetInputConnection(1, rvd->GetOutputPort(1));
  voronoi->Update();
  vtkPolyData* mat = voronoi->GetOutput();
  if (mat->GetNumberOfPoints() == 0)
  {
    std::cerr << "the medial axis computation failed\n";
    return 4;
  }
  std::cout << "initial medial mesh: " << mat->GetNumberOfPoints() << " spheres, "
            << mat->GetNumberOfPolys() << " triangles, " << mat->GetNumberOfLines()
            << " lines (from " << samples << " sites)\n";

  vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
  simplifier->SetInputConnection(0, voronoi->GetOutputPort());
  simplifier->SetInputConnection(1, rvd->GetOutputPort(0));
  simplifier->SetTargetNumberOfVertices(target);
  simplifier->SetPreserveSharpFeatures(cad);
  simplifier->Update();
  vtkPolyData* simplified = simplifier->GetOutput();
  if (simplified->GetNumberOfPoints() == 0)
  {
    std::cerr << "the simplification failed\n";
    return 4;
  }
  std::cout << "simplified medial mesh: " << simplified->GetNumberOfPoints() << " spheres, "
            << simplified->GetNumberOfPolys() << " triangles, " << simplified->GetNumberOfLines()
            << " lines\n";

  vtksys::SystemTools::MakeDirectory(outputDir);
  auto writeVtp = [&outputDir, &stem](vtkAlgorithmOutput* port, const std::string& suffix)
  {
    const std::string path = outputDir + "/" + stem + suffix + ".vtp";
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputConnection(port);
    writer->SetFileName(path.c_str());
    const bool ok = writer->Write() == 1;
    std::cout << (ok ? "wrote " : "cannot write ") << path << "\n";
    return ok;
  };
  bool ok = writeVtp(validator->GetOutputPort(), "_prepared");
  ok = writeVtp(rvd->GetOutputPort(0), "_rvd") && ok;
  ok = writeVtp(voronoi->GetOutputPort(), "_initial_mat") && ok;
  ok = writeVtp(simplifier->GetOutputPort(0), "_mat") && ok;
  ok = writeVtp(simplifier->GetOutputPort(1), "_correspondence") && ok;
  for (const auto& [port, suffix] :
    { std::pair<vtkAlgorithmOutput*, const char*>{ voronoi->GetOutputPort(), "_initial_mat.ma" },
      { simplifier->GetOutputPort(0), "_mat.ma" } })
  {
    vtkNew<vtkMedialAxisWriter> maWriter;
    maWriter->SetInputConnection(port);
    const std::string maPath = outputDir + "/" + stem + suffix;
    maWriter->SetFileName(maPath.c_str());
    const bool written = maWriter->Write() == 1;
    std::cout << (written ? "wrote " : "cannot write ") << maPath << "\n";
    ok = written && ok;
  }
  return ok ? 0 : 4;
}
