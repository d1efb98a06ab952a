// SPDX-License-Identifier: GPL-3.0-or-later
#include "Screenshot.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTubeFilter.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <fstream>

namespace medialaxis
{
namespace
{
// Distinct colours for fillet ids; grey for faces on no fillet.
void FilletColours(vtkLookupTable* table, int fillets)
{
  static const double palette[][3] = { { 0.90, 0.30, 0.24 }, { 0.12, 0.56, 1.00 },
    { 1.00, 0.76, 0.03 }, { 0.24, 0.70, 0.44 }, { 0.85, 0.44, 0.84 }, { 1.00, 0.55, 0.00 },
    { 0.25, 0.88, 0.82 }, { 0.42, 0.35, 0.80 } };
  const int n = fillets > 0 ? fillets : 1;
  table->SetNumberOfTableValues(n + 1);
  table->SetTableRange(-1, n - 1);
  table->SetTableValue(0, 0.80, 0.80, 0.78, 1.0);
  for (int f = 0; f < n; ++f)
  {
    const double* c = palette[f % 8];
    table->SetTableValue(f + 1, c[0], c[1], c[2], 1.0);
  }
  table->Build();
}
}

std::string WriteScreenshot(const std::string& path, vtkPolyData* surface, vtkPolyData* medial,
  vtkPolyData* filletFaces, vtkPolyData* filletLines, int width, int height)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->SetUseDepthPeeling(true);

  const int fillets = filletLines ? static_cast<int>(filletLines->GetNumberOfCells()) : 0;
  vtkNew<vtkLookupTable> filletTable;
  FilletColours(filletTable, fillets);
  vtkNew<vtkPolyDataMapper> surfaceMapper;
  vtkPolyData* shown = filletFaces ? filletFaces : surface;
  surfaceMapper->SetInputData(shown);
  if (filletFaces && filletFaces->GetCellData()->GetArray("FilletId"))
  {
    surfaceMapper->SetScalarModeToUseCellFieldData();
    surfaceMapper->SelectColorArray("FilletId");
    surfaceMapper->SetLookupTable(filletTable);
    surfaceMapper->UseLookupTableScalarRangeOn();
    surfaceMapper->SetColorModeToMapScalars();
  }
  else
  {
    surfaceMapper->ScalarVisibilityOff();
  }
  vtkNew<vtkActor> surfaceActor;
  surfaceActor->SetMapper(surfaceMapper);
  surfaceActor->GetProperty()->SetColor(0.80, 0.80, 0.78);
  surfaceActor->GetProperty()->SetOpacity(0.3);
  renderer->AddActor(surfaceActor);

  double bounds[6];
  shown->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  vtkNew<vtkPolyDataMapper> medialMapper;
  // A curve skeleton (lines only) as tubes.
  vtkNew<vtkTubeFilter> medialTubes;
  if (medial->GetNumberOfPolys() == 0 && medial->GetNumberOfLines() > 0)
  {
    medialTubes->SetInputData(medial);
    medialTubes->SetRadius(0.006 * diagonal);
    medialTubes->SetNumberOfSides(12);
    medialMapper->SetInputConnection(medialTubes->GetOutputPort());
  }
  else
  {
    medialMapper->SetInputData(medial);
  }
  // A medial mesh by its radii, a mid-surface by its thickness.
  for (const char* name : { "Radius", "Thickness" })
  {
    if (vtkDataArray* values = medial->GetPointData()->GetArray(name))
    {
      medialMapper->SetScalarModeToUsePointFieldData();
      medialMapper->SelectColorArray(name);
      medialMapper->SetScalarRange(values->GetRange());
      break;
    }
  }
  vtkNew<vtkLookupTable> radiusTable; // blue: thin, red: thick
  radiusTable->SetHueRange(0.667, 0.0);
  radiusTable->Build();
  medialMapper->SetLookupTable(radiusTable);
  vtkNew<vtkActor> medialActor;
  medialActor->SetMapper(medialMapper);
  renderer->AddActor(medialActor);

  vtkNew<vtkTubeFilter> tubes;
  vtkNew<vtkPolyDataMapper> lineMapper;
  vtkNew<vtkActor> lineActor;
  if (fillets > 0)
  {
    tubes->SetInputData(filletLines);
    tubes->SetRadius(0.005 * diagonal);
    tubes->SetNumberOfSides(12);
    lineMapper->SetInputConnection(tubes->GetOutputPort());
    lineMapper->ScalarVisibilityOff();
    lineActor->SetMapper(lineMapper);
    lineActor->GetProperty()->SetColor(0.55, 0.0, 0.05);
    renderer->AddActor(lineActor);
  }

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(true);
  window->SetAlphaBitPlanes(true);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->Azimuth(35.0);
  camera->Elevation(25.0);
  renderer->ResetCamera();
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (!std::ifstream(path).good())
  {
    return "cannot write " + path;
  }
  return "";
}
}
