// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/MedialComplexCleanup.h"

#include "Support/DisjointSets.h"

#include <algorithm>

namespace medialaxis
{
namespace
{
using EdgeKey = std::array<Index, 2>;

EdgeKey Key(Index a, Index b)
{
  return a < b ? EdgeKey{ a, b } : EdgeKey{ b, a };
}

// Keeps the vertices, edges and faces marked alive, renumbering vertices and
// carrying the Atlas and the per-face site pairs along.
void Compact(VoronoiMedialAxisResult& result, const std::vector<char>& vertexAlive,
  const std::vector<char>& faceAlive, const std::vector<EdgeKey>& edges)
{
  // In place: a kept item only moves to a lower index, so each array is
  // written over its own front (a copy beside the old complex was 27 MB at
  // 170,000 spheres).
  MedialMesh& mesh = result.Mesh;
  std::vector<Index> newId(mesh.Centers.size(), -1);
  const bool withClearance = result.SiteClearance.size() == mesh.Centers.size();
  std::vector<Index>& offsets = result.AtlasOffsets;
  std::vector<Index>& sites = result.AtlasSites;
  std::size_t vertices = 0, written = 0;
  for (std::size_t v = 0; v < mesh.Centers.size(); ++v)
  {
    if (!vertexAlive[v])
    {
      continue;
    }
    newId[v] = static_cast<Index>(vertices);
    mesh.Centers[vertices] = mesh.Centers[v];
    mesh.Radii[vertices] = mesh.Radii[v];
    if (withClearance)
    {
      result.SiteClearance[vertices] = result.SiteClearance[v];
    }
    // offsets[v] is read before offsets[vertices + 1] (<= v + 1) is written.
    const Index first = offsets[v], last = offsets[v + 1];
    for (Index k = first; k < last; ++k)
    {
      sites[written++] = sites[k];
    }
    offsets[vertices + 1] = static_cast<Index>(written);
    ++vertices;
  }
  mesh.Centers.resize(vertices);
  mesh.Radii.resize(vertices);
  result.SiteClearance.resize(withClearance ? vertices : 0);
  offsets.resize(vertices + 1);
  sites.resize(written);
  std::size_t faces = 0;
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    if (faceAlive[f])
    {
      const auto t = mesh.Faces[f];
      mesh.Faces[faces] = { newId[t[0]], newId[t[1]], newId[t[2]] };
      result.FaceSitePair[faces] = result.FaceSitePair[f];
      ++faces;
    }
  }
  mesh.Faces.resize(faces);
  result.FaceSitePair.resize(faces);
  mesh.Edges.clear();
  mesh.Edges.reserve(edges.size());
  for (const EdgeKey& e : edges)
  {
    mesh.Edges.push_back({ newId[e[0]], newId[e[1]] });
  }
}
}

std::size_t CollapseFlaggedTriangles(
  VoronoiMedialAxisResult& result, const std::vector<char>& flagged)
{
  MedialMesh& mesh = result.Mesh;
  const std::size_t nf = mesh.Faces.size(), nv = mesh.Centers.size();
  if (std::find(flagged.begin(), flagged.end(), 1) == flagged.end())
  {
    return 0;
  }
  // Per-vertex incidences (compressed rows): faces, and Voronoi edges.
  auto buildRows = [nv](std::size_t count, auto&& forEach)
  {
    std::vector<std::size_t> start(nv + 1, 0);
    forEach([&start](Index v, Index) { ++start[v + 1]; });
    for (std::size_t v = 0; v < nv; ++v)
    {
      start[v + 1] += start[v];
    }
    std::vector<Index> items(start[nv]);
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    forEach([&](Index v, Index item) { items[cursor[v]++] = item; });
    (void)count;
    return std::make_pair(std::move(start), std::move(items));
  };
  // Plain references, not structured bindings: C++17 does not let lambdas
  // capture those (GCC allows it, clang refuses).
  const auto faceRows = buildRows(3 * nf,
    [&mesh](auto&& add)
    {
      for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
      {
        for (Index v : mesh.Faces[f])
        {
          add(v, static_cast<Index>(f));
        }
      }
    });
  auto lineRowsOfMesh = [&mesh, &buildRows]()
  {
    return buildRows(2 * mesh.Edges.size(),
      [&mesh](auto&& add)
      {
        for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
        {
          add(mesh.Edges[e][0], static_cast<Index>(e));
          add(mesh.Edges[e][1], static_cast<Index>(e));
        }
      });
  };
  auto lineRows = lineRowsOfMesh(); // rebuilt when step 1 adds lines
  const std::vector<std::size_t>& faceStart = faceRows.first;
  const std::vector<Index>& vertexFaces = faceRows.second;
  const std::vector<std::size_t>& lineStart = lineRows.first;
  const std::vector<Index>& vertexLines = lineRows.second;

  std::vector<char> faceAlive(nf, 1), edgeAlive(mesh.Edges.size(), 1);
  std::vector<int> aliveFaces(nv, 0);
  for (const auto& t : mesh.Faces)
  {
    for (Index v : t)
    {
      ++aliveFaces[v];
    }
  }
  auto contains = [&mesh](Index f, Index v)
  {
    const auto& t = mesh.Faces[f];
    return t[0] == v || t[1] == v || t[2] == v;
  };
  // Alive triangles on edge (a, b), and one flagged one among them.
  auto trianglesOn = [&](Index a, Index b, Index* flaggedFace)
  {
    int count = 0;
    for (std::size_t i = faceStart[a]; i < faceStart[a + 1]; ++i)
    {
      const Index f = vertexFaces[i];
      if (faceAlive[f] && contains(f, b))
      {
        ++count;
        if (flaggedFace && flagged[f])
        {
          *flaggedFace = f;
        }
      }
    }
    return count;
  };
  auto killVoronoiEdge = [&](Index a, Index b)
  {
    for (std::size_t i = lineStart[a]; i < lineStart[a + 1]; ++i)
    {
      const auto& e = mesh.Edges[vertexLines[i]];
      if ((e[0] == b || e[1] == b) && edgeAlive[vertexLines[i]])
      {
        edgeAlive[vertexLines[i]] = 0;
      }
    }
  };

  // 1. Collapse flagged triangles through free edges.
  std::vector<Index> queue, touched, removedFaces;
  std::vector<EdgeKey> collapsedEdges; // the free edges that went with them
  for (std::size_t f = 0; f < nf; ++f)
  {
    if (flagged[f])
    {
      queue.push_back(static_cast<Index>(f));
    }
  }
  std::size_t removed = 0;
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    const Index f = queue[head];
    if (!faceAlive[f])
    {
      continue;
    }
    const auto t = mesh.Faces[f];
    int freeK = -1;
    for (int k = 0; k < 3 && freeK < 0; ++k)
    {
      if (trianglesOn(t[k], t[(k + 1) % 3], nullptr) == 1)
      {
        freeK = k;
      }
    }
    if (freeK < 0)
    {
      continue; // enclosed for now; revisited when a neighbour goes
    }
    faceAlive[f] = 0;
    ++removed;
    removedFaces.push_back(f);
    collapsedEdges.push_back(Key(t[freeK], t[(freeK + 1) % 3]));
    killVoronoiEdge(t[freeK], t[(freeK + 1) % 3]);
    for (Index v : t)
    {
      --aliveFaces[v];
      touched.push_back(v);
    }
    for (int k = 0; k < 3; ++k)
    {
      Index next = -1;
      if (k != freeK && trianglesOn(t[k], t[(k + 1) % 3], &next) == 1 && next >= 0)
      {
        queue.push_back(next);
      }
    }
  }
  if (removed == 0)
  {
    return 0;
  }

  // A triangle collapsed through one edge leaves its other two: those that
  // no triangle holds any more stay as lines, or a strip of flagged
  // triangles between two parts of the complex would cut it in two.
  {
    std::sort(collapsedEdges.begin(), collapsedEdges.end());
    std::vector<EdgeKey> existing, bare;
    for (const auto& e : mesh.Edges)
    {
      existing.push_back(Key(e[0], e[1]));
    }
    std::sort(existing.begin(), existing.end());
    for (Index f : removedFaces)
    {
      const auto& t = mesh.Faces[f];
      for (int k = 0; k < 3; ++k)
      {
        const EdgeKey e = Key(t[k], t[(k + 1) % 3]);
        if (trianglesOn(e[0], e[1], nullptr) == 0 &&
          !std::binary_search(collapsedEdges.begin(), collapsedEdges.end(), e) &&
          !std::binary_search(existing.begin(), existing.end(), e))
        {
          bare.push_back(e);
        }
      }
    }
    std::sort(bare.begin(), bare.end());
    bare.erase(std::unique(bare.begin(), bare.end()), bare.end());
    for (const EdgeKey& e : bare)
    {
      mesh.Edges.push_back({ e[0], e[1] });
      edgeAlive.push_back(1);
    }
    if (!bare.empty())
    {
      lineRows = lineRowsOfMesh();
    }
  }

  // 2. Voronoi edges left dangling are collapsed through vertices that
  // nothing else uses (no triangle and no other edge).
  std::vector<char> vertexAlive(nv, 1);
  auto aliveLinesAt = [&](Index v, Index* only)
  {
    int count = 0;
    for (std::size_t i = lineStart[v]; i < lineStart[v + 1]; ++i)
    {
      if (edgeAlive[vertexLines[i]])
      {
        ++count;
        *only = vertexLines[i];
      }
    }
    return count;
  };
  for (std::size_t head = 0; head < touched.size(); ++head)
  {
    const Index v = touched[head];
    Index edge = -1;
    if (!vertexAlive[v] || aliveFaces[v] != 0 || aliveLinesAt(v, &edge) != 1)
    {
      continue;
    }
    edgeAlive[edge] = 0;
    vertexAlive[v] = 0;
    const auto& e = mesh.Edges[edge];
    touched.push_back(e[0] == v ? e[1] : e[0]);
  }
  std::vector<EdgeKey> lines;
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
  {
    if (edgeAlive[e])
    {
      lines.push_back(Key(mesh.Edges[e][0], mesh.Edges[e][1]));
    }
  }
  Compact(result, vertexAlive, faceAlive, lines);
  return removed;
}

std::size_t DropSmallComponents(VoronoiMedialAxisResult& result, std::size_t minimumVertices)
{
  MedialMesh& mesh = result.Mesh;
  const std::size_t nv = mesh.Centers.size();
  DisjointSets pieces(nv);
  for (const auto& e : mesh.Edges)
  {
    pieces.Union(e[0], e[1]);
  }
  for (const auto& t : mesh.Faces)
  {
    pieces.Union(t[0], t[1]);
    pieces.Union(t[1], t[2]);
  }
  std::vector<std::size_t> size(nv, 0);
  for (std::size_t v = 0; v < nv; ++v)
  {
    ++size[pieces.Find(static_cast<Index>(v))];
  }
  // The largest piece always stays (a sphere's medial axis is one point).
  const std::size_t largest = nv ? *std::max_element(size.begin(), size.end()) : 0;
  std::vector<char> vertexAlive(nv, 1);
  std::size_t dropped = 0;
  for (std::size_t v = 0; v < nv; ++v)
  {
    const Index root = pieces.Find(static_cast<Index>(v));
    if (size[root] < minimumVertices && size[root] < largest)
    {
      vertexAlive[v] = 0;
      dropped += root == static_cast<Index>(v) ? 1 : 0;
    }
  }
  if (dropped == 0)
  {
    return 0;
  }
  std::vector<char> faceAlive(mesh.Faces.size());
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    faceAlive[f] = vertexAlive[mesh.Faces[f][0]];
  }
  std::vector<EdgeKey> lines;
  for (const auto& e : mesh.Edges)
  {
    if (vertexAlive[e[0]])
    {
      lines.push_back(Key(e[0], e[1]));
    }
  }
  Compact(result, vertexAlive, faceAlive, lines);
  return dropped;
}
}
