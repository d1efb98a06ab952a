// SPDX-License-Identifier: GPL-3.0-or-later
#include "Structure/MidSurfaceFolds.h"

#include <algorithm>
#include <utility>

namespace medialaxis
{
namespace
{
// The pairs of triangles across an edge of two.
std::vector<std::array<Index, 2>> TwoFacePairs(const EdgeFaceMap& edgeFaces)
{
  std::vector<std::array<Index, 2>> pairs;
  for (const auto& entry : edgeFaces)
  {
    if (entry.second.size() == 2)
    {
      pairs.push_back({ entry.second[0], entry.second[1] });
    }
  }
  return pairs;
}
// Of those pairs, the ones whose triangles face opposite ways (a fold).
std::vector<std::array<Index, 2>> FoldedPairs(const std::vector<Point3>& points,
  const std::vector<std::array<Index, 3>>& faces, const std::vector<std::array<Index, 2>>& pairs)
{
  std::vector<std::array<Index, 2>> folded;
  for (const auto& pair : pairs)
  {
    if (Dot(AreaNormal(points, faces[pair[0]]), AreaNormal(points, faces[pair[1]])) < 0.0)
    {
      folded.push_back(pair);
    }
  }
  return folded;
}
}

EdgeFaceMap EdgeFaces(const std::vector<std::array<Index, 3>>& faces)
{
  EdgeFaceMap edgeFaces;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = faces[f][k], b = faces[f][(k + 1) % 3];
      edgeFaces[{ std::min(a, b), std::max(a, b) }].push_back(static_cast<Index>(f));
    }
  }
  return edgeFaces;
}

void OrientConsistently(std::vector<std::array<Index, 3>>& faces)
{
  EdgeFaceMap edgeFaces = EdgeFaces(faces);
  auto uses = [&](Index f, Index a, Index b)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (faces[f][k] == a && faces[f][(k + 1) % 3] == b)
      {
        return true;
      }
    }
    return false;
  };
  std::vector<std::uint8_t> done(faces.size(), 0);
  for (std::size_t seed = 0; seed < faces.size(); ++seed)
  {
    if (done[seed])
    {
      continue;
    }
    done[seed] = 1;
    std::vector<Index> stack{ static_cast<Index>(seed) };
    while (!stack.empty())
    {
      const Index f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const Index a = faces[f][k], b = faces[f][(k + 1) % 3];
        const auto& around = edgeFaces[{ std::min(a, b), std::max(a, b) }];
        if (around.size() != 2)
        {
          continue;
        }
        const Index g = around[0] == f ? around[1] : around[0];
        if (done[g])
        {
          continue;
        }
        if (uses(g, a, b))
        {
          std::swap(faces[g][1], faces[g][2]);
        }
        done[g] = 1;
        stack.push_back(g);
      }
    }
  }
}

std::size_t UntangleFolds(std::vector<Point3>& points,
  const std::vector<std::array<Index, 3>>& faces, const std::vector<PlaneSet>& planes, int rounds,
  std::vector<std::uint8_t>& moved)
{
  moved.assign(planes.size(), 0);
  const EdgeFaceMap edgeFaces = EdgeFaces(faces);
  std::vector<std::vector<Index>> neighbours(planes.size());
  for (const auto& entry : edgeFaces)
  {
    neighbours[entry.first[0]].push_back(entry.first[1]);
    neighbours[entry.first[1]].push_back(entry.first[0]);
  }
  const std::vector<std::array<Index, 2>> pairs = TwoFacePairs(edgeFaces);
  std::size_t folded = 0;
  for (int round = 0; round <= rounds; ++round)
  {
    std::vector<std::uint8_t> moving(planes.size(), 0);
    const std::vector<std::array<Index, 2>> foldedPairs = FoldedPairs(points, faces, pairs);
    folded = foldedPairs.size();
    for (const auto& pair : foldedPairs)
    {
      for (Index f : pair)
      {
        for (Index v : faces[f])
        {
          moving[v] = 1;
        }
      }
    }
    if (folded == 0 || round == rounds)
    {
      break;
    }
    std::vector<Point3> next = points;
    for (std::size_t v = 0; v < planes.size(); ++v)
    {
      if (!moving[v] || neighbours[v].empty())
      {
        continue;
      }
      Point3 mean{ 0, 0, 0 };
      for (Index w : neighbours[v])
      {
        mean = mean + points[w];
      }
      mean = (1.0 / static_cast<double>(neighbours[v].size())) * mean;
      next[v] = points[v] + planes[v].AlongAll(mean - points[v]);
      moved[v] = 1;
    }
    points.swap(next);
  }
  return folded;
}

std::vector<Index> FoldedTips(
  const std::vector<Point3>& points, const std::vector<std::array<Index, 3>>& faces)
{
  std::vector<Index> tips;
  for (const auto& pair : FoldedPairs(points, faces, TwoFacePairs(EdgeFaces(faces))))
  {
    const double area0 = Norm(AreaNormal(points, faces[pair[0]]));
    const double area1 = Norm(AreaNormal(points, faces[pair[1]]));
    tips.push_back(area0 < area1 ? pair[0] : pair[1]);
  }
  std::sort(tips.begin(), tips.end());
  tips.erase(std::unique(tips.begin(), tips.end()), tips.end());
  return tips;
}
}
