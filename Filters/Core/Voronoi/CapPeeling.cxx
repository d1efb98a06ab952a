// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/CapPeeling.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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
  // The lookups in parallel (each triangle on its own), the counts after.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.Faces.size(), 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t f = range.begin(); f != range.end(); ++f)
      {
        const auto& t = mesh.Faces[f];
        for (int k = 0; k < 3; ++k)
        {
          this->FaceEdges[f][k] = this->Id(t[k], t[(k + 1) % 3]);
        }
      }
    });
  for (const auto& sides : this->FaceEdges)
  {
    for (std::size_t e : sides)
    {
      ++this->FaceCount[e];
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

const std::array<std::size_t, 3>& CapPeeler::EdgesOf(std::size_t face) const
{
  const std::size_t nf = this->Incidence.FaceEdges.size();
  return face < nf ? this->Incidence.FaceEdges[face] : this->FanEdges[face - nf];
}

template <typename F>
void CapPeeler::ForEachFaceOn(std::size_t edge, F&& visit) const
{
  const std::size_t ne = this->Incidence.Edges.size();
  if (edge >= ne) // a spoke of a fan
  {
    for (std::size_t f : this->SpokeFaces[edge - ne])
    {
      visit(f);
    }
    return;
  }
  for (std::size_t i = this->Incidence.Start[edge]; i < this->Incidence.Start[edge + 1]; ++i)
  {
    visit(static_cast<std::size_t>(this->Incidence.EdgeFaces[i]));
  }
  for (auto on = std::lower_bound(this->FansOnEdge.begin(), this->FansOnEdge.end(),
         std::pair<std::size_t, std::size_t>{ edge, 0 });
       on != this->FansOnEdge.end() && on->first == edge; ++on)
  {
    visit(on->second);
  }
}

CapPeeler::CapPeeler(const MedialMesh& mesh)
  : Incidence(mesh)
  , RemovedAt(mesh.Faces.size(), Survived)
  , Witness(mesh.Faces.size(), 0)
  , SurvivorsOn(this->Incidence.FaceCount)
{
  const auto freeEdge = [&](std::size_t f)
  {
    for (std::size_t e : this->Incidence.FaceEdges[f])
    {
      if (this->SurvivorsOn[e] == 1)
      {
        return e;
      }
    }
    return Survived;
  };
  std::vector<std::size_t> stack;
  for (std::size_t f = mesh.Faces.size(); f-- > 0;)
  {
    stack.push_back(f);
  }
  while (!stack.empty())
  {
    const std::size_t f = stack.back();
    stack.pop_back();
    const std::size_t witness = this->RemovedAt[f] == Survived ? freeEdge(f) : Survived;
    if (witness == Survived)
    {
      continue;
    }
    this->RemovedAt[f] = this->Removals++;
    this->Witness[f] = witness;
    for (std::size_t e : this->Incidence.FaceEdges[f])
    {
      if (--this->SurvivorsOn[e] == 1)
      {
        this->ForEachFaceOn(e,
          [&](std::size_t g)
          {
            if (this->RemovedAt[g] == Survived)
            {
              stack.push_back(g);
            }
          });
      }
    }
  }
}

bool CapPeeler::PeelWithFan(const std::vector<Index>& loop, std::vector<std::size_t>& order,
  std::vector<std::size_t>& survivors, std::vector<std::size_t>& witnesses) const
{
  // The candidate fan: face fan0 + k is hub, loop[k], loop[k + 1]; its
  // edges are the loop edge and spokes spoke0 + k and spoke0 + k + 1.
  const std::size_t n = loop.size();
  const std::size_t fan0 = this->RemovedAt.size(), spoke0 = this->SurvivorsOn.size();
  std::vector<std::array<std::size_t, 3>> fanEdges(n);
  std::vector<std::pair<std::size_t, std::size_t>> fanOnEdge; // sorted (loop edge, fan face)
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t e = this->Incidence.Id(loop[k], loop[(k + 1) % n]);
    fanEdges[k] = { e, spoke0 + k, spoke0 + (k + 1) % n };
    fanOnEdge.emplace_back(e, fan0 + k);
  }
  std::sort(fanOnEdge.begin(), fanOnEdge.end());
  const auto edgesOf = [&](std::size_t f) -> const std::array<std::size_t, 3>&
  { return f < fan0 ? this->EdgesOf(f) : fanEdges[f - fan0]; };
  const auto forEachFaceOn = [&](std::size_t e, auto&& visit)
  {
    if (e >= spoke0)
    {
      visit(fan0 + (e - spoke0));
      visit(fan0 + (e - spoke0 + n - 1) % n);
      return;
    }
    this->ForEachFaceOn(e, visit);
    for (auto on = std::lower_bound(
           fanOnEdge.begin(), fanOnEdge.end(), std::pair<std::size_t, std::size_t>{ e, 0 });
         on != fanOnEdge.end() && on->first == e; ++on)
    {
      visit(on->second);
    }
  };
  // The triangles whose removal depends on a loop edge: removed with it as
  // their witness, or with an edge of such a triangle as their witness.
  std::vector<std::size_t> peel;
  std::vector<char> inPeel(fan0 + n, 0);
  const auto dependsOn = [&](std::size_t e, std::size_t g)
  {
    if (g < fan0 && !inPeel[g] && this->RemovedAt[g] != Survived && this->Witness[g] == e)
    {
      inPeel[g] = 1;
      peel.push_back(g);
    }
  };
  for (const auto& on : fanOnEdge)
  {
    this->ForEachFaceOn(on.first, [&](std::size_t g) { dependsOn(on.first, g); });
  }
  for (std::size_t i = 0; i < peel.size(); ++i)
  {
    for (std::size_t e : this->EdgesOf(peel[i]))
    {
      this->ForEachFaceOn(e, [&](std::size_t g) { dependsOn(e, g); });
    }
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    inPeel[fan0 + k] = 1;
    peel.push_back(fan0 + k);
  }
  // Peel them again on top of the survivors of the first peeling, which
  // stay: every edge of theirs keeps two of them.
  std::vector<std::pair<std::size_t, int>> live; // sorted (edge, triangles on it)
  for (std::size_t f : peel)
  {
    for (std::size_t e : edgesOf(f))
    {
      live.emplace_back(e, 0);
    }
  }
  std::sort(live.begin(), live.end());
  live.erase(std::unique(live.begin(), live.end()), live.end());
  const auto count = [&](std::size_t e) -> int& {
    return std::lower_bound(live.begin(), live.end(), std::pair<std::size_t, int>{ e, 0 })->second;
  };
  for (auto& [e, c] : live)
  {
    c = e < spoke0 ? this->SurvivorsOn[e] : 0;
  }
  for (std::size_t f : peel)
  {
    for (std::size_t e : edgesOf(f))
    {
      ++count(e);
    }
  }
  const auto freeEdge = [&](std::size_t f)
  {
    for (std::size_t e : edgesOf(f))
    {
      if (count(e) == 1)
      {
        return e;
      }
    }
    return Survived;
  };
  order.clear();
  witnesses.clear();
  std::vector<std::size_t> stack(peel.rbegin(), peel.rend());
  while (!stack.empty())
  {
    const std::size_t f = stack.back();
    stack.pop_back();
    const std::size_t witness = inPeel[f] ? freeEdge(f) : Survived;
    if (witness == Survived)
    {
      continue;
    }
    inPeel[f] = 0; // removed
    order.push_back(f);
    witnesses.push_back(witness);
    for (std::size_t e : edgesOf(f))
    {
      if (--count(e) == 1)
      {
        forEachFaceOn(e,
          [&](std::size_t g)
          {
            if (inPeel[g])
            {
              stack.push_back(g);
            }
          });
      }
    }
  }
  survivors.clear();
  for (std::size_t f : peel)
  {
    if (inPeel[f])
    {
      survivors.push_back(f);
    }
  }
  return !survivors.empty() && survivors.back() >= fan0;
}

bool CapPeeler::CapClosesVoid(const std::vector<Index>& loop) const
{
  if (this->BoundsSmallPatch(loop))
  {
    return true;
  }
  std::vector<std::size_t> order, survivors, witnesses;
  return this->PeelWithFan(loop, order, survivors, witnesses);
}

void CapPeeler::AddCap(const std::vector<Index>& loop)
{
  std::vector<std::size_t> order, survivors, witnesses;
  this->PeelWithFan(loop, order, survivors, witnesses);
  const std::size_t n = loop.size();
  const std::size_t fan0 = this->RemovedAt.size(), spoke0 = this->SurvivorsOn.size();
  const std::size_t nf = this->Incidence.FaceEdges.size();
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t e = this->Incidence.Id(loop[k], loop[(k + 1) % n]);
    this->FanEdges.push_back({ e, spoke0 + k, spoke0 + (k + 1) % n });
    this->FansOnEdge.emplace_back(e, fan0 + k);
    this->SpokeFaces.push_back({ fan0 + k, fan0 + (k + n - 1) % n });
  }
  std::sort(this->FansOnEdge.begin(), this->FansOnEdge.end());
  this->RemovedAt.resize(nf + this->FanEdges.size(), Survived);
  this->Witness.resize(this->RemovedAt.size(), 0);
  this->SurvivorsOn.resize(spoke0 + n, 0);
  // The triangles peeled again went after all the others, in the order
  // found; what survived holds its edges.
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    this->RemovedAt[order[i]] = this->Removals++;
    this->Witness[order[i]] = witnesses[i];
  }
  for (std::size_t f : survivors)
  {
    this->RemovedAt[f] = Survived;
    for (std::size_t e : this->EdgesOf(f))
    {
      ++this->SurvivorsOn[e];
    }
  }
}

bool CapPeeler::PeelsAway() const
{
  return std::none_of(this->RemovedAt.begin(), this->RemovedAt.end(),
    [](std::size_t removedAt) { return removedAt == Survived; });
}

std::vector<char> CapPeeler::EdgesLeft() const
{
  std::vector<char> left(this->Incidence.Edges.size(), 1);
  for (std::size_t f = 0; f < this->RemovedAt.size(); ++f)
  {
    if (this->RemovedAt[f] != Survived && this->Witness[f] < left.size())
    {
      left[this->Witness[f]] = 0;
    }
  }
  return left;
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
