// SPDX-License-Identifier: GPL-3.0-or-later
// Every analytic shape is closed, manifold, outward, with the exact area and
// volume within 1% at the default resolution, and vertices on the surface.
#include "Surface/AnalyticShapes.h"
#include "Surface/SurfacePreparation.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkMedialSurfaceValidator.h"

#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace medialaxis;

namespace
{
struct ShapeCase
{
  const char* Name;
  int Shape;
  std::function<void(vtkAnalyticShapeSource*)> Configure;
  // Distance from a point to the exact surface.
  std::function<double(const double*)> SurfaceDistance;
};

double Clamp(double v, double lo, double hi)
{
  return std::max(lo, std::min(hi, v));
}

double RoundedBoxDistance(const double* p, double hx, double hy, double hz, double rho)
{
  const double q[3] = { Clamp(p[0], -(hx - rho), hx - rho), Clamp(p[1], -(hy - rho), hy - rho),
    Clamp(p[2], -(hz - rho), hz - rho) };
  const double d = std::sqrt(
    (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  return std::fabs(d - rho);
}

double BoxDistance(const double* p, double h)
{
  // Points of a box surface have max |coordinate| = h.
  return std::fabs(std::max({ std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]) }) - h);
}

const ShapeCase Cases[] = {
  { "Sphere", vtkAnalyticShapeSource::SPHERE, [](vtkAnalyticShapeSource* s) { s->SetRadius(1.5); },
    [](const double* p)
    { return std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.5); } },
  { "Capsule", vtkAnalyticShapeSource::CAPSULE,
    [](vtkAnalyticShapeSource* s)
    {
      s->SetRadius(0.5);
      s->SetLength(2.0);
    },
    [](const double* p) { return RoundedBoxDistance(p, 0.5, 0.5, 1.5, 0.5); } },
  { "Torus", vtkAnalyticShapeSource::TORUS,
    [](vtkAnalyticShapeSource* s)
    {
      s->SetMajorRadius(2.0);
      s->SetMinorRadius(0.5);
    },
    [](const double* p)
    {
      const double ring = std::sqrt(p[0] * p[0] + p[1] * p[1]) - 2.0;
      return std::fabs(std::sqrt(ring * ring + p[2] * p[2]) - 0.5);
    } },
  { "Box", vtkAnalyticShapeSource::BOX, [](vtkAnalyticShapeSource*) {},
    [](const double* p) { return BoxDistance(p, 1.0); } },
  { "RoundedBox", vtkAnalyticShapeSource::ROUNDED_BOX,
    [](vtkAnalyticShapeSource* s)
    {
      s->SetXLength(2.0);
      s->SetYLength(1.0);
      s->SetZLength(3.0);
      s->SetFilletRadius(0.2);
    },
    [](const double* p) { return RoundedBoxDistance(p, 1.0, 0.5, 1.5, 0.2); } },
  { "Cylinder", vtkAnalyticShapeSource::CYLINDER,
    [](vtkAnalyticShapeSource* s)
    {
      s->SetRadius(1.0);
      s->SetLength(3.0);
    },
    [](const double* p)
    {
      const double radial = std::sqrt(p[0] * p[0] + p[1] * p[1]);
      const double side = std::fabs(radial - 1.0);
      const double cap = std::fabs(std::fabs(p[2]) - 1.5);
      return std::min(
        radial <= 1.0 + 1e-12 ? cap : 1e9, std::fabs(p[2]) <= 1.5 + 1e-12 ? side : 1e9);
    } },
  { "LBlock", vtkAnalyticShapeSource::L_BLOCK, [](vtkAnalyticShapeSource*) {},
    [](const double* p)
    {
      double d = std::min({ 1.0 - std::fabs(p[0]), 1.0 - std::fabs(p[1]), 1.0 - std::fabs(p[2]) });
      if (p[0] >= -1e-12 && p[1] >= -1e-12)
      {
        d = std::min({ d, std::fabs(p[0]), std::fabs(p[1]) }); // the inner walls
      }
      return std::fabs(d);
    } },
  { "Dumbbell", vtkAnalyticShapeSource::DUMBBELL,
    [](vtkAnalyticShapeSource* s)
    {
      s->SetLength(1.0);
      s->SetRadius(0.2);
      s->SetMinorRadius(0.02);
    },
    [](const double* p)
    {
      const double radial = std::sqrt(p[0] * p[0] + p[1] * p[1]);
      const double top = std::hypot(radial, p[2] - 0.3), bottom = std::hypot(radial, p[2] + 0.3);
      return std::min({ std::fabs(top - 0.2), std::fabs(bottom - 0.2),
        std::fabs(p[2]) < 0.3 ? std::fabs(radial - 0.02) : 1e9 });
    } },
  { "PlateWithBoss", vtkAnalyticShapeSource::PLATE_WITH_BOSS,
    [](vtkAnalyticShapeSource* s)
    {
      s->SetXLength(1.0);
      s->SetZLength(0.01);
      s->SetRadius(0.15);
      s->SetLength(0.2);
    },
    [](const double* p)
    {
      const double radial = std::sqrt(p[0] * p[0] + p[1] * p[1]);
      const double rim = std::max(std::fabs(p[0]), std::fabs(p[1]));
      return std::min({ std::fabs(std::fabs(p[2]) - 0.005), std::fabs(rim - 0.5),
        p[2] > 0.005 ? std::fabs(radial - 0.15) : 1e9,
        radial <= 0.15 + 1e-12 ? std::fabs(p[2] - 0.205) : 1e9 });
    } },
  { "BlockWithFin", vtkAnalyticShapeSource::BLOCK_WITH_FIN,
    [](vtkAnalyticShapeSource* s)
    {
      s->SetXLength(2.0);
      s->SetYLength(1.0);
      s->SetZLength(1.0);
      s->SetLength(0.5);
      s->SetThickness(0.02);
    },
    [](const double* p)
    {
      // The block [-1, 1] x [-0.5, 0.5] x [-0.5, 0.5]; the fin [-0.5, 0.5] x
      // [-0.01, 0.01] x [0.5, 1].
      const bool inBlock = std::fabs(p[0]) <= 1.0 + 1e-12 && std::fabs(p[1]) <= 0.5 + 1e-12 &&
        std::fabs(p[2]) <= 0.5 + 1e-12;
      const bool inFin = std::fabs(p[0]) <= 0.5 + 1e-12 && std::fabs(p[1]) <= 0.01 + 1e-12 &&
        p[2] >= 0.5 - 1e-12 && p[2] <= 1.0 + 1e-12;
      const double block = std::min({ std::fabs(std::fabs(p[0]) - 1.0),
        std::fabs(std::fabs(p[1]) - 0.5), std::fabs(std::fabs(p[2]) - 0.5) });
      const double fin = std::min({ std::fabs(std::fabs(p[0]) - 0.5),
        std::fabs(std::fabs(p[1]) - 0.01), std::fabs(p[2] - 1.0) });
      return std::min(inBlock ? block : 1e9, inFin ? fin : 1e9);
    } },
};

class AnalyticShape : public ::testing::TestWithParam<ShapeCase>
{
};
}

TEST_P(AnalyticShape, ClosedManifoldOutwardWithExactMeasures)
{
  const ShapeCase& c = GetParam();
  vtkNew<vtkAnalyticShapeSource> source;
  source->SetShape(c.Shape);
  c.Configure(source);
  vtkNew<vtkMedialSurfaceValidator> validator;
  validator->SetInputConnection(source->GetOutputPort());
  validator->FixOrientationOff(); // any orientation defect is then an error
  validator->Update();
  ASSERT_TRUE(validator->GetValid()) << c.Name << ": " << validator->GetErrorMessage();
  EXPECT_EQ(validator->GetNumberOfMergedPoints(), 0) << "duplicate points in " << c.Name;
  EXPECT_EQ(validator->GetNumberOfDegenerateTriangles(), 0);
  EXPECT_EQ(validator->GetNumberOfDuplicateTriangles(), 0);
  EXPECT_EQ(validator->GetNumberOfComponents(), 1);
  EXPECT_GT(validator->GetVolume(), 0.0);
  EXPECT_NEAR(validator->GetArea() / source->GetExactArea(), 1.0, 0.01) << c.Name;
  EXPECT_NEAR(validator->GetVolume() / source->GetExactVolume(), 1.0, 0.01) << c.Name;

  vtkPolyData* mesh = source->GetOutput();
  double worst = 0.0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst, c.SurfaceDistance(mesh->GetPoint(i)));
  }
  EXPECT_LT(worst, 1e-12) << c.Name << ": a vertex is off the exact surface";
}

INSTANTIATE_TEST_SUITE_P(AllShapes, AnalyticShape, ::testing::ValuesIn(Cases),
  [](const ::testing::TestParamInfo<ShapeCase>& info) { return info.param.Name; });

TEST(AnalyticShapes, ConvergesWithResolution)
{
  double previous = 1.0;
  for (int resolution : { 4, 8, 16, 32 })
  {
    const TriangleMesh m = MakeRoundedBox({ 2, 2, 2 }, 0.5, resolution);
    const double error =
      std::fabs(SurfaceArea(m) / RoundedBoxAreaVolume({ 2, 2, 2 }, 0.5).Area - 1.0);
    EXPECT_LT(error, previous);
    previous = error;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(AnalyticShapes, CentreTranslatesTheShape)
{
  vtkNew<vtkAnalyticShapeSource> source;
  source->SetShapeToSphere();
  source->SetCenter(10, -5, 2);
  source->Update();
  double bounds[6];
  source->GetOutput()->GetBounds(bounds);
  EXPECT_NEAR(0.5 * (bounds[0] + bounds[1]), 10.0, 1e-12);
  EXPECT_NEAR(0.5 * (bounds[2] + bounds[3]), -5.0, 1e-12);
  EXPECT_NEAR(0.5 * (bounds[4] + bounds[5]), 2.0, 1e-12);
}

TEST(AnalyticShapes, InvalidParametersAreReported)
{
  EXPECT_THROW(MakeTorus(1.0, 2.0, 8), std::invalid_argument);
  EXPECT_THROW(MakeRoundedBox({ 1, 1, 1 }, 0.8, 8), std::invalid_argument);
  EXPECT_THROW(MakeSphere(-1.0, 8), std::invalid_argument);
  EXPECT_THROW(MakeDumbbell(1.0, 0.3, 0.02, 8), std::invalid_argument); // the balls overlap
  EXPECT_THROW(MakeDumbbell(1.0, 0.2, 0.25, 8), std::invalid_argument); // neck wider than balls
  EXPECT_THROW(MakePlateWithBoss(1.0, 0.01, 0.6, 0.1, 8), std::invalid_argument);
  EXPECT_THROW(MakeBlockWithFin({ 2, 1, 1 }, 0.5, 0.6, 8), std::invalid_argument); // too thick
  EXPECT_THROW(MakeBlockWithFin({ 2, 1, 1 }, 0.0, 0.02, 8), std::invalid_argument);
}
