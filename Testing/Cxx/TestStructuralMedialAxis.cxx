// SPDX-License-Identifier: GPL-3.0-or-later
// The one-click filter: the same result as the chain of stage filters, its
// presets, per-stage times and counts, progress, abort and stage errors.
#include "Mesh/MedialMesh.h"
#include "TestHelpers.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkMedialMeshConversion.h"
#include "vtkStructuralMedialAxis.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>
#include <vector>

using namespace medialaxis;

namespace
{
using test::FieldValue;

struct ProgressLog
{
  std::vector<double> Values;
  double AbortAt = 2.0;
  static void Record(vtkObject* caller, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ProgressLog*>(clientData);
    self->Values.push_back(*static_cast<double*>(callData));
    if (self->Values.back() > self->AbortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  }
};
}

TEST(StructuralMedialAxis, PresetsFollowThePaper)
{
  vtkNew<vtkStructuralMedialAxis> filter;
  EXPECT_EQ(filter->GetNumberOfSamples(), 10000);
  EXPECT_EQ(filter->GetTargetNumberOfVertices(), 1000);
  EXPECT_FALSE(filter->GetPreserveSharpFeatures());
  EXPECT_TRUE(filter->GetGenerateEnvelope());
  EXPECT_TRUE(filter->GetAdaptiveSampling()); // organic shapes: thin parts sampled densely
  filter->SetPresetToCAD();
  EXPECT_EQ(filter->GetNumberOfSamples(), 50000);
  EXPECT_EQ(filter->GetTargetNumberOfVertices(), 5000);
  EXPECT_TRUE(filter->GetPreserveSharpFeatures());
  EXPECT_FALSE(filter->GetAdaptiveSampling());
  filter->SetPresetToOrganic();
  EXPECT_TRUE(filter->GetAdaptiveSampling());
}

TEST(StructuralMedialAxis, SameResultAsTheChainWithTimesCountsAndProgress)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToRoundedBox();
  shape->SetFilletRadius(0.2);
  shape->SetResolution(16);

  vtkNew<vtkStructuralMedialAxis> filter;
  filter->SetInputConnection(shape->GetOutputPort());
  filter->SetPresetToCAD();
  filter->SetNumberOfSamples(4000);
  filter->SetTargetNumberOfVertices(400);
  ProgressLog log;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(&ProgressLog::Record);
  progress->SetClientData(&log);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  filter->Update();
  vtkPolyData* mat = filter->GetOutput(0);

  // The chain of stage filters with the same parameters.
  test::InitialMedialPipeline chain(shape->GetOutputPort(), 4000);
  vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
  simplifier->SetInputConnection(0, chain.Voronoi->GetOutputPort());
  simplifier->SetInputConnection(1, chain.Rvd->GetOutputPort(0));
  simplifier->SetTargetNumberOfVertices(400);
  simplifier->PreserveSharpFeaturesOn();
  simplifier->Update();
  vtkPolyData* expected = simplifier->GetOutput(0);
  ASSERT_EQ(mat->GetNumberOfPoints(), 400);
  ASSERT_EQ(expected->GetNumberOfPoints(), 400);
  for (vtkIdType i = 0; i < 400; ++i)
  {
    double p[3], q[3];
    mat->GetPoint(i, p);
    expected->GetPoint(i, q);
    ASSERT_EQ(p[0], q[0]);
    ASSERT_EQ(p[1], q[1]);
    ASSERT_EQ(p[2], q[2]);
  }
  EXPECT_EQ(mat->GetNumberOfPolys(), expected->GetNumberOfPolys());
  EXPECT_EQ(ValidateMedialPolyData(mat), "");

  // Times and counts.
  double sum = 0.0;
  for (const char* stage : { "SamplingSeconds", "RestrictedVoronoiSeconds",
         "VoronoiMedialAxisSeconds", "SimplificationSeconds" })
  {
    const double t = FieldValue(mat, stage);
    EXPECT_GT(t, 0.0) << stage;
    sum += t;
  }
  EXPECT_NEAR(FieldValue(mat, "TotalSeconds"), sum, 1e-12);
  EXPECT_EQ(FieldValue(mat, "Sites"), 4000.0);
  EXPECT_EQ(FieldValue(mat, "InitialVertices"),
    static_cast<double>(chain.Voronoi->GetOutput()->GetNumberOfPoints()));
  EXPECT_GT(FieldValue(mat, "Collapses"), 0.0);
  // The correspondence and the sites.
  vtkPolyData* cells = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(1));
  EXPECT_NE(cells->GetCellData()->GetArray("MedialVertexId"), nullptr);
  EXPECT_EQ(vtkPolyData::SafeDownCast(filter->GetOutputDataObject(2))->GetNumberOfPoints(), 4000);

  // The envelope: balls, cones and slabs of the medial mesh.
  vtkPolyData* envelope = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(3));
  EXPECT_GT(envelope->GetNumberOfPolys(), 0);
  EXPECT_NE(envelope->GetCellData()->GetArray("PrimitiveKind"), nullptr);
  EXPECT_GT(FieldValue(mat, "EnvelopeSeconds"), 0.0);

  // Progress never goes back and ends at 1, through every stage's share.
  ASSERT_GT(log.Values.size(), 10u);
  for (std::size_t i = 1; i < log.Values.size(); ++i)
  {
    EXPECT_GE(log.Values[i], log.Values[i - 1]);
  }
  EXPECT_EQ(log.Values.back(), 1.0);
  EXPECT_TRUE(std::any_of(log.Values.begin(), log.Values.end(),
    [](double v) { return v > 0.4 && v < 0.9; })); // inside the simplification
}

TEST(StructuralMedialAxis, AbortLeavesAnEmptyOutput)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToTorus();
  shape->SetResolution(16);
  vtkNew<vtkStructuralMedialAxis> filter;
  filter->SetInputConnection(shape->GetOutputPort());
  filter->SetNumberOfSamples(3000);
  filter->SetTargetNumberOfVertices(100);
  ProgressLog log;
  log.AbortAt = 0.5;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(&ProgressLog::Record);
  progress->SetClientData(&log);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  filter->Update();
  EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_LT(log.Values.back(), 1.0);
}

TEST(StructuralMedialAxis, StageErrorsNameTheStageAndTheDefect)
{
  auto run = [](vtkPolyData* surface)
  {
    vtkNew<vtkStructuralMedialAxis> filter;
    vtkNew<test::ErrorCatcher> errors;
    filter->AddObserver(vtkCommand::ErrorEvent, errors);
    filter->SetInputData(surface);
    filter->SetNumberOfSamples(500);
    filter->SetTargetNumberOfVertices(50);
    filter->Update();
    EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
    return errors->Last;
  };
  vtkNew<vtkPolyData> empty;
  EXPECT_NE(run(empty).find("has no polygons"), std::string::npos);

  // A sphere with one triangle missing is open.
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToSphere();
  shape->SetResolution(8);
  shape->Update();
  vtkNew<vtkPolyData> open;
  open->DeepCopy(shape->GetOutput());
  open->BuildCells();
  open->DeleteCell(0);
  open->RemoveDeletedCells();
  const std::string message = run(open);
  EXPECT_NE(
    message.find("stage Sampling failed: cannot sample: surface is not closed: 3 boundary edges"),
    std::string::npos)
    << message;
}

namespace
{
// Everything a run produces that could differ: medial points, radii and
// cells, and the envelope's points, as exact values.
struct Fingerprint
{
  std::vector<double> Values;
  std::vector<vtkIdType> Cells;
  bool operator==(const Fingerprint& o) const
  {
    return this->Values == o.Values && this->Cells == o.Cells;
  }
};

Fingerprint RunOnShape(int shape)
{
  vtkNew<vtkAnalyticShapeSource> source;
  if (shape == 0)
  {
    source->SetShapeToTorus();
  }
  else
  {
    source->SetShapeToRoundedBox();
    source->SetFilletRadius(0.2);
  }
  source->SetResolution(16);
  vtkNew<vtkStructuralMedialAxis> filter;
  filter->SetInputConnection(source->GetOutputPort());
  filter->SetNumberOfSamples(3000);
  filter->SetTargetNumberOfVertices(300);
  filter->SetPreserveSharpFeatures(shape == 1);
  filter->Update();
  Fingerprint f;
  for (int port : { 0, 3 })
  {
    vtkPolyData* out = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(port));
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double p[3];
      out->GetPoint(i, p);
      f.Values.insert(f.Values.end(), p, p + 3);
    }
    for (vtkCellArray* cells : { out->GetPolys(), out->GetLines(), out->GetVerts() })
    {
      for (vtkIdType i = 0; i < cells->GetConnectivityArray()->GetNumberOfValues(); ++i)
      {
        f.Cells.push_back(static_cast<vtkIdType>(cells->GetConnectivityArray()->GetTuple1(i)));
      }
    }
  }
  vtkDataArray* radii = filter->GetOutput(0)->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < radii->GetNumberOfTuples(); ++i)
  {
    f.Values.push_back(radii->GetTuple1(i));
  }
  return f;
}
}

TEST(StructuralMedialAxis, ConcurrentPipelinesGiveTheResultsOfRunningAlone)
{
  // Two pipelines on different inputs, each alone, then both at once in two
  // threads of this process: bit-identical results.
  const Fingerprint torus = RunOnShape(0), box = RunOnShape(1);
  ASSERT_FALSE(torus.Values.empty());
  ASSERT_FALSE(box.Values.empty());
  for (int round = 0; round < 2; ++round)
  {
    Fingerprint concurrentTorus, concurrentBox;
    std::thread first([&] { concurrentTorus = RunOnShape(0); });
    std::thread second([&] { concurrentBox = RunOnShape(1); });
    first.join();
    second.join();
    EXPECT_TRUE(concurrentTorus == torus) << round;
    EXPECT_TRUE(concurrentBox == box) << round;
  }
}

// FinalFit reaches the simplifier: its rounds and distances travel as field
// data; off, the spheres stay where the collapses put them.
TEST(StructuralMedialAxis, FinalFitSwitch)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToTorus();
  shape->SetResolution(24);
  auto run = [&](bool fit)
  {
    vtkNew<vtkStructuralMedialAxis> filter;
    filter->SetInputConnection(shape->GetOutputPort());
    filter->SetNumberOfSamples(3000);
    filter->SetTargetNumberOfVertices(300);
    filter->SetFinalFit(fit);
    filter->Update();
    vtkSmartPointer<vtkPolyData> mat = filter->GetOutput(0);
    return mat;
  };
  vtkNew<vtkStructuralMedialAxis> defaults;
  EXPECT_TRUE(defaults->GetFinalFit());
  const vtkSmartPointer<vtkPolyData> fitted = run(true), plain = run(false);
  EXPECT_GT(test::FieldValue(fitted, "FitRounds"), 0.0);
  EXPECT_LT(test::FieldValue(fitted, "FitRMSAfter"), test::FieldValue(fitted, "FitRMSBefore"));
  EXPECT_EQ(test::FieldValue(plain, "FitRounds"), 0.0);
  EXPECT_EQ(test::FieldValue(plain, "FitRMSAfter"), 0.0);
  ASSERT_EQ(fitted->GetNumberOfPoints(), plain->GetNumberOfPoints());
  bool moved = false;
  for (vtkIdType i = 0; i < plain->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    plain->GetPoint(i, a);
    fitted->GetPoint(i, b);
    moved = moved || a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
  }
  EXPECT_TRUE(moved);
}

TEST(StructuralMedialAxis, FewSpheresKeepTheCloserFringeSetting)
{
  // Below 200 spheres an organic shape is simplified without and with
  // fringe collapses and the closer run is kept: a torus, whose medial axis
  // is a circle, shrinks to it without them.
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToTorus();
  shape->SetResolution(24);
  vtkNew<vtkStructuralMedialAxis> filter;
  filter->SetInputConnection(shape->GetOutputPort());
  filter->SetNumberOfSamples(10000);
  filter->SetTargetNumberOfVertices(100);
  filter->SetGenerateEnvelope(false);
  filter->Update();
  vtkPolyData* mat = filter->GetOutput(0);
  const double off = test::FieldValue(mat, "HausdorffWithoutFringeCollapses");
  const double on = test::FieldValue(mat, "HausdorffWithFringeCollapses");
  std::cout << "torus, 100 spheres: without fringe collapses " << 100 * off << "%, with them "
            << 100 * on << "%\n";
  EXPECT_EQ(mat->GetNumberOfPoints(), 100);
  EXPECT_GT(off, 0.0);
  EXPECT_LT(off, on);
  EXPECT_EQ(test::FieldValue(mat, "FringeCollapsesUsed"), 0.0);
  medialaxis::MedialMesh mesh;
  ASSERT_EQ(medialaxis::PolyDataToMedialMesh(mat, mesh), "");
  EXPECT_EQ(medialaxis::EulerCharacteristic(mesh), 0);
  // At 200 spheres and more, and on CAD parts, one run with the automatic
  // setting: no such field data.
  filter->SetTargetNumberOfVertices(200);
  filter->Update();
  EXPECT_EQ(
    filter->GetOutput(0)->GetFieldData()->GetArray("HausdorffWithFringeCollapses"), nullptr);
}

TEST(StructuralMedialAxis, MaximumErrorGivesFewSpheresWithinIt)
{
  // A torus, whose medial axis is a circle: a few dozen spheres are within
  // 1% of the diagonal (Structural MAT).
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToTorus();
  shape->SetResolution(24);
  auto run = [&](double maximumError, vtkIdType target, int strategy)
  {
    vtkNew<vtkStructuralMedialAxis> filter;
    filter->SetInputConnection(shape->GetOutputPort());
    filter->SetNumberOfSamples(3000);
    filter->SetMaximumError(maximumError);
    filter->SetTargetNumberOfVertices(target);
    filter->SetStrategy(strategy);
    filter->SetGenerateEnvelope(false);
    filter->Update();
    vtkSmartPointer<vtkPolyData> mat = filter->GetOutput(0);
    return mat;
  };
  for (int strategy : { vtkStructuralMedialAxis::Structural, vtkStructuralMedialAxis::QMat })
  {
    // (Q-MAT has no final fit: its initial medial mesh is 1.5% away.)
    const double bound = strategy == vtkStructuralMedialAxis::QMat ? 0.03 : 0.01;
    const vtkSmartPointer<vtkPolyData> searched = run(bound, 1000, strategy);
    const vtkIdType count = searched->GetNumberOfPoints();
    const double reached = test::FieldValue(searched, "ErrorTargetHausdorff");
    const double evaluations = test::FieldValue(searched, "ErrorTargetEvaluations");
    std::cout << (strategy == vtkStructuralMedialAxis::QMat ? "Q-MAT" : "Structural MAT")
              << " within " << 100 * bound << "%: " << count << " of "
              << test::FieldValue(searched, "InitialVertices") << " vertices, " << 100 * reached
              << "% after " << evaluations << " evaluations\n";
    EXPECT_EQ(test::FieldValue(searched, "MaximumError"), bound);
    EXPECT_GT(reached, 0.0);
    EXPECT_LE(reached, bound);
    // Far fewer spheres than the initial medial mesh (the vertex target of
    // 1,000 is ignored).
    EXPECT_LT(count, test::FieldValue(searched, "InitialVertices") / 8);
    EXPECT_NE(count, 1000);
    if (strategy == vtkStructuralMedialAxis::Structural)
    {
      // Error-bounded collapses, at the bound or a half, quarter or eighth
      // of it: one run each, as far as the bound lets them go.
      EXPECT_GE(evaluations, 1.0);
      EXPECT_LE(evaluations, 4.0);
      const double local = test::FieldValue(searched, "ErrorBound");
      EXPECT_EQ(local, std::ldexp(bound, 1 - static_cast<int>(evaluations)));
      EXPECT_LT(count, 60);
      continue;
    }
    // Q-MAT: the vertex count is searched, and the result is exactly what
    // that count as a target gives.
    EXPECT_GT(evaluations, 2.0);
    const vtkSmartPointer<vtkPolyData> direct = run(0.0, count, strategy);
    ASSERT_EQ(direct->GetNumberOfPoints(), count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      double a[3], b[3];
      searched->GetPoint(i, a);
      direct->GetPoint(i, b);
      ASSERT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << i;
    }
    EXPECT_EQ(direct->GetFieldData()->GetArray("ErrorTargetEvaluations"), nullptr);
  }
}
