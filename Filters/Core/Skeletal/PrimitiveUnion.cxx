// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeletal/PrimitiveUnion.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
PrimitiveUnion::PrimitiveUnion(const std::vector<TriangleMesh>& primitives)
{
  for (const TriangleMesh& mesh : primitives)
  {
    if (mesh.Triangles.empty())
    {
      continue;
    }
    this->Meshes.push_back(mesh);
    const TriangleMesh& stored = this->Meshes.back();
    this->Locators.push_back(std::make_unique<TriangleLocator>(stored));
    Box box;
    for (const Point3& p : stored.Points)
    {
      box.Extend(p);
    }
    this->Boxes.push_back(box);
    this->AllBounds.Extend(box);
    const Index offset = static_cast<Index>(this->All.Points.size());
    this->All.Points.insert(this->All.Points.end(), stored.Points.begin(), stored.Points.end());
    for (const Triangle& t : stored.Triangles)
    {
      this->All.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    }
  }
  this->AllLocator = std::make_unique<TriangleLocator>(this->All);
}

bool PrimitiveUnion::Inside(std::size_t i, const Point3& x) const
{
  if (SquaredDistanceToBox(x, this->Boxes[i]) > 0.0)
  {
    return false;
  }
  return this->Locators[i]->Inside(x);
}

double PrimitiveUnion::SignedDistance(const Point3& x) const
{
  double depth = 0.0;
  bool inside = false;
  for (std::size_t i = 0; i < this->Meshes.size(); ++i)
  {
    if (this->Inside(i, x))
    {
      inside = true;
      depth = std::max(depth, this->Locators[i]->Distance(x));
    }
  }
  return inside ? -depth : this->AllLocator->Distance(x);
}

// Blocks of 4^3 points: F costs several ray casts, so a band half as
// thick is worth the eight times as many block centres.
constexpr int BlockSide = 4;

DistanceGrid SamplePrimitiveUnion(
  const PrimitiveUnion& primitives, double spacing, const std::function<bool(double)>& progress)
{
  if (primitives.Empty())
  {
    return DistanceGrid();
  }
  return SampleNarrowBand(
    primitives.Bounds(), spacing,
    [&primitives](const Point3& x) { return primitives.SignedDistance(x); }, progress, BlockSide);
}
}
