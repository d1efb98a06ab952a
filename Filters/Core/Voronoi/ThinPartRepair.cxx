// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/ThinPartRepair.h"

#include "Support/DisjointSets.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
// Keeps the clusters of spanning cells (VoronoiMedialAxis.cxx, step 2b) that add no loop to the
// medial complex: a cluster added to the inside cells changes the Euler
// characteristic by V - E + F (its vertices, the Voronoi edges and the
// complete Voronoi faces it brings); joining m separate pieces accounts
// for 1 - m of that, filling a hole for +1, and anything lower is a new
// tunnel or loop, which no repair of a solid should make. Clears the others.
std::vector<Index> KeepSpanningClustersWithoutNewLoops(const CellArray& cellSites,
  const CellArray& cellNeighbours, const std::vector<char>& inside, std::vector<char>& spanning)
{
  const std::size_t nc = cellSites.size();
  DisjointSets clusters(nc), pieces(nc);
  for (std::size_t c = 0; c < nc; ++c)
  {
    for (Index n : cellNeighbours[c])
    {
      if (n > static_cast<Index>(c) && spanning[c] && spanning[n])
      {
        clusters.Union(static_cast<Index>(c), n);
      }
      if (n > static_cast<Index>(c) && inside[c] && inside[n])
      {
        pieces.Union(static_cast<Index>(c), n);
      }
    }
  }
  // Clusters that complete a Voronoi face together are one: neither
  // would bring that face alone.
  for (std::size_t c = 0; c < nc; ++c)
  {
    if (!spanning[c])
    {
      continue;
    }
    for (int e = 0; e < 6; ++e)
    {
      const Index start = static_cast<Index>(c);
      bool other = false;
      const bool complete = AroundEdge(cellSites, cellNeighbours, start, e,
        [&](Index n)
        {
          other = other || (spanning[n] && clusters.Find(n) != clusters.Find(start));
          return inside[n] || spanning[n];
        });
      if (complete && other)
      {
        AroundEdge(cellSites, cellNeighbours, start, e,
          [&](Index n)
          {
            if (spanning[n])
            {
              clusters.Union(start, n);
            }
            return true;
          });
      }
    }
  }
  std::vector<Index> clusterOf(nc, -1), pieceOf(nc, -1);
  std::vector<std::vector<Index>> members;
  std::vector<Index> clusterId(nc, -1);
  for (std::size_t c = 0; c < nc; ++c)
  {
    if (inside[c])
    {
      pieceOf[c] = pieces.Find(static_cast<Index>(c));
    }
    if (!spanning[c])
    {
      continue;
    }
    const Index root = clusters.Find(static_cast<Index>(c));
    if (clusterId[root] < 0)
    {
      clusterId[root] = static_cast<Index>(members.size());
      members.emplace_back();
    }
    clusterOf[c] = clusterId[root];
    members[clusterId[root]].push_back(static_cast<Index>(c));
  }
  std::vector<char> keep(members.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, members.size(), 16),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      std::vector<Index> touched;
      std::vector<std::array<Index, 2>> faces;
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        auto insideWith = [&](Index c)
        { return c >= 0 && (inside[c] || clusterOf[c] == static_cast<Index>(k)); };
        long long vertices = 0, edges = 0;
        touched.clear();
        faces.clear();
        for (Index c : members[k])
        {
          ++vertices;
          for (Index n : cellNeighbours[c])
          {
            if (n >= 0 && inside[n])
            {
              ++edges;
              touched.push_back(pieceOf[n]);
            }
            else if (n > c && insideWith(n))
            {
              ++edges;
            }
          }
          for (int e = 0; e < 6; ++e)
          {
            std::array<Index, 2> key{ cellSites[c][edgeEnds[e][0]], cellSites[c][edgeEnds[e][1]] };
            std::sort(key.begin(), key.end());
            if (std::find(faces.begin(), faces.end(), key) == faces.end() &&
              AroundEdge(cellSites, cellNeighbours, c, e, insideWith))
            {
              faces.push_back(key);
            }
          }
        }
        std::sort(touched.begin(), touched.end());
        const long long joined = std::unique(touched.begin(), touched.end()) - touched.begin();
        const long long change = vertices - edges + static_cast<long long>(faces.size());
        keep[k] = change >= 1 - std::max(joined, 1LL) ? 1 : 0;
      }
    });
  for (std::size_t c = 0; c < nc; ++c)
  {
    if (spanning[c] && !keep[clusterOf[c]])
    {
      spanning[c] = 0;
      clusterOf[c] = -1;
    }
  }
  return clusterOf;
}

// Which sites lie in a void of the complex made of the cells for which
// kept(cell) holds: the sites' Voronoi cells are joined across every
// Voronoi face not in the complex, and the unbounded ones to infinity; the
// groups that do not reach infinity are enclosed by the complex.
template <typename Kept>
std::vector<char> EnclosedSites(
  const CellArray& cellSites, const CellArray& cellNeighbours, std::size_t sites, Kept&& kept)
{
  const Index infinity = static_cast<Index>(sites);
  DisjointSets regions(sites + 1);
  for (std::size_t c = 0; c < cellSites.size(); ++c)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (cellNeighbours[c][k] < 0) // a hull facet: its sites' cells are unbounded
      {
        for (int j = 0; j < 4; ++j)
        {
          if (j != k)
          {
            regions.Union(cellSites[c][j], infinity);
          }
        }
      }
    }
    for (int e = 0; e < 6; ++e)
    {
      const Index u = cellSites[c][edgeEnds[e][0]], v = cellSites[c][edgeEnds[e][1]];
      if (regions.Find(u) != regions.Find(v) &&
        !AroundEdge(cellSites, cellNeighbours, static_cast<Index>(c), e, kept))
      {
        regions.Union(u, v);
      }
    }
  }
  std::vector<char> enclosed(sites);
  const Index outside = regions.Find(infinity);
  for (std::size_t s = 0; s < sites; ++s)
  {
    enclosed[s] = regions.Find(static_cast<Index>(s)) != outside ? 1 : 0;
  }
  return enclosed;
}

// Clears the spanning clusters that enclose a void the complex did not have
// without them: a solid's medial axis encloses none (one that fills a
// pocket's mouth looks like one that fills a hole to the Euler test).
void OpenNewVoids(const CellArray& cellSites, const CellArray& cellNeighbours, std::size_t sites,
  const std::vector<char>& inside, std::vector<char>& spanning, const std::vector<Index>& clusterOf)
{
  const std::vector<char> before = EnclosedSites(
    cellSites, cellNeighbours, sites, [&](Index c) { return c >= 0 && inside[c] != 0; });
  for (int round = 0; round < 3; ++round)
  {
    const std::vector<char> after = EnclosedSites(cellSites, cellNeighbours, sites,
      [&](Index c) { return c >= 0 && (inside[c] || spanning[c]); });
    std::vector<char> drop(cellSites.size(), 0);
    bool any = false;
    for (std::size_t c = 0; c < cellSites.size(); ++c)
    {
      for (Index s : cellSites[c])
      {
        if (spanning[c] && after[s] && !before[s])
        {
          drop[clusterOf[c]] = 1;
          any = true;
        }
      }
    }
    if (!any)
    {
      return;
    }
    for (std::size_t c = 0; c < cellSites.size(); ++c)
    {
      if (spanning[c] && drop[clusterOf[c]])
      {
        spanning[c] = 0;
      }
    }
  }
}
}

void KeepSpanningCellsThatAddNoLoopOrVoid(const CellArray& cellSites,
  const CellArray& cellNeighbours, std::size_t sites, const std::vector<char>& inside,
  std::vector<char>& spanning)
{
  const std::vector<Index> clusterOf =
    KeepSpanningClustersWithoutNewLoops(cellSites, cellNeighbours, inside, spanning);
  OpenNewVoids(cellSites, cellNeighbours, sites, inside, spanning, clusterOf);
}

std::vector<std::array<Index, 2>> FacesOpeningVoids(const CellArray& cellSites,
  const CellArray& cellNeighbours, std::size_t sites, const std::vector<char>& inside,
  const std::vector<double>& radius)
{
  auto kept = [&](Index c) { return c >= 0 && inside[c] != 0; };
  const std::vector<char> enclosed = EnclosedSites(cellSites, cellNeighbours, sites, kept);
  std::vector<std::array<Index, 2>> faces;
  if (std::find(enclosed.begin(), enclosed.end(), 1) == enclosed.end())
  {
    return faces;
  }
  // The void each enclosed site is in: its sites joined across faces not in
  // the complex (as EnclosedSites does), restricted to enclosed sites.
  DisjointSets voids(sites);
  for (std::size_t c = 0; c < cellSites.size(); ++c)
  {
    for (int e = 0; e < 6; ++e)
    {
      const Index u = cellSites[c][edgeEnds[e][0]], v = cellSites[c][edgeEnds[e][1]];
      if (enclosed[u] && enclosed[v] && voids.Find(u) != voids.Find(v) &&
        !AroundEdge(cellSites, cellNeighbours, static_cast<Index>(c), e, kept))
      {
        voids.Union(u, v);
      }
    }
  }
  // Per void, the boundary face (one enclosed site, one not) of least
  // mean radius; ties to the lower site pair.
  struct Best
  {
    double Radius = HUGE_VAL;
    std::array<Index, 2> Face{ -1, -1 };
  };
  std::vector<Best> best(sites);
  for (std::size_t c = 0; c < cellSites.size(); ++c)
  {
    if (!inside[c])
    {
      continue;
    }
    for (int e = 0; e < 6; ++e)
    {
      Index u = cellSites[c][edgeEnds[e][0]], v = cellSites[c][edgeEnds[e][1]];
      if (enclosed[u] == enclosed[v])
      {
        continue;
      }
      double sum = 0.0;
      int count = 0;
      if (!AroundEdge(cellSites, cellNeighbours, static_cast<Index>(c), e,
            [&](Index n)
            {
              sum += kept(n) ? radius[n] : 0.0;
              ++count;
              return kept(n);
            }))
      {
        continue;
      }
      const Index root = voids.Find(enclosed[u] ? u : v);
      const std::array<Index, 2> face{ std::min(u, v), std::max(u, v) };
      const double mean = sum / count;
      if (mean < best[root].Radius || (mean == best[root].Radius && face < best[root].Face))
      {
        best[root] = { mean, face };
      }
    }
  }
  for (const Best& b : best)
  {
    if (b.Face[0] >= 0)
    {
      faces.push_back(b.Face);
    }
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}
}
