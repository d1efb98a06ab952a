// SPDX-License-Identifier: GPL-3.0-or-later
// Surfaces from unsigned distances given as C++ functions, and the sheet's
// hole closing, below and through vtkUnsignedDistanceSurfaceExtractor.
#include "Udf/DistanceFunction.h"
#include "Udf/ShellSheet.h"
#include "vtkUnsignedDistanceSurfaceExtractor.h"

#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
// The unit disk in z = 0.
double DiskDistance(const double* p)
{
  const double outside = std::max(0.0, std::hypot(p[0], p[1]) - 1.0);
  return std::hypot(outside, p[2]);
}

long long FieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? static_cast<long long>(array->GetComponent(0, 0)) : -1;
}

struct ErrorCounter : vtkCommand
{
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* text) override
  {
    this->Text += static_cast<const char*>(text);
  }
  std::string Text;
};
}

TEST(UnsignedDistance, DiskFromAFunctionSnapsOntoItsPlane)
{
  for (const bool snap : { false, true })
  {
    vtkNew<vtkUnsignedDistanceSurfaceExtractor> extractor;
    long long calls = 0;
    extractor->SetDistanceFunction(
      [&calls](vtkIdType count, const double* points, double* distances)
      {
        ++calls;
        EXPECT_LE(count, 65536);
        for (vtkIdType i = 0; i < count; ++i)
        {
          distances[i] = DiskDistance(points + 3 * i);
        }
      });
    extractor->SetFunctionBounds(-1, 1, -1, 1, 0, 0);
    extractor->SetResampleDimension(64);
    extractor->SetSnapToZeroSet(snap);
    extractor->Update();
    vtkPolyData* surface = extractor->GetOutput();
    ASSERT_GT(surface->GetNumberOfPolys(), 500);
    EXPECT_GE(calls, 1);
    EXPECT_EQ(FieldValue(surface, "BoundaryLoops"), 1);
    EXPECT_EQ(FieldValue(surface, "JunctionEdges"), 0);
    // 64 points along the longest side, 6 free cells on each side.
    const double spacing = 2.0 / (64 - 1 - 12);
    EXPECT_NEAR(extractor->GetUsedEpsilon(), 2 * spacing, 1e-12);
    double highest = 0.0, widest = 0.0;
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    {
      const double* p = surface->GetPoint(i);
      highest = std::max(highest, std::abs(p[2]));
      widest = std::max(widest, std::hypot(p[0], p[1]));
    }
    EXPECT_LT(widest, 1.0 + spacing);
    EXPECT_GT(widest, 1.0 - spacing);
    // The shell's medial axis of a flat disk is its plane already, up to the
    // sampling; the exact projection puts every point on it (up to the
    // central differences at the rim).
    EXPECT_LT(highest, snap ? 1e-4 * spacing : spacing);
  }
}

TEST(UnsignedDistance, FunctionErrorsAreReported)
{
  vtkNew<ErrorCounter> errors;
  vtkNew<vtkUnsignedDistanceSurfaceExtractor> extractor;
  extractor->AddObserver(vtkCommand::ErrorEvent, errors);
  extractor->SetResampleDimension(32);
  extractor->Update();
  EXPECT_NE(errors->Text.find("no input and no distance function"), std::string::npos);

  extractor->SetDistanceFunction([](vtkIdType count, const double*, double* distances)
    { std::fill(distances, distances + count, std::numeric_limits<double>::quiet_NaN()); });
  extractor->SetFunctionBounds(-1, 1, -1, 1, 0, 0);
  errors->Text.clear();
  extractor->Update();
  EXPECT_NE(errors->Text.find("not a number"), std::string::npos) << errors->Text;

  extractor->SetDistanceFunction([](vtkIdType count, const double* points, double* distances)
    { std::fill(distances, distances + count, -1.0); });
  errors->Text.clear();
  extractor->Update();
  EXPECT_NE(errors->Text.find("negative values"), std::string::npos) << errors->Text;

  extractor->SetDistanceFunction(
    [](vtkIdType count, const double* points, double* distances)
    {
      for (vtkIdType i = 0; i < count; ++i)
        distances[i] = DiskDistance(points + 3 * i);
    });
  extractor->SetFunctionBounds(1, -1, 0, 0, 0, 0);
  errors->Text.clear();
  extractor->Update();
  EXPECT_NE(errors->Text.find("is not a box"), std::string::npos) << errors->Text;

  extractor->RemoveDistanceFunction();
  EXPECT_FALSE(extractor->HasDistanceFunction());
}

TEST(UnsignedDistance, NarrowHolesOfTheSheetAreClosed)
{
  // A flat 20 x 20 grid of spheres of radius epsilon, without the two
  // triangles of one square (a hole narrower than two epsilon) and without
  // a 5 x 5 block (a hole as wide as 5 epsilon).
  const double epsilon = 1.0;
  medialaxis::MedialMesh medial;
  const int n = 21;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      medial.Centers.push_back({ double(i), double(j), 0.0 });
      medial.Radii.push_back(epsilon);
    }
  }
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const bool small = i == 3 && j == 3;
      const bool large = i >= 10 && i < 15 && j >= 10 && j < 15;
      if (small || large)
      {
        continue;
      }
      const medialaxis::Index a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      medial.Faces.push_back({ a, b, c });
      medial.Faces.push_back({ a, c, d });
    }
  }
  medialaxis::ShellSheetOptions options;
  options.Epsilon = epsilon;
  const medialaxis::ShellSheet sheet = medialaxis::ExtractShellSheet(medial, options, nullptr);
  EXPECT_EQ(sheet.FilledHoles, 1u);
  EXPECT_EQ(sheet.Surface.Triangles.size(), medial.Faces.size() + 2);
  // The outer boundary and the large hole are left.
  EXPECT_EQ(medialaxis::CountBoundaryLoops(sheet.Surface), 2u);
}

TEST(UnsignedDistance, FunctionProbeReadsTheGradient)
{
  // |x - 0.3| along x: distance 0.7 at the origin's neighbour, gradient -x.
  const medialaxis::DistanceFunction plane =
    [](const std::vector<medialaxis::Point3>& points, std::vector<double>& distances)
  {
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      distances[i] = std::abs(points[i][0] - 0.3);
    }
    return std::string();
  };
  const medialaxis::FunctionProbe probe(plane);
  std::vector<double> values;
  std::vector<medialaxis::Point3> gradients;
  ASSERT_TRUE(probe.Values({ { -0.4, 2.0, 1.0 } }, values).empty());
  EXPECT_DOUBLE_EQ(values[0], 0.7);
  ASSERT_TRUE(probe.Gradients({ { -0.4, 2.0, 1.0 } }, { 0.1 }, gradients).empty());
  EXPECT_NEAR(gradients[0][0], -1.0, 1e-12);
  EXPECT_NEAR(gradients[0][1], 0.0, 1e-12);
  EXPECT_TRUE(probe.Exact());
}
