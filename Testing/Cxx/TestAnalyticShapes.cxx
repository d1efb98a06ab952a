// SPDX-License-Identifier: GPL-3.0-or-later
// Every analytic shape is closed, manifold, outward, with the exact area and
// volume within 1% at the default resolution, and vertices on the surface.
#include "Surface/AnalyticShapes.h"
#include "Surface/SurfacePreparation.h"
#include "Surface/WallShapes.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkMedialSurfaceValidator.h"

#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

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

// Distance in the (y, z) plane from p to a section's outline, given as
// straight segments and quarter-circle arcs (centre, radius, and the
// quadrant's signs: the arc is the part of the circle on that side).
struct Segment
{
  double Y0, Z0, Y1, Z1;
};
struct Arc
{
  double Y, Z, Radius, SignY, SignZ;
};
double OutlineDistance(const double* p, double halfLength, const std::vector<Segment>& segments,
  const std::vector<Arc>& arcs)
{
  if (std::fabs(p[0]) > halfLength + 1e-12)
  {
    return 1e9;
  }
  double best = 1e9;
  for (const Segment& s : segments)
  {
    const double dy = s.Y1 - s.Y0, dz = s.Z1 - s.Z0;
    const double u = Clamp(((p[1] - s.Y0) * dy + (p[2] - s.Z0) * dz) / (dy * dy + dz * dz), 0, 1);
    best = std::min(best, std::hypot(p[1] - s.Y0 - u * dy, p[2] - s.Z0 - u * dz));
  }
  for (const Arc& a : arcs)
  {
    if ((p[1] - a.Y) * a.SignY >= -1e-12 && (p[2] - a.Z) * a.SignZ >= -1e-12)
    {
      best = std::min(best, std::fabs(std::hypot(p[1] - a.Y, p[2] - a.Z) - a.Radius));
    }
  }
  return best;
}

// The T-plate's outline (section of TPlateSection): plate 2 wide, walls
// 0.05 thick, rib 1 high, junction fillets of radius rho.
double TPlateDistance(const double* p, double rho)
{
  const double t = 0.025, w = 1.0, h = t + 1.0;
  return OutlineDistance(p, 1.0,
    { { -w, -t, w, -t }, { w, -t, w, t }, { w, t, t + rho, t }, { t, t + rho, t, h },
      { t, h, -t, h }, { -t, h, -t, t + rho }, { -t - rho, t, -w, t }, { -w, t, -w, -t } },
    rho > 0
      ? std::vector<Arc>{ { t + rho, t + rho, rho, -1, -1 }, { -t - rho, t + rho, rho, 1, -1 } }
      : std::vector<Arc>{});
}

// The L-bracket's (LBracketSection): plate 2 long, wall 1 high, 0.05 thick.
double LBracketDistance(const double* p, double rho)
{
  const double t = 0.05, outer = rho > 0 ? rho + t : 0.0;
  return OutlineDistance(p, 1.0,
    { { outer, 0, 2, 0 }, { 2, 0, 2, t }, { 2, t, t + rho, t }, { t, t + rho, t, 1 },
      { t, 1, 0, 1 }, { 0, 1, 0, outer } },
    rho > 0 ? std::vector<Arc>{ { t + rho, t + rho, rho, -1, -1 }, { outer, outer, outer, -1, -1 } }
            : std::vector<Arc>{});
}

void WallShape(vtkAnalyticShapeSource* s, double rho)
{
  s->SetXLength(2.0);
  s->SetYLength(2.0);
  s->SetZLength(1.0);
  s->SetThickness(0.05);
  s->SetFilletRadius(rho);
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
  { "TPlate", vtkAnalyticShapeSource::T_PLATE, [](vtkAnalyticShapeSource* s) { WallShape(s, 0.0); },
    [](const double* p) { return TPlateDistance(p, 0.0); } },
  { "TPlateFilleted", vtkAnalyticShapeSource::T_PLATE,
    [](vtkAnalyticShapeSource* s) { WallShape(s, 0.1); },
    [](const double* p) { return TPlateDistance(p, 0.1); } },
  { "LBracket", vtkAnalyticShapeSource::L_BRACKET,
    [](vtkAnalyticShapeSource* s) { WallShape(s, 0.0); },
    [](const double* p) { return LBracketDistance(p, 0.0); } },
  { "LBracketFilleted", vtkAnalyticShapeSource::L_BRACKET,
    [](vtkAnalyticShapeSource* s) { WallShape(s, 0.1); },
    [](const double* p) { return LBracketDistance(p, 0.1); } },
  { "WedgePlate", vtkAnalyticShapeSource::WEDGE_PLATE,
    [](vtkAnalyticShapeSource* s)
    {
      WallShape(s, 0.0);
      s->SetEndThickness(0.15);
    },
    [](const double* p)
    {
      // Thickness 0.05 at y = -1 to 0.15 at y = 1, symmetric about z = 0.
      const double half = 0.05 + 0.025 * p[1];
      return OutlineDistance(p, 1.0,
               { { -1, -0.025, 1, -0.075 }, { 1, -0.075, 1, 0.075 }, { 1, 0.075, -1, 0.025 },
                 { -1, 0.025, -1, -0.025 } },
               {}) +
        0.0 * half;
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
  EXPECT_THROW(
    TPlateSection(0.5, 1.0, 0.05, 0.3, 0.1, 8), std::invalid_argument); // fillets too wide
  EXPECT_THROW(LBracketSection(1.0, 1.0, 0.05, -0.1, 0.1, 8), std::invalid_argument);
  EXPECT_THROW(WedgePlateSection(1.0, 0.0, 0.1, 0.1), std::invalid_argument);
}

// Ear clipping: a comb-shaped outline with collinear points gives as many
// triangles as a triangulation must (n - 2), of the polygon's area, none flat.
TEST(AnalyticShapes, CapsTriangulateSimplePolygons)
{
  std::vector<std::array<double, 2>> comb{ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 3, 0 }, { 3, 2 },
    { 2.5, 2 }, { 2.5, 1 }, { 2, 1 }, { 2, 2 }, { 1, 2 }, { 1, 1 }, { 0.5, 1 }, { 0.5, 2 },
    { 0, 2 }, { 0, 1 } };
  const auto triangles = TriangulatePolygon(comb);
  ASSERT_EQ(triangles.size(), comb.size() - 2);
  double area = 0.0;
  for (const auto& t : triangles)
  {
    const auto &a = comb[t[0]], &b = comb[t[1]], &c = comb[t[2]];
    const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    EXPECT_GT(twice, 1e-9);
    area += 0.5 * twice;
  }
  EXPECT_NEAR(area, 6.0 - 2 * 0.5, 1e-12); // two notches
}
