// SPDX-License-Identifier: GPL-3.0-or-later
// Embeds the MedialAxis filters in a VTK application: reads a surface,
// computes its Structural MAT with the one-click filter, measures how well
// the MAT reconstructs the surface, counts its sheets and seams, and writes
// the MAT, its envelope and its structure.
//   medial-axis-app [output folder] [surface file]
// Without a surface it uses a generated box with rounded edges.
#include "vtkAnalyticShapeSource.h"
#include "vtkMedialAxisWriter.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialStructure.h"
#include "vtkSlabReconstructor.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfaceFileReader.h"

#include "vtkAlgorithmOutput.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  vtkSmartPointer<vtkAlgorithm> source;
  if (argc > 2)
  {
    auto reader = vtkSmartPointer<vtkSurfaceFileReader>::New();
    reader->SetFileName(argv[2]);
    source = reader;
  }
  else
  {
    auto part = vtkSmartPointer<vtkAnalyticShapeSource>::New();
    part->SetShapeToRoundedBox();
    part->SetFilletRadius(0.2);
    source = part;
  }
  const std::string out = argc > 1 ? argv[1] : ".";

  vtkNew<vtkStructuralMedialAxis> mat;
  mat->SetInputConnection(source->GetOutputPort());
  mat->SetPresetToOrganic();
  mat->Update();
  if (mat->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "no medial axis (see the error above)\n";
    return 1;
  }
  vtkNew<vtkMedialReconstructionError> error;
  error->SetInputConnection(0, source->GetOutputPort());
  error->SetInputConnection(1, mat->GetOutputPort(0));
  error->SetNumberOfSamples(20000);
  error->Update();
  std::cout << "medial axis: " << mat->GetOutput()->GetNumberOfPoints() << " spheres in "
            << mat->GetOutput()->GetFieldData()->GetArray("TotalSeconds")->GetComponent(0, 0)
            << " s; two-sided Hausdorff distance " << error->GetHausdorffPercent()
            << "% of the diagonal\n";

  // What each sphere is (point data MedialType), the sheets and the seams;
  // port 1 of the one-click filter, the sites' restricted Voronoi cells,
  // gives the tangent components that cross-check the types.
  vtkNew<vtkMedialStructure> structure;
  structure->SetInputConnection(0, mat->GetOutputPort(0));
  structure->SetCellsConnection(mat->GetOutputPort(1));
  structure->Update();
  std::cout << "structure: " << structure->GetNumberOfSheets() << " sheets, "
            << structure->GetNumberOfSeams() << " seams, "
            << structure->GetNumberOfVerticesOfType(2) << " junction spheres\n";

  vtkNew<vtkMedialAxisWriter> ma;
  ma->SetInputConnection(mat->GetOutputPort(0));
  ma->SetFileName((out + "/mat.ma").c_str());
  vtkNew<vtkSlabReconstructor> envelope;
  envelope->SetInputConnection(mat->GetOutputPort(0));
  vtkNew<vtkXMLPolyDataWriter> vtp;
  vtp->SetInputConnection(envelope->GetOutputPort());
  vtp->SetFileName((out + "/envelope.vtp").c_str());
  vtkNew<vtkXMLPolyDataWriter> typed;
  typed->SetInputConnection(structure->GetOutputPort(0));
  typed->SetFileName((out + "/structure.vtp").c_str());
  return ma->Write() == 1 && vtp->Write() == 1 && typed->Write() == 1 ? 0 : 1;
}
