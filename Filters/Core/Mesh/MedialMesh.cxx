// SPDX-License-Identifier: GPL-3.0-or-later
#include "Mesh/MedialMesh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace medialaxis
{
namespace
{
std::array<Index, 2> SortedEdge(Index a, Index b)
{
  return a < b ? std::array<Index, 2>{ a, b } : std::array<Index, 2>{ b, a };
}

std::array<Index, 3> SortedFace(std::array<Index, 3> f)
{
  std::sort(f.begin(), f.end());
  return f;
}

template <typename T>
std::size_t CountRepeats(std::vector<T> items)
{
  std::sort(items.begin(), items.end());
  std::size_t repeats = 0;
  for (std::size_t i = 1; i < items.size(); ++i)
  {
    repeats += (items[i] == items[i - 1]) ? 1 : 0;
  }
  return repeats;
}

// "1 radius", "2 radii": irregular plurals are spelled out by the caller.
std::string Plural(std::size_t n, const char* singular, const char* plural)
{
  std::ostringstream s;
  s << n << ' ' << (n == 1 ? singular : plural);
  return s.str();
}
}

MedialMeshCheck ValidateMedialMesh(const MedialMesh& mesh)
{
  MedialMeshCheck check;
  const std::size_t nv = mesh.Centers.size();
  if (mesh.Radii.size() != nv)
  {
    std::ostringstream s;
    s << "medial mesh has " << mesh.Radii.size() << " radii for " << nv << " vertices";
    check.Message = s.str();
    return check;
  }

  std::size_t nonFinitePoints = 0, badRadii = 0;
  for (std::size_t i = 0; i < nv; ++i)
  {
    const Point3& p = mesh.Centers[i];
    nonFinitePoints += (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) ? 0 : 1;
    badRadii += (std::isfinite(mesh.Radii[i]) && mesh.Radii[i] >= 0.0) ? 0 : 1;
  }
  if (nonFinitePoints)
  {
    check.Message = "medial mesh has " + Plural(nonFinitePoints, "vertex", "vertices") +
      " with NaN or infinite coordinates";
    return check;
  }
  if (badRadii)
  {
    check.Message = "medial mesh has " + Plural(badRadii, "radius that is", "radii that are") +
      " negative, NaN or infinite";
    return check;
  }

  auto outOfRange = [nv](Index i) { return i < 0 || static_cast<std::size_t>(i) >= nv; };
  std::size_t badIndices = 0, degenerate = 0;
  std::vector<std::array<Index, 2>> edges;
  edges.reserve(mesh.Edges.size());
  for (const auto& e : mesh.Edges)
  {
    badIndices += (outOfRange(e[0]) || outOfRange(e[1])) ? 1 : 0;
    degenerate += (e[0] == e[1]) ? 1 : 0;
    edges.push_back(SortedEdge(e[0], e[1]));
  }
  std::vector<std::array<Index, 3>> faces;
  faces.reserve(mesh.Faces.size());
  for (const auto& f : mesh.Faces)
  {
    badIndices += (outOfRange(f[0]) || outOfRange(f[1]) || outOfRange(f[2])) ? 1 : 0;
    degenerate += (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) ? 1 : 0;
    faces.push_back(SortedFace(f));
  }
  if (badIndices)
  {
    check.Message = "medial mesh has " + Plural(badIndices, "cell", "cells") +
      " referencing a vertex index outside [0, " + std::to_string(nv) + ")";
    return check;
  }
  if (degenerate)
  {
    check.Message = "medial mesh has " + Plural(degenerate, "degenerate cell", "degenerate cells") +
      " (a vertex repeated within an edge or triangle)";
    return check;
  }
  const std::size_t duplicateEdges = CountRepeats(std::move(edges));
  const std::size_t duplicateFaces = CountRepeats(std::move(faces));
  if (duplicateEdges || duplicateFaces)
  {
    check.Message = "medial mesh has " +
      Plural(duplicateFaces, "duplicate triangle", "duplicate triangles") + " and " +
      Plural(duplicateEdges, "duplicate edge", "duplicate edges");
    return check;
  }
  return check;
}

// Sorts edge keys (a < b) lexicographically: bucketed by a (a counting
// sort), then each bucket's few b sorted. Linear in the keys, where a
// comparison sort of the pairs was a large share of the initial medial
// mesh's clean-up and repair.
void SortEdgeKeys(std::vector<std::array<Index, 2>>& keys)
{
  Index lowest = 0, highest = -1;
  for (const auto& k : keys)
  {
    lowest = std::min(lowest, k[0]);
    highest = std::max(highest, k[0]);
  }
  if (keys.size() < 256 || lowest < 0)
  {
    std::sort(keys.begin(), keys.end());
    return;
  }
  const std::size_t buckets = static_cast<std::size_t>(highest) + 1;
  std::vector<std::size_t> start(buckets + 1, 0);
  for (const auto& k : keys)
  {
    ++start[static_cast<std::size_t>(k[0]) + 1];
  }
  for (std::size_t a = 0; a < buckets; ++a)
  {
    start[a + 1] += start[a];
  }
  std::vector<Index> second(keys.size());
  {
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    for (const auto& k : keys)
    {
      second[cursor[static_cast<std::size_t>(k[0])]++] = k[1];
    }
  }
  for (std::size_t a = 0; a < buckets; ++a)
  {
    std::sort(second.begin() + static_cast<std::ptrdiff_t>(start[a]),
      second.begin() + static_cast<std::ptrdiff_t>(start[a + 1]));
    for (std::size_t i = start[a]; i < start[a + 1]; ++i)
    {
      keys[i] = { static_cast<Index>(a), second[i] };
    }
  }
}

namespace
{
// Calls use(a, b) for each listed edge and for each edge of each face.
template <typename Use>
void ForEachEdgeUse(const MedialMesh& mesh, Use&& use)
{
  for (const auto& e : mesh.Edges)
  {
    use(e[0], e[1]);
  }
  for (const auto& f : mesh.Faces)
  {
    use(f[0], f[1]);
    use(f[1], f[2]);
    use(f[2], f[0]);
  }
}
}

std::vector<std::array<Index, 2>> AllEdges(const MedialMesh& mesh)
{
  // Each edge's larger vertex in the row of its smaller one (interior edges
  // of faces twice), each row sorted and deduplicated: half the transient
  // room of sorting every (smaller, larger) pair, which set the topology
  // repair's peak on large surfaces.
  const std::size_t n = mesh.NumberOfVertices();
  std::vector<std::size_t> start(n + 1, 0);
  bool valid = true;
  ForEachEdgeUse(mesh,
    [&](Index a, Index b)
    {
      if (a < 0 || b < 0 || static_cast<std::size_t>(std::max(a, b)) >= n)
      {
        valid = false;
        return;
      }
      ++start[static_cast<std::size_t>(std::min(a, b)) + 1];
    });
  std::vector<std::array<Index, 2>> edges;
  if (!valid)
  {
    // Ids outside the vertices: sort the pairs as they are.
    ForEachEdgeUse(mesh, [&](Index a, Index b) { edges.push_back(SortedEdge(a, b)); });
    SortEdgeKeys(edges);
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
  }
  for (std::size_t a = 0; a < n; ++a)
  {
    start[a + 1] += start[a];
  }
  std::vector<Index> larger(start[n]);
  {
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    ForEachEdgeUse(mesh,
      [&](Index a, Index b)
      { larger[cursor[static_cast<std::size_t>(std::min(a, b))]++] = std::max(a, b); });
  }
  // Each row sorted and its distinct entries counted, then written at the
  // row's offset: rows are independent, so in parallel.
  std::vector<std::size_t> offset(n + 1, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t a = range.begin(); a != range.end(); ++a)
      {
        const auto first = larger.begin() + static_cast<std::ptrdiff_t>(start[a]);
        const auto last = larger.begin() + static_cast<std::ptrdiff_t>(start[a + 1]);
        std::sort(first, last);
        std::size_t unique = 0;
        for (auto i = first; i != last; ++i)
        {
          unique += (i == first || *i != *(i - 1)) ? 1 : 0;
        }
        offset[a + 1] = unique;
      }
    });
  for (std::size_t a = 0; a < n; ++a)
  {
    offset[a + 1] += offset[a];
  }
  edges.resize(offset[n]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t a = range.begin(); a != range.end(); ++a)
      {
        std::size_t out = offset[a];
        Index previous = -1;
        for (std::size_t i = start[a]; i < start[a + 1]; ++i)
        {
          if (larger[i] != previous)
          {
            edges[out++] = { static_cast<Index>(a), larger[i] };
            previous = larger[i];
          }
        }
      }
    });
  return edges;
}

MedialAdjacency VertexAdjacency(const MedialMesh& mesh)
{
  const std::size_t n = mesh.NumberOfVertices();
  const std::vector<std::array<Index, 2>> edges = AllEdges(mesh);
  MedialAdjacency adjacency;
  adjacency.Start.assign(n + 1, 0);
  for (const auto& e : edges)
  {
    ++adjacency.Start[e[0] + 1];
    ++adjacency.Start[e[1] + 1];
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    adjacency.Start[i + 1] += adjacency.Start[i];
  }
  adjacency.Next.resize(adjacency.Start[n]);
  std::vector<Index> fill(adjacency.Start.begin(), adjacency.Start.end() - 1);
  for (const auto& e : edges)
  {
    adjacency.Next[fill[e[0]]++] = e[1];
    adjacency.Next[fill[e[1]]++] = e[0];
  }
  return adjacency;
}

namespace
{
/// The three edges of every triangle, sorted, an edge once per triangle.
std::vector<std::array<Index, 2>> FaceEdgeUses(const MedialMesh& mesh)
{
  std::vector<std::array<Index, 2>> faceEdges;
  faceEdges.reserve(3 * mesh.Faces.size());
  for (const auto& f : mesh.Faces)
  {
    faceEdges.push_back(SortedEdge(f[0], f[1]));
    faceEdges.push_back(SortedEdge(f[1], f[2]));
    faceEdges.push_back(SortedEdge(f[2], f[0]));
  }
  SortEdgeKeys(faceEdges);
  return faceEdges;
}
}

std::vector<std::array<Index, 2>> SheetBoundaryEdges(const MedialMesh& mesh)
{
  const std::vector<std::array<Index, 2>> faceEdges = FaceEdgeUses(mesh);
  std::vector<std::array<Index, 2>> boundary;
  for (std::size_t i = 0; i < faceEdges.size();)
  {
    std::size_t j = i + 1;
    while (j < faceEdges.size() && faceEdges[j] == faceEdges[i])
    {
      ++j;
    }
    if (j - i == 1)
    {
      boundary.push_back(faceEdges[i]);
    }
    i = j;
  }
  return boundary;
}

std::vector<std::array<Index, 2>> EdgesNotOnFaces(const MedialMesh& mesh)
{
  const std::vector<std::array<Index, 2>> faceEdges = FaceEdgeUses(mesh);
  std::vector<std::array<Index, 2>> result;
  for (const auto& e : mesh.Edges)
  {
    const auto s = SortedEdge(e[0], e[1]);
    if (!std::binary_search(faceEdges.begin(), faceEdges.end(), s))
    {
      result.push_back(s);
    }
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

long long EulerCharacteristic(const MedialMesh& mesh)
{
  return static_cast<long long>(mesh.Centers.size()) -
    static_cast<long long>(AllEdges(mesh).size()) + static_cast<long long>(mesh.Faces.size());
}

void CanonicalCycle(std::vector<Index>& cycle)
{
  if (cycle.empty())
  {
    return;
  }
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  if (cycle.size() > 2 && cycle.back() < cycle[1])
  {
    std::reverse(cycle.begin() + 1, cycle.end());
  }
}

std::vector<Index> IsolatedVertices(const MedialMesh& mesh)
{
  std::vector<char> used(mesh.Centers.size(), 0);
  auto mark = [&used](Index i)
  {
    if (i >= 0 && static_cast<std::size_t>(i) < used.size())
    {
      used[i] = 1;
    }
  };
  for (const auto& e : mesh.Edges)
  {
    mark(e[0]);
    mark(e[1]);
  }
  for (const auto& f : mesh.Faces)
  {
    mark(f[0]);
    mark(f[1]);
    mark(f[2]);
  }
  std::vector<Index> isolated;
  for (std::size_t i = 0; i < used.size(); ++i)
  {
    if (!used[i])
    {
      isolated.push_back(static_cast<Index>(i));
    }
  }
  return isolated;
}
}
