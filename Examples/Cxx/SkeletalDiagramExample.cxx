// SPDX-License-Identifier: GPL-3.0-or-later
// A Medial Skeletal Diagram in a VTK C++ application: read a surface (or
// make a dumbbell: two balls joined by a thin neck), simplify its medial
// axis to a hundred spheres, build a diagram of at most N elements whose
// generalized primitives cover the surface within 0.5% of its diagonal, and
// write the skeleton and the primitives.
//
//   SkeletalDiagramExample [--output DIR] [--elements N] [mesh.obj|.off|.ply|.stl|.vtp|.vtk]
#include "vtkAnalyticShapeSource.h"
#include "vtkMedialSkeletalDiagram.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfaceFileReader.h"

#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSetCollection.h"
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
  int elements = 50;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--elements" && i + 1 < argc)
    {
      elements = std::atoi(argv[++i]);
    }
    else if (!arg.empty() && arg[0] != '-')
    {
      input = arg;
    }
    else
    {
      std::cerr << "usage: SkeletalDiagramExample [--output DIR] [--elements N] [mesh]\n";
      return 2;
    }
  }

  vtkSmartPointer<vtkPolyDataAlgorithm> surface;
  if (input.empty())
  {
    auto dumbbell = vtkSmartPointer<vtkAnalyticShapeSource>::New();
    dumbbell->SetShapeToDumbbell();
    dumbbell->SetLength(1.2);
    dumbbell->SetRadius(0.25);
    dumbbell->SetMinorRadius(0.1);
    surface = dumbbell;
  }
  else
  {
    auto reader = vtkSmartPointer<vtkSurfaceFileReader>::New();
    reader->SetFileName(input.c_str());
    surface = reader;
  }

  vtkNew<vtkStructuralMedialAxis> medialAxis;
  medialAxis->SetInputConnection(surface->GetOutputPort());
  medialAxis->SetTargetNumberOfVertices(100);
  vtkNew<vtkMedialSkeletalDiagram> diagram;
  diagram->SetInputConnection(0, surface->GetOutputPort());
  diagram->SetMedialAxisConnection(medialAxis->GetOutputPort(0));
  diagram->SetMaximumElements(elements);
  diagram->Update();
  vtkPolyData* skeleton = diagram->GetSkeleton();
  if (skeleton->GetNumberOfPoints() == 0)
  {
    std::cerr << "no skeletal diagram (see the messages above)\n";
    return 1;
  }
  // The skeleton's points: its vertices, then the bends of edges routed
  // inside the surface (each edge is a polyline).
  const auto vertices =
    static_cast<vtkIdType>(skeleton->GetFieldData()->GetArray("Vertices")->GetTuple1(0));
  std::cout << "skeletal diagram: " << vertices << " vertices, " << skeleton->GetNumberOfLines()
            << " edges, " << skeleton->GetNumberOfPolys() << " triangles; surface within "
            << 100.0 * diagram->GetReachedError() << "% of the diagonal of the primitives\n";

  // The skeleton, and each primitive in a file of its own (primitive_E.vtp,
  // E its element's index: vertices, then edges, then triangles).
  vtksys::SystemTools::MakeDirectory(outputDir);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(skeleton);
  writer->SetFileName((outputDir + "/skeleton.vtp").c_str());
  bool written = writer->Write() != 0;
  vtkPartitionedDataSetCollection* primitives = diagram->GetPrimitives();
  for (unsigned int e = 0; e < primitives->GetNumberOfPartitionedDataSets(); ++e)
  {
    writer->SetInputData(primitives->GetPartition(e, 0));
    writer->SetFileName((outputDir + "/primitive_" + std::to_string(e) + ".vtp").c_str());
    written = writer->Write() != 0 && written;
  }
  // The union of the primitives as one closed surface.
  writer->SetInputData(diagram->GetReconstruction());
  writer->SetFileName((outputDir + "/reconstruction.vtp").c_str());
  written = writer->Write() != 0 && written;
  if (!written)
  {
    std::cerr << "could not write into " << outputDir << "\n";
    return 1;
  }
  std::cout << "wrote " << outputDir << "/skeleton.vtp, reconstruction.vtp and "
            << primitives->GetNumberOfPartitionedDataSets() << " primitive_E.vtp\n";
  return EXIT_SUCCESS;
}
