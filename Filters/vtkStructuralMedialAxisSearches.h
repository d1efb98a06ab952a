// SPDX-License-Identifier: GPL-3.0-or-later
// vtkStructuralMedialAxis's stage observer and its searches over the
// simplification: to a maximum error, and between the fringe settings.
// Internal to the module (not wrapped).
#ifndef vtkStructuralMedialAxisSearches_h
#define vtkStructuralMedialAxisSearches_h

#include "vtkErrorEventText.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStructuralMedialAxis.h"

#include <string>

class vtkAlgorithm;
class vtkAtlasMedialAxisSimplifier;
class vtkQMatSimplifier;

namespace medialaxis
{
// Forwards a stage's progress into its share of the whole, its errors to
// the outer filter, and the outer filter's abort request to the stage.
struct StageObserver
{
  vtkStructuralMedialAxis* Outer = nullptr;
  vtkAlgorithm* Stage = nullptr;
  double Start = 0.0, Share = 0.0;
  std::string Error;

  static void OnProgress(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<StageObserver*>(clientData);
    const double fraction = callData ? *static_cast<double*>(callData) : 0.0;
    self->Outer->UpdateProgress(self->Start + self->Share * fraction);
    if (self->Outer->GetAbortExecute())
    {
      self->Stage->SetAbortExecute(1);
    }
  }
  static void OnError(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<StageObserver*>(clientData);
    self->Error = medialaxis::ErrorEventMessage(callData);
  }
};

struct ErrorTargetResult
{
  int Ok = 0;
  double Hausdorff = 0.0; // two-sided, fraction of the diagonal, at the count chosen
  int Evaluations = 0;
};

// MaximumError: the smallest vertex count whose two-sided Hausdorff distance
// stays within the bound, assuming the distance grows as spheres go. Counts
// are halved from the initial medial mesh until the bound is passed, then
// bisected (geometrically) to within 5%. Evaluation k reports progress in
// [1 - 2^-k, 1 - 2^-(k+1)) of the stage, so the bar only moves forward.
ErrorTargetResult SimplifyToErrorTarget(vtkStructuralMedialAxis* outer,
  vtkAtlasMedialAxisSimplifier* simplifier, vtkQMatSimplifier* qmat, vtkAlgorithm* simplification,
  vtkPolyData* surface, vtkIdType initial, StageObserver& observer);

// Below 200 spheres (where the simplifier's automatic setting turns fringe
// collapses off) an organic shape is simplified both without and with them,
// and the run whose two-sided Hausdorff distance is smaller is kept. With
// them most organic shapes keep their parts and their topology (bunny,
// 50,000 samples -> 100 spheres: 1.8% instead of 4.3%, Euler characteristic
// 1 instead of 9); without them tubes and blobs, whose medial axis is a
// curve or a point, shrink to it (a torus to its centre circle). The kept
// outputs are deep copies; their field data FringeCollapsesUsed says which
// run they come from.
struct FringeChoice
{
  int Ok = 0;
  vtkNew<vtkPolyData> Mat;
  vtkNew<vtkPolyData> Correspondence;
  double HausdorffOff = 0.0, HausdorffOn = 0.0;
};
void SimplifyWithTheCloserFringeSetting(vtkStructuralMedialAxis* outer,
  vtkAtlasMedialAxisSimplifier* simplifier, vtkPolyData* surface, StageObserver& observer,
  FringeChoice& choice);
}

#endif
