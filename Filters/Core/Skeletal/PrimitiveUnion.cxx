// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeletal/PrimitiveUnion.h"

#include "Geometry/Vec3.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

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

std::function<double(const Point3&)> PrimitiveUnion::LocalSignedDistance(
  const Point3& centre, double radius) const
{
  std::vector<std::size_t> near, containing; // of the points, some / all inside
  for (std::size_t i = 0; i < this->Meshes.size(); ++i)
  {
    if (SquaredDistanceToBox(centre, this->Boxes[i]) > radius * radius)
    {
      continue; // no point of the ball is in its box
    }
    if (this->Locators[i]->Distance(centre, 2.0 * radius) <= radius)
    {
      near.push_back(i);
    }
    else if (this->Locators[i]->Inside(centre))
    {
      containing.push_back(i);
    }
  }
  // Distances beyond twice the radius are only needed as bounds (the grid
  // fills far blocks from their centre's): the searches stop there.
  const double limit = 2.0 * radius;
  return [this, near = std::move(near), containing = std::move(containing), limit](const Point3& x)
  {
    bool inside = !containing.empty();
    double depth = 0.0;
    for (std::size_t i : containing)
    {
      depth = std::max(depth, this->Locators[i]->Distance(x, limit));
    }
    for (std::size_t i : near)
    {
      if (SquaredDistanceToBox(x, this->Boxes[i]) == 0.0)
      {
        const double f = this->Locators[i]->SignedDistance(x, limit);
        if (f < 0.0)
        {
          inside = true;
          depth = std::max(depth, -f);
        }
      }
    }
    return inside ? -depth : this->AllLocator->Distance(x, limit);
  };
}

std::size_t KeepComponentsAroundSkeleton(TriangleMesh& contour, const std::vector<Point3>& skeleton)
{
  DisjointSets sets(contour.Points.size());
  for (const Triangle& t : contour.Triangles)
  {
    sets.Union(t[0], t[1]);
    sets.Union(t[1], t[2]);
  }
  std::map<Index, TriangleMesh> components; // by root; points shared with `contour`
  for (const Triangle& t : contour.Triangles)
  {
    components[sets.Find(t[0])].Triangles.push_back(t);
  }
  if (components.size() < 2)
  {
    return 0;
  }
  std::set<Index> kept;
  for (auto& [root, component] : components)
  {
    component.Points = contour.Points; // the locator needs the points by index
    const TriangleLocator locator(component);
    for (const Point3& p : skeleton)
    {
      if (locator.Inside(p))
      {
        kept.insert(root);
        break;
      }
    }
  }
  const std::size_t before = contour.Triangles.size();
  contour.Triangles.erase(std::remove_if(contour.Triangles.begin(), contour.Triangles.end(),
                            [&](const Triangle& t) { return !kept.count(sets.Find(t[0])); }),
    contour.Triangles.end());
  // The points of the dropped shells go too.
  std::vector<Index> renumbered(contour.Points.size(), -1);
  std::vector<Point3> points;
  for (Triangle& t : contour.Triangles)
  {
    for (Index& v : t)
    {
      if (renumbered[v] < 0)
      {
        renumbered[v] = static_cast<Index>(points.size());
        points.push_back(contour.Points[v]);
      }
      v = renumbered[v];
    }
  }
  contour.Points.swap(points);
  return before - contour.Triangles.size();
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
  return SampleNarrowBandLocal(
    primitives.Bounds(), spacing,
    [&primitives](const Point3& centre, double radius)
    { return primitives.LocalSignedDistance(centre, radius); },
    progress, BlockSide);
}
}
