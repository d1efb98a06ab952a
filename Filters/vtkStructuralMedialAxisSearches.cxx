// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkStructuralMedialAxisSearches.h"

#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkExecutive.h"
#include "vtkMedialReconstructionError.h"
#include "vtkQMatSimplifier.h"

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
// Runs the simplification stage and measures its output's two-sided
// Hausdorff distance (fraction of the diagonal); negative on failure or
// abort. Shared by the searches over counts and over fringe settings.
struct MeasuredSimplification
{
  vtkStructuralMedialAxis* Outer;
  vtkAlgorithm* Simplification;
  StageObserver& Observer;
  vtkNew<vtkMedialReconstructionError> Measure;

  MeasuredSimplification(vtkStructuralMedialAxis* outer, vtkAlgorithm* simplification,
    vtkPolyData* surface, StageObserver& observer)
    : Outer(outer)
    , Simplification(simplification)
    , Observer(observer)
  {
    this->Measure->SetInputData(0, surface);
    this->Measure->SetInputConnection(1, simplification->GetOutputPort(0));
    this->Measure->SetNumberOfThreads(outer->GetNumberOfThreads());
  }
  double Run()
  {
    if (!this->Simplification->GetExecutive()->Update() || !this->Observer.Error.empty() ||
      this->Outer->GetAbortExecute())
    {
      return -1.0;
    }
    this->Measure->Modified();
    this->Measure->Update();
    return this->Measure->GetHausdorffPercent() / 100.0;
  }
};
}

// MaximumError: the smallest vertex count whose two-sided Hausdorff distance
// stays within the bound, assuming the distance grows as spheres go. Counts
// are halved from the initial medial mesh until the bound is passed, then
// bisected (geometrically) to within 5%. Evaluation k reports progress in
// [1 - 2^-k, 1 - 2^-(k+1)) of the stage, so the bar only moves forward.
ErrorTargetResult SimplifyToErrorTarget(vtkStructuralMedialAxis* outer,
  vtkAtlasMedialAxisSimplifier* simplifier, vtkQMatSimplifier* qmat, vtkAlgorithm* simplification,
  vtkPolyData* surface, vtkIdType initial, StageObserver& observer)
{
  const double bound = outer->GetMaximumError();
  const double stageStart = observer.Start, stageShare = observer.Share;
  MeasuredSimplification measured(outer, simplification, surface, observer);
  ErrorTargetResult result;
  vtkIdType lastTarget = -1; // what the simplification's output now holds
  // The error at `target` vertices, or a negative value on failure or abort.
  auto evaluate = [&](vtkIdType target)
  {
    lastTarget = target;
    const double slice = std::ldexp(1.0, -(result.Evaluations + 1));
    observer.Start = stageStart + stageShare * (1.0 - 2.0 * slice);
    observer.Share = stageShare * slice;
    ++result.Evaluations;
    simplifier->SetTargetNumberOfVertices(target);
    qmat->SetTargetNumberOfVertices(target);
    return measured.Run();
  };
  // Structural MAT: error-bounded collapses (vtkAtlasMedialAxisSimplifier::
  // ErrorBound), as far as they go, at local bounds of the bound, a half, a
  // quarter and an eighth of it; the first whose two-sided distance is within
  // the bound is the result. The local error misses what later collapses
  // around a sphere do to its Atlas and the envelope between the samples, so
  // the distance measured can exceed the local bound (bunny, 10,000 samples:
  // local 0.5% gives 0.75%, local 0.25% 0.46% with 396 spheres, where the
  // count search below ends at 21,862 spheres after six runs, the distance
  // not growing steadily as spheres go). Organic shapes use fringe
  // collapses, as at vertex targets of 200 and more.
  if (simplification == simplifier)
  {
    const int fringe = simplifier->GetFringeCollapses();
    if (fringe == vtkAtlasMedialAxisSimplifier::FringeAutomatic &&
      !outer->GetPreserveSharpFeatures())
    {
      simplifier->SetFringeCollapses(vtkAtlasMedialAxisSimplifier::FringeOn);
    }
    for (int halvings = 0; halvings < 4; ++halvings)
    {
      simplifier->SetErrorBound(std::ldexp(bound, -halvings));
      const double error = evaluate(1);
      if (error < 0.0)
      {
        return result;
      }
      if (error <= bound)
      {
        result.Hausdorff = error;
        result.Ok = 1;
        return result;
      }
    }
    // None within: the vertex count is searched.
    simplifier->SetErrorBound(0.0);
    simplifier->SetFringeCollapses(fringe);
  }
  vtkIdType good = initial, bad = 0; // within the bound at `good`; beyond it at `bad`
  double goodError = -1.0;
  for (vtkIdType target = initial / 2; target >= 1; target /= 2)
  {
    const double error = evaluate(target);
    if (error < 0.0)
    {
      return result;
    }
    if (error > bound)
    {
      bad = target;
      break;
    }
    good = target;
    goodError = error;
  }
  while (bad > 0 && good - bad > 1 && static_cast<double>(good) > 1.05 * static_cast<double>(bad))
  {
    const vtkIdType middle = std::clamp<vtkIdType>(
      static_cast<vtkIdType>(std::llround(std::sqrt(static_cast<double>(good) * bad))), bad + 1,
      good - 1);
    const double error = evaluate(middle);
    if (error < 0.0)
    {
      return result;
    }
    (error > bound ? bad : good) = middle;
    if (middle == good)
    {
      goodError = error;
    }
  }
  // The output at the count chosen, unless the last run was at it (the
  // simplifier is deterministic); even half the initial vertices too many:
  // the initial medial mesh, measured.
  if (lastTarget != good || goodError < 0.0)
  {
    const double error = evaluate(good);
    if (error < 0.0)
    {
      return result;
    }
    goodError = goodError >= 0.0 ? goodError : error;
  }
  result.Hausdorff = goodError;
  result.Ok = 1;
  return result;
}

void SimplifyWithTheCloserFringeSetting(vtkStructuralMedialAxis* outer,
  vtkAtlasMedialAxisSimplifier* simplifier, vtkPolyData* surface, StageObserver& observer,
  FringeChoice& choice)
{
  const double stageStart = observer.Start, stageShare = observer.Share;
  MeasuredSimplification measured(outer, simplifier, surface, observer);
  double errors[2] = { 0.0, 0.0 };
  for (int on = 0; on < 2; ++on)
  {
    observer.Start = stageStart + 0.5 * on * stageShare;
    observer.Share = 0.5 * stageShare;
    simplifier->SetFringeCollapses(
      on ? vtkAtlasMedialAxisSimplifier::FringeOn : vtkAtlasMedialAxisSimplifier::FringeOff);
    errors[on] = measured.Run();
    if (errors[on] < 0.0)
    {
      return;
    }
    if (on == 0 || errors[1] < errors[0])
    {
      choice.Mat->DeepCopy(simplifier->GetOutput(0));
      choice.Correspondence->DeepCopy(simplifier->GetOutputDataObject(1));
    }
  }
  simplifier->SetFringeCollapses(vtkAtlasMedialAxisSimplifier::FringeAutomatic);
  choice.HausdorffOff = errors[0];
  choice.HausdorffOn = errors[1];
  choice.Ok = 1;
}
}
