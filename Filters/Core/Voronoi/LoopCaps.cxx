// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/LoopCaps.h"

#include "Geometry/Vec3.h"

#include <cstddef>

namespace medialaxis
{
namespace repair
{
namespace
{
// The hub of a fan over `loop`: a point inside the surface from which every
// loop vertex (and, with `edgeMiddles`, the middle of every loop edge) is
// seen without crossing it. False if none of the candidates is.
bool FindHub(const MedialMesh& mesh, const std::vector<Index>& loop,
  const TopologyRepairQueries& queries, bool edgeMiddles, Point3& hub)
{
  Point3 centroid{ 0.0, 0.0, 0.0 };
  for (Index v : loop)
  {
    centroid = centroid + mesh.Centers[v];
  }
  centroid = (1.0 / static_cast<double>(loop.size())) * centroid;
  std::vector<Point3> targets;
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    targets.push_back(mesh.Centers[loop[k]]);
  }
  if (edgeMiddles)
  {
    for (std::size_t k = 0; k < loop.size(); ++k)
    {
      targets.push_back(0.5 * (targets[k] + targets[(k + 1) % loop.size()]));
    }
  }
  // Candidates that fail mostly fail on the target the last one failed on:
  // it is tested first (the answer does not depend on the order).
  std::size_t blocker = 0;
  auto seesAll = [&](const Point3& p)
  {
    if (!queries.Inside(p) || queries.Crosses(p, targets[blocker]))
    {
      return false;
    }
    for (std::size_t k = 0; k < targets.size(); ++k)
    {
      if (k != blocker && queries.Crosses(p, targets[k]))
      {
        blocker = k;
        return false;
      }
    }
    return true;
  };
  if (seesAll(centroid))
  {
    hub = centroid;
    return true;
  }
  for (Index v : loop)
  {
    for (double t : { 1.0 / 3.0, 2.0 / 3.0, 0.95 })
    {
      const Point3 p = centroid + t * (mesh.Centers[v] - centroid);
      if (seesAll(p))
      {
        hub = p;
        return true;
      }
    }
  }
  return false;
}

bool FindSplitCap(const MedialMesh& mesh, const std::vector<Index>& loop,
  const TopologyRepairQueries& queries, bool split, LoopCap& cap, int depth, int& hubSearches)
{
  if (hubSearches <= 0)
  {
    return false;
  }
  --hubSearches;
  Point3 hub;
  if (FindHub(mesh, loop, queries, split, hub))
  {
    cap.Hubs.push_back(hub);
    cap.Fans.push_back(loop);
    return true;
  }
  const std::size_t n = loop.size();
  if (depth <= 0 || n < 6)
  {
    return false;
  }
  // Chords across the middle of the loop, from a few starting vertices.
  for (std::size_t start : { std::size_t(0), n / 4, n / 8, 3 * n / 8 })
  {
    const std::size_t end = start + n / 2;
    if (queries.Crosses(mesh.Centers[loop[start]], mesh.Centers[loop[end]]))
    {
      continue;
    }
    const std::vector<Index> first(loop.begin() + static_cast<std::ptrdiff_t>(start),
      loop.begin() + static_cast<std::ptrdiff_t>(end + 1));
    std::vector<Index> second(loop.begin() + static_cast<std::ptrdiff_t>(end), loop.end());
    second.insert(
      second.end(), loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(start + 1));
    const std::size_t hubs = cap.Hubs.size();
    if (FindSplitCap(mesh, first, queries, true, cap, depth - 1, hubSearches) &&
      FindSplitCap(mesh, second, queries, true, cap, depth - 1, hubSearches))
    {
      return true;
    }
    cap.Hubs.resize(hubs);
    cap.Fans.resize(hubs);
  }
  return false;
}
}

bool FindCap(const MedialMesh& mesh, const std::vector<Index>& loop,
  const TopologyRepairQueries& queries, LoopCap& cap, int depth)
{
  cap.Hubs.clear();
  cap.Fans.clear();
  // A hub search tests O(n^2) segments on a loop of n vertices: a loop round
  // a handle of the solid, which no cap fits, must not cost hundreds.
  int hubSearches = 64;
  return FindSplitCap(mesh, loop, queries, false, cap, depth, hubSearches);
}
}
}
