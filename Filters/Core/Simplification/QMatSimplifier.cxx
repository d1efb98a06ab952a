// SPDX-License-Identifier: GPL-3.0-or-later
#include "Simplification/QMatSimplifier.h"

#include "Geometry/Vec3.h"
#include "Mesh/MedialPrimitives.h"
#include "Simplification/EdgeCollapse.h"
#include "Simplification/SphereQuadric.h"
#include "Support/Prefetch.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace medialaxis
{
namespace
{
// SQE term of one plane tangent to sphere (c, r) with outward unit normal n
// (Eq. 1): the squared distance of a variable sphere to it, n.x + r_x = n.c + r.
void AddTangentPlane(SphereQuadric& q, const Point3& n, const Point3& c, double r, double weight)
{
  q.AddFacet(n, Dot(n, c) + r, weight);
}

// A medial cone's SQE: two slabs of four tangent planes, a quarter turn
// apart around the axis (the sum does not depend on which four).
void AddCone(SphereQuadric& q, const ConePrimitive& cone)
{
  for (const Point3& radial : { cone.Perp1, -1.0 * cone.Perp1, cone.Perp2, -1.0 * cone.Perp2 })
  {
    AddTangentPlane(q, cone.SinPhi * cone.Axis + cone.CosPhi * radial, cone.C[0], cone.R[0], 1.0);
  }
}

class QMatPolicy final : public CollapsePolicy
{
public:
  QMatPolicy(const AtlasMedialMesh& input, const QMatSimplifierOptions& options);

  const Normalisation& Frame() const { return this->UnitFrame; }
  Evaluation Evaluate(
    const MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch) const override;
  std::array<Sphere, 3> FallbackSpheres(
    const MedialEdgeCollapse& mesh, Index a, Index b) const override;
  void Merged(MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch) override;
  void Prefetch(Index v) const override { PrefetchObject(&this->Quadric[v]); }
  AtlasMedialMesh Output(const MedialEdgeCollapse& mesh) const;

  std::size_t FacesWithoutTangentPlanes = 0, NestedCones = 0;

private:
  void AddQuadrics(const MedialMesh& unit);
  void AddBoundaryPlanes(const MedialMesh& unit);

  const QMatSimplifierOptions& Options;
  Normalisation UnitFrame;
  std::vector<SphereQuadric> Quadric; // per vertex
  bool HasAtlas = false;
  std::vector<std::vector<Index>> Atlas;
};

QMatPolicy::QMatPolicy(const AtlasMedialMesh& input, const QMatSimplifierOptions& options)
  : Options(options)
{
  // Unit bounding-box diagonal of the union of the balls (the shape).
  const MedialMesh& mesh = input.Mesh;
  const std::size_t nv = mesh.Centers.size();
  Point3 lo{ HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (std::size_t v = 0; v < nv; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], mesh.Centers[v][k] - mesh.Radii[v]);
      hi[k] = std::max(hi[k], mesh.Centers[v][k] + mesh.Radii[v]);
    }
  }
  const double diagonal = nv > 0 ? Norm(hi - lo) : 0.0;
  this->UnitFrame.Origin = nv > 0 ? lo : Point3{ 0, 0, 0 };
  this->UnitFrame.Scale = diagonal > 0.0 ? 1.0 / diagonal : 1.0;

  MedialMesh unit;
  unit.Centers.resize(nv);
  unit.Radii.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    unit.Centers[v] = this->UnitFrame.To(mesh.Centers[v]);
    unit.Radii[v] = mesh.Radii[v] * this->UnitFrame.Scale;
  }
  unit.Edges = mesh.Edges;
  unit.Faces = mesh.Faces;
  this->Quadric.assign(nv, SphereQuadric());
  this->AddQuadrics(unit);
  if (this->Options.BoundaryWeight > 0.0)
  {
    this->AddBoundaryPlanes(unit);
  }

  this->HasAtlas = input.AtlasOffsets.size() == nv + 1;
  if (this->HasAtlas)
  {
    this->Atlas.resize(nv);
    for (std::size_t v = 0; v < nv; ++v)
    {
      this->Atlas[v].assign(input.AtlasSites.begin() + input.AtlasOffsets[v],
        input.AtlasSites.begin() + input.AtlasOffsets[v + 1]);
      std::sort(this->Atlas[v].begin(), this->Atlas[v].end());
      this->Atlas[v].erase(
        std::unique(this->Atlas[v].begin(), this->Atlas[v].end()), this->Atlas[v].end());
    }
  }
}

// Eq. 4: each vertex sums the SQE of its slabs (both tangent planes of each
// face) and of its cones (edges in no face). A face whose balls have no
// common tangent planes is the union of its edge cones: those stand in.
void QMatPolicy::AddQuadrics(const MedialMesh& unit)
{
  std::vector<std::array<Index, 2>> faceEdges;
  for (const auto& t : unit.Faces)
  {
    const SlabPrimitive slab =
      MakeSlab({ unit.Centers[t[0]], unit.Centers[t[1]], unit.Centers[t[2]] },
        { unit.Radii[t[0]], unit.Radii[t[1]], unit.Radii[t[2]] });
    for (int k = 0; k < 3; ++k)
    {
      faceEdges.push_back({ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) });
    }
    SphereQuadric q;
    if (slab.HasTangentPlanes)
    {
      for (int s = 0; s < 2; ++s)
      {
        q.AddFacet(slab.Normals[s], slab.Offsets[s], 1.0);
      }
    }
    else
    {
      ++this->FacesWithoutTangentPlanes;
      for (const ConePrimitive& cone : slab.Edges)
      {
        if (!cone.Nested)
        {
          AddCone(q, cone);
        }
      }
    }
    for (Index v : t)
    {
      this->Quadric[v] += q;
    }
  }
  std::sort(faceEdges.begin(), faceEdges.end());
  for (const auto& e : unit.Edges)
  {
    const std::array<Index, 2> key{ std::min(e[0], e[1]), std::max(e[0], e[1]) };
    if (key[0] == key[1] || std::binary_search(faceEdges.begin(), faceEdges.end(), key))
    {
      continue;
    }
    const ConePrimitive cone =
      MakeCone(unit.Centers[key[0]], unit.Radii[key[0]], unit.Centers[key[1]], unit.Radii[key[1]]);
    if (cone.Nested)
    {
      ++this->NestedCones;
      continue;
    }
    SphereQuadric q;
    AddCone(q, cone);
    this->Quadric[key[0]] += q;
    this->Quadric[key[1]] += q;
  }
}

// Section 4.4: soft planes, weighted k0 x stability ratio^2, against the
// shrinking of (1) a boundary vertex with a single edge and no face (the
// plane tangent to its ball, orthogonal to the edge) and (2) an edge of
// exactly one face (the plane tangent to its cone, orthogonal to the face).
void QMatPolicy::AddBoundaryPlanes(const MedialMesh& unit)
{
  const std::size_t nv = unit.Centers.size();
  std::vector<std::vector<Index>> neighbours(nv);
  std::vector<char> inFace(nv, 0);
  std::vector<std::pair<std::array<Index, 2>, Index>> edgeApex; // edge of a face, third vertex
  auto link = [&neighbours](Index a, Index b)
  {
    if (a != b)
    {
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  };
  for (const auto& e : unit.Edges)
  {
    link(e[0], e[1]);
  }
  for (const auto& t : unit.Faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = t[k], b = t[(k + 1) % 3];
      link(a, b);
      inFace[a] = 1;
      edgeApex.push_back({ { std::min(a, b), std::max(a, b) }, t[(k + 2) % 3] });
    }
  }
  for (auto& n : neighbours)
  {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  const double k0 = this->Options.BoundaryWeight;
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (inFace[v] || neighbours[v].size() != 1)
    {
      continue;
    }
    const Index u = neighbours[v][0];
    const Point3 axis = unit.Centers[v] - unit.Centers[u];
    if (!(Norm(axis) > 0.0))
    {
      continue;
    }
    const double gamma =
      StabilityRatio(unit.Centers[v], unit.Radii[v], unit.Centers[u], unit.Radii[u]);
    AddTangentPlane(
      this->Quadric[v], Normalized(axis), unit.Centers[v], unit.Radii[v], k0 * gamma * gamma);
  }
  std::sort(edgeApex.begin(), edgeApex.end());
  for (std::size_t i = 0; i < edgeApex.size();)
  {
    std::size_t j = i + 1;
    while (j < edgeApex.size() && edgeApex[j].first == edgeApex[i].first)
    {
      ++j;
    }
    if (j - i == 1)
    {
      const Index a = edgeApex[i].first[0], b = edgeApex[i].first[1], x = edgeApex[i].second;
      const ConePrimitive cone =
        MakeCone(unit.Centers[a], unit.Radii[a], unit.Centers[b], unit.Radii[b]);
      // In the face's plane, orthogonal to the edge, away from the apex.
      const Point3 toApex = unit.Centers[x] - unit.Centers[a];
      const Point3 across = toApex - Dot(toApex, cone.Axis) * cone.Axis;
      if (!cone.Nested && Norm(across) > 0.0)
      {
        const Point3 n = cone.SinPhi * cone.Axis - cone.CosPhi * Normalized(across);
        const double gamma =
          StabilityRatio(unit.Centers[a], unit.Radii[a], unit.Centers[b], unit.Radii[b]);
        for (Index v : { a, b })
        {
          AddTangentPlane(this->Quadric[v], n, cone.C[0], cone.R[0], k0 * gamma * gamma);
        }
      }
    }
    i = j;
  }
}

// Eq. 5-8: the merged sphere minimises the summed SQE of both ends (best of
// the ends and the midpoint when the system is singular or the radius comes
// out negative); cost (E + k) x stability ratio^2.
CollapsePolicy::Evaluation QMatPolicy::Evaluate(
  const MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch&) const
{
  SphereQuadric q = this->Quadric[a];
  q += this->Quadric[b];
  Evaluation best;
  double energy = HUGE_VAL;
  Eigen::Vector4d x;
  const double gamma = mesh.StabilityRatio(a, b);
  if (gamma < this->Options.SpikeRatio)
  {
    // A spike: the smaller ball lies almost inside the bigger one, so the
    // shape keeps its extent when the edge merges into the bigger ball;
    // the SQE minimiser is ill-defined along a spike (every ball inscribed
    // in its wedge fits) and may move the tip anywhere along it.
    best.Target = mesh.SphereOf(a)[3] >= mesh.SphereOf(b)[3] ? mesh.SphereOf(a) : mesh.SphereOf(b);
    energy = q.Evaluate(best.Target);
  }
  else if (SolveQuadric<4>(q, x) && x[3] >= 0.0)
  {
    best.Target = { x[0], x[1], x[2], x[3] };
    energy = q.Evaluate(best.Target);
  }
  else
  {
    best.Target = this->FallbackSpheres(mesh, a, b)[0];
    energy = q.Evaluate(best.Target);
  }
  best.Cost = (std::max(0.0, energy) + this->Options.K) * gamma * gamma;
  return best;
}

std::array<Sphere, 3> QMatPolicy::FallbackSpheres(
  const MedialEdgeCollapse& mesh, Index a, Index b) const
{
  const Sphere pa = mesh.SphereOf(a), pb = mesh.SphereOf(b);
  std::array<Sphere, 3> candidates{ pa, pb,
    Sphere{ 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2]),
      0.5 * (pa[3] + pb[3]) } };
  SphereQuadric q = this->Quadric[a];
  q += this->Quadric[b];
  double energy[3];
  for (int k = 0; k < 3; ++k)
  {
    energy[k] = q.Evaluate(candidates[k]);
  }
  std::array<int, 3> order{ 0, 1, 2 };
  std::sort(order.begin(), order.end(),
    [&energy](int x, int y) { return energy[x] != energy[y] ? energy[x] < energy[y] : x < y; });
  return { candidates[order[0]], candidates[order[1]], candidates[order[2]] };
}

// Eq. 7: the merged sphere stands for the slabs of both.
void QMatPolicy::Merged(MedialEdgeCollapse&, Index a, Index b, CollapseScratch& scratch)
{
  this->Quadric[a] += this->Quadric[b];
  if (!this->HasAtlas)
  {
    return;
  }
  auto& merged = scratch.Indices;
  merged.clear();
  std::set_union(this->Atlas[a].begin(), this->Atlas[a].end(), this->Atlas[b].begin(),
    this->Atlas[b].end(), std::back_inserter(merged));
  this->Atlas[a].swap(merged);
  std::vector<Index>().swap(this->Atlas[b]);
}

AtlasMedialMesh QMatPolicy::Output(const MedialEdgeCollapse& mesh) const
{
  AtlasMedialMesh out;
  std::vector<Index> inputId;
  out.Mesh = mesh.Output(inputId);
  out.FeatureVertex.assign(inputId.size(), 0);
  if (this->HasAtlas)
  {
    for (Index v : inputId)
    {
      out.AtlasSites.insert(out.AtlasSites.end(), this->Atlas[v].begin(), this->Atlas[v].end());
      out.AtlasOffsets.push_back(static_cast<Index>(out.AtlasSites.size()));
    }
  }
  return out;
}
} // namespace

QMatSimplifierResult SimplifyMedialAxisQMat(
  const AtlasMedialMesh& input, const QMatSimplifierOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  QMatPolicy policy(input, options);
  EdgeCollapseOptions collapse;
  collapse.TargetNumberOfVertices = options.TargetNumberOfVertices;
  collapse.MaximumCost = options.MaximumCost;
  collapse.TopologyGuardVertexCount = options.TopologyGuardVertexCount;
  collapse.StrictTopologyGuard = options.StrictTopologyGuard;
  collapse.PreventFolds = options.PreventFolds;
  collapse.SpikeThreshold = options.SpikeRatio;
  collapse.FoldTestOnSpikes = false;
  collapse.FringeCollapses = options.EulerNeutralCollapses;
  collapse.StrictLinkConditionVertexCount = 0;
  // The baseline as published: strictly one collapse at a time.
  collapse.MaximumBatch = 1;
  collapse.Progress = options.Progress;
  MedialEdgeCollapse mesh(input.Mesh, policy.Frame(), collapse, policy);
  const double setupSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const EdgeCollapseCounts counts = mesh.Run();
  QMatSimplifierResult result;
  static_cast<EdgeCollapseCounts&>(result) = counts;
  result.QueueInitialisationSeconds += setupSeconds;
  result.FacesWithoutTangentPlanes = policy.FacesWithoutTangentPlanes;
  result.NestedCones = policy.NestedCones;
  if (!counts.Aborted)
  {
    result.Medial = policy.Output(mesh);
  }
  return result;
}
}
