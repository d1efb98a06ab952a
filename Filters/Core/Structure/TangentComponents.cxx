// SPDX-License-Identifier: GPL-3.0-or-later
#include "Structure/TangentComponents.h"

#include "Geometry/KdTree.h"
#include "Mesh/MedialMesh.h"
#include "Support/DisjointSets.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace medialaxis
{
SiteAdjacency ComputeSiteAdjacency(const std::vector<Point3>& vertices,
  const std::vector<Index>& offsets, const std::vector<Index>& polygonSite,
  std::size_t numberOfSites, double tolerance)
{
  // The site of every polygon vertex; a vertex shared by two cells is
  // computed once per cell, so coincident copies are matched by a radius
  // search.
  std::vector<Index> siteOfVertex(vertices.size(), -1);
  for (std::size_t p = 0; p + 1 < offsets.size(); ++p)
  {
    for (Index k = offsets[p]; k < offsets[p + 1]; ++k)
    {
      siteOfVertex[k] = polygonSite[p];
    }
  }
  const KdTree tree(vertices);
  tbb::enumerable_thread_specific<std::vector<std::array<Index, 2>>> found;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size(), 4096),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      auto& pairs = found.local();
      std::vector<std::pair<std::uint32_t, double>> near;
      for (std::size_t i = r.begin(); i != r.end(); ++i)
      {
        tree.WithinRadius(vertices[i], tolerance, near, false);
        for (const auto& [j, squared] : near)
        {
          const Index a = siteOfVertex[i], b = siteOfVertex[j];
          if (a >= 0 && b >= 0 && a < b)
          {
            pairs.push_back({ a, b });
          }
        }
      }
    });
  std::vector<std::array<Index, 2>> pairs;
  for (const auto& local : found)
  {
    pairs.insert(pairs.end(), local.begin(), local.end());
  }
  // Both directions, then sorted: the same lists at any thread count.
  const std::size_t half = pairs.size();
  for (std::size_t k = 0; k < half; ++k)
  {
    pairs.push_back({ pairs[k][1], pairs[k][0] });
  }
  SortEdgeKeys(pairs);
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  SiteAdjacency out;
  out.Offsets.assign(numberOfSites + 1, 0);
  for (const auto& [a, b] : pairs)
  {
    ++out.Offsets[a + 1];
  }
  for (std::size_t s = 0; s < numberOfSites; ++s)
  {
    out.Offsets[s + 1] += out.Offsets[s];
  }
  out.Neighbours.reserve(pairs.size());
  for (const auto& [a, b] : pairs)
  {
    out.Neighbours.push_back(b);
  }
  return out;
}

std::vector<int> CountTangentComponents(const std::vector<Index>& atlasOffsets,
  const std::vector<Index>& atlasSites, const SiteAdjacency& adjacency)
{
  const std::size_t nv = atlasOffsets.empty() ? 0 : atlasOffsets.size() - 1;
  std::vector<int> count(nv, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 256),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      std::vector<Index> atlas;
      for (std::size_t v = r.begin(); v != r.end(); ++v)
      {
        atlas.assign(
          atlasSites.begin() + atlasOffsets[v], atlasSites.begin() + atlasOffsets[v + 1]);
        std::sort(atlas.begin(), atlas.end());
        atlas.erase(std::unique(atlas.begin(), atlas.end()), atlas.end());
        DisjointSets pieces(atlas.size());
        for (std::size_t i = 0; i < atlas.size(); ++i)
        {
          const Index s = atlas[i];
          if (s < 0 || s + 1 >= static_cast<Index>(adjacency.Offsets.size()))
          {
            continue;
          }
          for (Index k = adjacency.Offsets[s]; k < adjacency.Offsets[s + 1]; ++k)
          {
            const auto at = std::lower_bound(atlas.begin(), atlas.end(), adjacency.Neighbours[k]);
            if (at != atlas.end() && *at == adjacency.Neighbours[k])
            {
              pieces.Union(static_cast<Index>(i), static_cast<Index>(at - atlas.begin()));
            }
          }
        }
        int roots = 0;
        for (std::size_t i = 0; i < atlas.size(); ++i)
        {
          roots += pieces.Find(static_cast<Index>(i)) == static_cast<Index>(i) ? 1 : 0;
        }
        count[v] = roots;
      }
    });
  return count;
}
}
