// SPDX-License-Identifier: GPL-3.0-or-later
// Fins folded into the sheets they hang on: a small sheet that branches off
// a larger one along junction edges and whose balls reach out of the cones
// of those edges by little covers only a small bump of the surface (as the
// scale axis transform's devoured balls do), yet its junction cuts the sheet
// it hangs on. Its vertices are collapsed, farthest first, into the
// junction, whose spheres stay where they are: the sheets on either side
// then join across it, and the topology is kept (every collapse passes the
// link condition and the validity checks).
#include "Mesh/MedialPrimitives.h"
#include "Simplification/EdgeCollapse.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <tuple>

namespace medialaxis
{
namespace
{
// The unit direction from the edge (u, v) towards x, across the edge.
Point3 AcrossEdge(const Point3& u, const Point3& v, const Point3& x)
{
  const Point3 e = v - u;
  const double e2 = Dot(e, e);
  Point3 d = x - u;
  if (e2 > 0.0)
  {
    d = d - (Dot(d, e) / e2) * e;
  }
  const double n = Norm(d);
  return n > 0.0 ? (1.0 / n) * d : d;
}
}

std::vector<std::vector<Index>> MedialEdgeCollapse::FindFins(double budget, double areaShare) const
{
  // Triangle edges (min, max, face) sorted by edge.
  std::vector<std::tuple<Index, Index, Index>> halfEdges;
  std::vector<Index> alive;
  for (std::size_t f = 0; f < this->Faces.size(); ++f)
  {
    if (!this->FaceAlive[f])
    {
      continue;
    }
    alive.push_back(static_cast<Index>(f));
    const auto& t = this->Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      const Index u = t[k], v = t[(k + 1) % 3];
      halfEdges.emplace_back(std::min(u, v), std::max(u, v), static_cast<Index>(f));
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  const std::size_t nf = this->Faces.size();
  DisjointSets sheets(nf);
  // Per face (at its sheet's root once merged): on a junction edge as a
  // branch, or as one of the two faces that go straight through it.
  std::vector<char> branch(nf, 0), through(nf, 0);
  std::vector<std::array<Index, 2>> junctionEdges;
  std::vector<Index> junctionFaces; // parallel to junctionEdges' runs
  std::vector<Index> runStart{ 0 };
  auto apex = [this](Index f, Index u, Index v)
  {
    for (Index w : this->Faces[f])
    {
      if (w != u && w != v)
      {
        return w;
      }
    }
    return this->Faces[f][0];
  };
  for (std::size_t i = 0; i < halfEdges.size();)
  {
    std::size_t j = i + 1;
    const auto [u, v, f0] = halfEdges[i];
    while (j < halfEdges.size() && std::get<0>(halfEdges[j]) == u && std::get<1>(halfEdges[j]) == v)
    {
      ++j;
    }
    if (j - i == 2)
    {
      sheets.Union(f0, std::get<2>(halfEdges[i + 1]));
    }
    else if (j - i > 2)
    {
      // The two faces closest to a straight continuation of each other go
      // through; the others branch off.
      const Point3 pu = this->Position(u), pv = this->Position(v);
      std::size_t bestA = i, bestB = i + 1;
      double flattest = HUGE_VAL;
      for (std::size_t a = i; a < j; ++a)
      {
        const Point3 da = AcrossEdge(pu, pv, this->Position(apex(std::get<2>(halfEdges[a]), u, v)));
        for (std::size_t b = a + 1; b < j; ++b)
        {
          const Point3 db =
            AcrossEdge(pu, pv, this->Position(apex(std::get<2>(halfEdges[b]), u, v)));
          const double c = Dot(da, db);
          if (c < flattest)
          {
            flattest = c;
            bestA = a;
            bestB = b;
          }
        }
      }
      junctionEdges.push_back({ u, v });
      for (std::size_t k = i; k < j; ++k)
      {
        const Index f = std::get<2>(halfEdges[k]);
        (k == bestA || k == bestB ? through : branch)[f] = 1;
        junctionFaces.push_back(f);
      }
      runStart.push_back(static_cast<Index>(junctionFaces.size()));
    }
    i = j;
  }
  // Per sheet (at its root): area, and whether it branches or goes through.
  std::vector<double> area(nf, 0.0);
  std::vector<char> sheetBranches(nf, 0), sheetThrough(nf, 0);
  double total = 0.0, largest = 0.0;
  for (Index f : alive)
  {
    const auto& t = this->Faces[f];
    const double a = 0.5 *
      Norm(Cross(
        this->Position(t[1]) - this->Position(t[0]), this->Position(t[2]) - this->Position(t[0])));
    const Index root = sheets.Find(f);
    area[root] += a;
    sheetBranches[root] |= branch[f];
    sheetThrough[root] |= through[f];
    total += a;
  }
  for (Index f : alive)
  {
    largest = std::max(largest, area[f]);
  }
  auto isCandidate = [&](Index root)
  {
    return sheetBranches[root] && !sheetThrough[root] && area[root] < areaShare * total &&
      area[root] < largest;
  };
  // Junction edges of each candidate sheet.
  std::vector<std::vector<std::array<Index, 2>>> attachment(nf);
  for (std::size_t e = 0; e < junctionEdges.size(); ++e)
  {
    for (Index k = runStart[e]; k < runStart[e + 1]; ++k)
    {
      const Index root = sheets.Find(junctionFaces[k]);
      if (isCandidate(root))
      {
        attachment[root].push_back(junctionEdges[e]);
      }
    }
  }
  // The vertices of each candidate, in face order (deterministic).
  std::vector<std::vector<Index>> members(nf);
  for (Index f : alive)
  {
    const Index root = sheets.Find(f);
    if (!attachment[root].empty())
    {
      members[root].insert(members[root].end(), this->Faces[f].begin(), this->Faces[f].end());
    }
  }
  std::vector<std::vector<Index>> fins;
  for (Index f : alive)
  {
    if (attachment[f].empty() || sheets.Find(f) != f)
    {
      continue;
    }
    auto& vertices = members[f];
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::vector<Index> attached;
    for (const auto& e : attachment[f])
    {
      attached.push_back(e[0]);
      attached.push_back(e[1]);
    }
    std::sort(attached.begin(), attached.end());
    attached.erase(std::unique(attached.begin(), attached.end()), attached.end());
    std::vector<ConePrimitive> cones;
    for (const auto& e : attachment[f])
    {
      cones.push_back(MakeCone(this->Position(e[0]), this->Spheres[e[0]][3], this->Position(e[1]),
        this->Spheres[e[1]][3]));
    }
    // How far the fin's balls reach out of the cones of its junction: the
    // surface it alone stands for.
    double protrusion = 0.0;
    bool free = false;
    for (Index v : vertices)
    {
      if (std::binary_search(attached.begin(), attached.end(), v))
      {
        continue;
      }
      free = true;
      double reach = HUGE_VAL;
      for (const ConePrimitive& cone : cones)
      {
        reach = std::min(reach, ConeDistance(cone, this->Position(v)).Distance);
      }
      protrusion = std::max(protrusion, reach + this->Spheres[v][3]);
    }
    if (free && protrusion <= budget)
    {
      // First the attachment, then the fin's own vertices.
      std::vector<Index> fin = attached;
      fin.push_back(-1);
      for (Index v : vertices)
      {
        if (!std::binary_search(attached.begin(), attached.end(), v))
        {
          fin.push_back(v);
        }
      }
      fins.push_back(std::move(fin));
    }
  }
  return fins;
}

std::size_t MedialEdgeCollapse::CollapseFins(double budget, double areaShare)
{
  std::size_t collapsed = 0;
  std::vector<Index> touched;
  for (int pass = 0; pass < 4; ++pass)
  {
    const std::vector<std::vector<Index>> fins = this->FindFins(budget, areaShare);
    std::size_t before = collapsed;
    for (const std::vector<Index>& fin : fins)
    {
      // Hops from the attachment, through the fin's vertices.
      const auto split = std::find(fin.begin(), fin.end(), Index(-1));
      std::vector<Index> own(split + 1, fin.end());
      std::vector<int> hops(own.size(), -1);
      auto slot = [&own](Index v)
      {
        const auto it = std::lower_bound(own.begin(), own.end(), v);
        return it != own.end() && *it == v ? static_cast<std::ptrdiff_t>(it - own.begin()) : -1;
      };
      auto isAttached = [&](Index v) { return std::binary_search(fin.begin(), split, v); };
      std::deque<Index> queue;
      for (std::size_t k = 0; k < own.size(); ++k)
      {
        for (Index u : this->VertexNeighbours[own[k]])
        {
          if (isAttached(u))
          {
            hops[k] = 1;
            queue.push_back(own[k]);
            break;
          }
        }
      }
      while (!queue.empty())
      {
        const Index v = queue.front();
        queue.pop_front();
        for (Index u : this->VertexNeighbours[v])
        {
          const std::ptrdiff_t k = slot(u);
          if (k >= 0 && hops[k] < 0)
          {
            hops[k] = hops[slot(v)] + 1;
            queue.push_back(u);
          }
        }
      }
      // Farthest first, each into a neighbour nearer the attachment (the
      // attachment itself at one hop), keeping that neighbour's sphere.
      std::vector<std::size_t> order(own.size());
      for (std::size_t k = 0; k < order.size(); ++k)
      {
        order[k] = k;
      }
      std::stable_sort(order.begin(), order.end(),
        [&hops](std::size_t x, std::size_t y) { return hops[x] > hops[y]; });
      for (std::size_t k : order)
      {
        const Index v = own[k];
        if (!this->VertexAlive[v] || hops[k] < 0)
        {
          continue;
        }
        std::vector<Index> into;
        for (Index u : this->VertexNeighbours[v])
        {
          const std::ptrdiff_t s = slot(u);
          if ((hops[k] == 1 && isAttached(u)) || (s >= 0 && hops[s] >= 0 && hops[s] < hops[k]))
          {
            into.push_back(u);
          }
        }
        for (Index keep : into)
        {
          if (!this->VertexAlive[keep])
          {
            continue;
          }
          auto& scratch = this->Scratch;
          scratch.EulerNeutral = false;
          scratch.FoldsBeforeA = scratch.FoldsBeforeB = -1;
          scratch.MergedFaces = scratch.EulerNeutralMerges = 0;
          const bool guarded =
            this->NumberAlive <= this->Options.TopologyGuardVertexCount && !this->Relaxed;
          if (guarded && !this->LinkConditionHolds(keep, v, scratch))
          {
            continue;
          }
          const Sphere target = this->Spheres[keep];
          this->IgnorePolicyBound = true;
          const bool valid = this->CollapseIsValid(keep, v, target, scratch);
          this->IgnorePolicyBound = false;
          if (!valid)
          {
            continue;
          }
          this->ApplyCollapse(keep, v, target, scratch);
          --this->NumberAlive;
          ++this->Counts.Collapses;
          ++this->Counts.FinCollapses;
          this->Counts.MergedFaces += scratch.MergedFaces;
          this->Counts.EulerNeutralCollapses += scratch.EulerNeutral ? 1 : 0;
          this->Counts.EulerNeutralMerges += scratch.EulerNeutralMerges;
          touched.push_back(keep);
          ++collapsed;
          break;
        }
      }
    }
    if (collapsed == before)
    {
      break;
    }
  }
  // The edges around what stayed are queued again at their new costs.
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (Index v : touched)
  {
    if (!this->VertexAlive[v])
    {
      continue;
    }
    for (Index u : this->VertexNeighbours[v])
    {
      Candidate c = this->MakeCandidate(v, u, this->Scratch);
      if (c.Cost < HUGE_VAL)
      {
        this->Queue.Push(c);
      }
    }
  }
  return collapsed;
}
}
