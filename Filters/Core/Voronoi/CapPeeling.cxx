// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/CapPeeling.h"

#include <algorithm>
#include <limits>

namespace medialaxis
{
namespace repair
{
FaceIncidence::FaceIncidence(const MedialMesh& mesh)
  : Edges(AllEdges(mesh))
  , FaceEdges(mesh.Faces.size())
  , FaceCount(this->Edges.size(), 0)
  , Start(this->Edges.size() + 1, 0)
  , FirstEdge(mesh.NumberOfVertices() + 1, 0)
{
  // Edges are sorted by their smaller vertex: the edges of each vertex as
  // the smaller one form a run, found in constant time (a few edges long),
  // where a binary search over all edges missed the cache at every step.
  for (const EdgeKey& e : this->Edges)
  {
    ++this->FirstEdge[e[0] + 1];
  }
  for (std::size_t v = 0; v + 1 < this->FirstEdge.size(); ++v)
  {
    this->FirstEdge[v + 1] += this->FirstEdge[v];
  }
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    const auto& t = mesh.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      this->FaceEdges[f][k] = this->Id(t[k], t[(k + 1) % 3]);
      ++this->FaceCount[this->FaceEdges[f][k]];
    }
  }
  for (std::size_t e = 0; e < this->Edges.size(); ++e)
  {
    this->Start[e + 1] = this->Start[e] + static_cast<std::size_t>(this->FaceCount[e]);
  }
  this->EdgeFaces.resize(this->Start.back());
  std::vector<std::size_t> cursor(this->Start.begin(), this->Start.end() - 1);
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    for (std::size_t e : this->FaceEdges[f])
    {
      this->EdgeFaces[cursor[e]++] = static_cast<Index>(f);
    }
  }
}

bool CapPeeler::CapClosesVoid(const std::vector<Index>& loop) const
{
  if (this->BoundsSmallPatch(loop))
  {
    return true;
  }
  const std::size_t nf = this->Incidence.FaceEdges.size(), ne = this->Incidence.Edges.size();
  // The fans: the caps made so far, then the candidate. Fan face i (id
  // nf + i) is hub, loop[k], loop[k + 1]; its edges: the loop edge and the
  // spokes to loop[k] and loop[k + 1] (ids ne + the spoke's number).
  std::vector<std::array<std::size_t, 3>> capEdges;
  std::vector<std::pair<std::size_t, Index>> loopEdgeCap; // sorted: edge -> fan face
  std::vector<std::array<std::size_t, 2>> spokeFaces;     // the two fan faces of each spoke
  std::vector<int> count(this->Incidence.FaceCount);
  std::size_t candidate = 0; // the candidate's first fan face
  const auto addFan = [&](const std::vector<Index>& fan)
  {
    const std::size_t n = fan.size(), face = capEdges.size(), spoke = spokeFaces.size();
    for (std::size_t k = 0; k < n; ++k)
    {
      const std::size_t e = this->Incidence.Id(fan[k], fan[(k + 1) % n]);
      capEdges.push_back({ e, ne + spoke + k, ne + spoke + (k + 1) % n });
      ++count[e];
      loopEdgeCap.emplace_back(e, static_cast<Index>(nf + face + k));
      spokeFaces.push_back({ nf + face + k, nf + face + (k + n - 1) % n });
    }
  };
  for (const std::vector<Index>& cap : this->Caps)
  {
    addFan(cap);
  }
  candidate = capEdges.size();
  addFan(loop);
  count.resize(ne + spokeFaces.size(), 2);
  std::sort(loopEdgeCap.begin(), loopEdgeCap.end());
  const std::size_t nc = capEdges.size();
  auto edgesOf = [&](std::size_t f) -> const std::array<std::size_t, 3>&
  { return f < nf ? this->Incidence.FaceEdges[f] : capEdges[f - nf]; };
  std::vector<char> alive(nf + nc, 1);
  auto isFree = [&](std::size_t f)
  {
    const auto& e = edgesOf(f);
    return count[e[0]] == 1 || count[e[1]] == 1 || count[e[2]] == 1;
  };
  std::vector<Index> stack;
  for (std::size_t f = 0; f < nf + nc; ++f)
  {
    if (isFree(f))
    {
      stack.push_back(static_cast<Index>(f));
    }
  }
  auto pushFacesOf = [&](std::size_t e)
  {
    if (e >= ne) // a spoke: the fan faces on either side
    {
      for (std::size_t f : spokeFaces[e - ne])
      {
        stack.push_back(static_cast<Index>(f));
      }
      return;
    }
    for (std::size_t i = this->Incidence.Start[e]; i < this->Incidence.Start[e + 1]; ++i)
    {
      stack.push_back(this->Incidence.EdgeFaces[i]);
    }
    for (auto cap = std::lower_bound(loopEdgeCap.begin(), loopEdgeCap.end(),
           std::pair<std::size_t, Index>{ e, std::numeric_limits<Index>::min() });
         cap != loopEdgeCap.end() && cap->first == e; ++cap)
    {
      stack.push_back(cap->second);
    }
  };
  while (!stack.empty())
  {
    const std::size_t f = static_cast<std::size_t>(stack.back());
    stack.pop_back();
    if (!alive[f] || !isFree(f))
    {
      continue;
    }
    alive[f] = 0;
    for (std::size_t e : edgesOf(f))
    {
      if (--count[e] == 1)
      {
        pushFacesOf(e);
      }
    }
  }
  return std::any_of(alive.begin() + static_cast<std::ptrdiff_t>(nf + candidate), alive.end(),
    [](char a) { return a != 0; });
}

bool CapPeeler::BoundsSmallPatch(const std::vector<Index>& loop) const
{
  constexpr std::size_t limit = 64; // triangles; beyond, peeling decides
  std::vector<std::size_t> rim;
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    rim.push_back(this->Incidence.Id(loop[k], loop[(k + 1) % loop.size()]));
    const int count = this->Incidence.FaceCount[rim.back()];
    if (count != 1 && count != 2)
    {
      return false;
    }
  }
  const std::size_t first = rim[0];
  std::sort(rim.begin(), rim.end());
  // The patch on each side of the loop's first edge (a rim edge of a sheet
  // has one side): grown across edges on exactly two triangles, never across
  // the loop, it must close up with every loop edge on exactly one of its
  // triangles. With the cap it then makes a closed surface, which no peeling
  // removes.
  std::vector<Index> patch;
  for (std::size_t side = this->Incidence.Start[first]; side < this->Incidence.Start[first + 1];
       ++side)
  {
    patch.assign(1, this->Incidence.EdgeFaces[side]);
    bool closed = true;
    for (std::size_t k = 0; closed && k < patch.size(); ++k)
    {
      for (std::size_t e : this->Incidence.FaceEdges[patch[k]])
      {
        if (std::binary_search(rim.begin(), rim.end(), e))
        {
          continue;
        }
        if (this->Incidence.FaceCount[e] != 2 || patch.size() > limit)
        {
          closed = false;
          break;
        }
        for (std::size_t i = this->Incidence.Start[e]; i < this->Incidence.Start[e + 1]; ++i)
        {
          const Index f = this->Incidence.EdgeFaces[i];
          if (std::find(patch.begin(), patch.end(), f) == patch.end())
          {
            patch.push_back(f);
          }
        }
      }
    }
    closed = closed && patch.size() <= limit &&
      std::all_of(rim.begin(), rim.end(),
        [&](std::size_t e)
        {
          int on = 0;
          for (std::size_t i = this->Incidence.Start[e]; i < this->Incidence.Start[e + 1]; ++i)
          {
            on += std::find(patch.begin(), patch.end(), this->Incidence.EdgeFaces[i]) != patch.end()
              ? 1
              : 0;
          }
          return on == 1;
        });
    if (closed)
    {
      return true;
    }
  }
  return false;
}
}
}
