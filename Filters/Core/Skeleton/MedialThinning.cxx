// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeleton/MedialThinning.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <tuple>

namespace medialaxis
{
namespace
{
void InsertSorted(std::vector<Index>& list, Index v)
{
  const auto it = std::lower_bound(list.begin(), list.end(), v);
  if (it == list.end() || *it != v)
  {
    list.insert(it, v);
  }
}

void EraseSorted(std::vector<Index>& list, Index v)
{
  const auto it = std::lower_bound(list.begin(), list.end(), v);
  if (it != list.end() && *it == v)
  {
    list.erase(it);
  }
}

bool Contains(const std::array<Index, 3>& t, Index v)
{
  return t[0] == v || t[1] == v || t[2] == v;
}

// The complex under contraction: sorted neighbour lists, triangles with the
// vertices they lie on, and per vertex the sum and count of the medial
// vertices merged into it.
class Complex
{
public:
  explicit Complex(const MedialMesh& mesh)
    : Neighbours(mesh.NumberOfVertices())
    , VertexTriangles(mesh.NumberOfVertices())
    , Triangles(mesh.Faces)
    , TriangleAlive(mesh.Faces.size(), 1)
    , Sum(mesh.NumberOfVertices())
    , Weight(mesh.NumberOfVertices())
    , Alive(mesh.NumberOfVertices(), 1)
    , Stamp(mesh.NumberOfVertices(), 0)
    , MergedInto(mesh.NumberOfVertices(), -1)
  {
    const auto link = [this](Index a, Index b)
    {
      if (a != b)
      {
        this->Neighbours[a].push_back(b);
        this->Neighbours[b].push_back(a);
      }
    };
    for (std::size_t f = 0; f < this->Triangles.size(); ++f)
    {
      const auto& t = this->Triangles[f];
      for (int k = 0; k < 3; ++k)
      {
        link(t[k], t[(k + 1) % 3]);
        this->VertexTriangles[t[k]].push_back(static_cast<Index>(f));
      }
    }
    for (const auto& e : mesh.Edges)
    {
      link(e[0], e[1]);
    }
    for (auto& list : this->Neighbours)
    {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    // Weights: the balls' volumes (r^3, above a floor so that a cluster of
    // zero radii still has a centroid).
    double largest = 0.0;
    for (double r : mesh.Radii)
    {
      largest = std::max(largest, r);
    }
    const double floor = 1e-3 * largest;
    for (std::size_t v = 0; v < mesh.NumberOfVertices(); ++v)
    {
      const double r = std::max(mesh.Radii[v], floor);
      this->Weight[v] = r * r * r;
      this->Sum[v] = this->Weight[v] * mesh.Centers[v];
    }
  }

  Point3 Position(Index v) const { return (1.0 / this->Weight[v]) * this->Sum[v]; }

  // The third vertices of the live triangles on edge (a, b), sorted.
  void Apexes(Index a, Index b, std::vector<Index>& out) const
  {
    out.clear();
    for (Index f : this->VertexTriangles[a])
    {
      const auto& t = this->Triangles[f];
      if (this->TriangleAlive[f] && Contains(t, b))
      {
        out.push_back(t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]));
      }
    }
    std::sort(out.begin(), out.end());
  }

  bool HasTriangle(Index a, Index b, Index c) const
  {
    for (Index f : this->VertexTriangles[a])
    {
      if (this->TriangleAlive[f] && Contains(this->Triangles[f], b) &&
        Contains(this->Triangles[f], c))
      {
        return true;
      }
    }
    return false;
  }

  // Lk(a) n Lk(b) = Lk(ab): the common neighbours are the apexes of the
  // triangles on ab, and no edge uw closes triangles with both a and b.
  bool LinkConditionHolds(
    Index a, Index b, std::vector<Index>& apexes, std::vector<Index>& common) const
  {
    this->Apexes(a, b, apexes);
    common.clear();
    std::set_intersection(this->Neighbours[a].begin(), this->Neighbours[a].end(),
      this->Neighbours[b].begin(), this->Neighbours[b].end(), std::back_inserter(common));
    if (common != apexes)
    {
      return false;
    }
    for (std::size_t i = 0; i < apexes.size(); ++i)
    {
      for (std::size_t j = i + 1; j < apexes.size(); ++j)
      {
        if (this->HasTriangle(a, apexes[i], apexes[j]) &&
          this->HasTriangle(b, apexes[i], apexes[j]))
        {
          return false;
        }
      }
    }
    return true;
  }

  // Merges b into a.
  void Contract(Index a, Index b)
  {
    for (Index f : this->VertexTriangles[b])
    {
      if (!this->TriangleAlive[f])
      {
        continue;
      }
      auto& t = this->Triangles[f];
      if (Contains(t, a))
      {
        this->TriangleAlive[f] = 0;
        continue;
      }
      for (Index& v : t)
      {
        v = v == b ? a : v;
      }
      this->VertexTriangles[a].push_back(f);
    }
    for (Index u : this->Neighbours[b])
    {
      EraseSorted(this->Neighbours[u], b);
      if (u != a)
      {
        InsertSorted(this->Neighbours[u], a);
        InsertSorted(this->Neighbours[a], u);
      }
    }
    std::vector<Index>().swap(this->Neighbours[b]);
    std::vector<Index>().swap(this->VertexTriangles[b]);
    auto& mine = this->VertexTriangles[a];
    mine.erase(
      std::remove_if(mine.begin(), mine.end(), [this](Index f) { return !this->TriangleAlive[f]; }),
      mine.end());
    std::sort(mine.begin(), mine.end());
    mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    this->Sum[a] = this->Sum[a] + this->Sum[b];
    this->Weight[a] += this->Weight[b];
    this->Alive[b] = 0;
    this->MergedInto[b] = a;
    ++this->Stamp[a];
  }

  // Collapses every triangle that has a free edge when its turn comes (in
  // id order), removing that edge; returns how many.
  std::size_t CollapseFreeFaces()
  {
    std::size_t collapsed = 0;
    std::vector<Index> apexes;
    for (std::size_t f = 0; f < this->Triangles.size(); ++f)
    {
      if (!this->TriangleAlive[f])
      {
        continue;
      }
      const auto t = this->Triangles[f];
      for (int k = 0; k < 3; ++k)
      {
        const Index u = t[k], v = t[(k + 1) % 3];
        this->Apexes(u, v, apexes);
        if (apexes.size() == 1)
        {
          this->TriangleAlive[f] = 0;
          EraseSorted(this->Neighbours[u], v);
          EraseSorted(this->Neighbours[v], u);
          ++this->Stamp[u];
          ++this->Stamp[v];
          ++collapsed;
          break;
        }
      }
    }
    return collapsed;
  }

  std::size_t LiveTriangles() const
  {
    return static_cast<std::size_t>(
      std::count(this->TriangleAlive.begin(), this->TriangleAlive.end(), 1));
  }

  std::vector<std::vector<Index>> Neighbours;
  std::vector<std::vector<Index>> VertexTriangles;
  std::vector<std::array<Index, 3>> Triangles;
  std::vector<char> TriangleAlive;
  std::vector<Point3> Sum; // of the centres, weighted
  std::vector<double> Weight;
  std::vector<char> Alive;
  std::vector<std::uint32_t> Stamp;
  std::vector<Index> MergedInto;
};

// One contraction of the shortest contractible edge after another, until
// none is left; returns how many.
std::size_t ContractShortest(Complex& c, std::size_t& done, std::size_t total,
  const std::function<bool(double)>& progress, bool& aborted)
{
  using Entry = std::tuple<double, Index, Index, std::uint32_t, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  std::vector<Index> apexes, common;
  const auto push = [&](Index a, Index b)
  {
    c.Apexes(a, b, apexes);
    if (!apexes.empty())
    {
      const Index lo = std::min(a, b), hi = std::max(a, b);
      queue.emplace(Distance2(c.Position(lo), c.Position(hi)), lo, hi, c.Stamp[lo], c.Stamp[hi]);
    }
  };
  for (std::size_t f = 0; f < c.Triangles.size(); ++f)
  {
    if (c.TriangleAlive[f])
    {
      const auto& t = c.Triangles[f];
      for (int k = 0; k < 3; ++k)
      {
        if (t[k] < t[(k + 1) % 3])
        {
          push(t[k], t[(k + 1) % 3]);
        }
      }
    }
  }
  std::size_t contractions = 0;
  while (!queue.empty())
  {
    const auto [length2, a, b, stampA, stampB] = queue.top();
    queue.pop();
    if (!c.Alive[a] || !c.Alive[b] || c.Stamp[a] != stampA || c.Stamp[b] != stampB ||
      !c.LinkConditionHolds(a, b, apexes, common) || apexes.empty())
    {
      continue;
    }
    // The vertex of more weight stays (ties: the lower id).
    const Index keep = c.Weight[b] > c.Weight[a] ? b : a, gone = keep == a ? b : a;
    c.Contract(keep, gone);
    ++contractions;
    if (progress && ++done % 1024 == 0 && !progress(std::min(0.99, double(done) / total)))
    {
      aborted = true;
      return contractions;
    }
    for (Index u : std::vector<Index>(c.Neighbours[keep]))
    {
      push(keep, u);
    }
  }
  return contractions;
}
}

ThinnedGraph ThinMedialMesh(const MedialMesh& mesh, const std::function<bool(double)>& progress)
{
  ThinnedGraph out;
  Complex c(mesh);
  std::size_t done = 0;
  const std::size_t total = std::max<std::size_t>(1, mesh.NumberOfVertices());
  // Contractions until stuck, then the free faces; again while either acts.
  while (true)
  {
    const std::size_t contracted = ContractShortest(c, done, total, progress, out.Aborted);
    out.Contractions += contracted;
    if (out.Aborted)
    {
      return out;
    }
    if (c.LiveTriangles() == 0)
    {
      break;
    }
    const std::size_t collapsed = c.CollapseFreeFaces();
    out.FreeFaceCollapses += collapsed;
    if (collapsed == 0 && contracted == 0)
    {
      break;
    }
  }
  out.UncollapsedTriangles = c.LiveTriangles();

  // The graph: live vertices renumbered in order, their edges.
  const std::size_t nv = mesh.NumberOfVertices();
  std::vector<Index> id(nv, -1);
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (c.Alive[v])
    {
      id[v] = static_cast<Index>(out.Centroid.size());
      out.Centroid.push_back(c.Position(static_cast<Index>(v)));
    }
  }
  out.VertexOf.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    Index root = static_cast<Index>(v);
    while (c.MergedInto[root] >= 0)
    {
      root = c.MergedInto[root];
    }
    out.VertexOf[v] = id[root];
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    for (Index u : c.Neighbours[v])
    {
      if (c.Alive[v] && static_cast<Index>(v) < u)
      {
        out.Edges.push_back({ id[v], id[u] });
      }
    }
  }
  std::sort(out.Edges.begin(), out.Edges.end());
  return out;
}
}
