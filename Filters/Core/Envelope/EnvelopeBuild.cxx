// SPDX-License-Identifier: GPL-3.0-or-later
// The envelope's construction: its primitives from the medial mesh, the box
// tree over them and the compact per-leaf records that the searches of
// EnvelopeDistance.cxx scan.
#include "Envelope/EnvelopeDistance.h"

#include "Envelope/PrimitiveRecords.h"
#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace medialaxis
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
// Primitives per tree leaf: evaluating one (four lanes at a time) costs far
// less than a node's bound, and fewer, larger nodes mean fewer cache misses.
// Bunny at 5,000 spheres, one thread: error evaluation 1.55-1.84 s with 16
// against 1.81-2.15 s with 8, 4 much slower; with 32 against 16, the final
// fit 1.22-1.25 s against 1.30-1.32 s (13.96 against 15.95 G instructions;
// 64: 14.15 G) and the error evaluation 0.95-0.98 s against 0.99-1.27 s; at
// 20,000 spheres (two threads) the fit 5.80-6.05 s against 6.64-6.74 s.
constexpr int EnvelopeLeafSize = 32;

Box BallBox(const Point3& c, double r)
{
  Box b;
  b.Extend(Point3{ c[0] - r, c[1] - r, c[2] - r });
  b.Extend(Point3{ c[0] + r, c[1] + r, c[2] + r });
  return b;
}
}

MedialEnvelope::MedialEnvelope(const MedialMesh& mesh, bool accelerate)
  : Accelerate(accelerate)
{
  const std::size_t nv = mesh.NumberOfVertices();
  this->SphereList.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    this->SphereList[v] = { mesh.Centers[v], mesh.Radii[v] };
  }
  this->Edges = AllEdges(mesh);
  this->Faces = mesh.Faces;
  std::vector<int> degree(nv, 0);
  this->ConeList.reserve(this->Edges.size());
  for (const auto& e : this->Edges)
  {
    ++degree[e[0]];
    ++degree[e[1]];
    this->ConeList.push_back(
      MakeCone(mesh.Centers[e[0]], mesh.Radii[e[0]], mesh.Centers[e[1]], mesh.Radii[e[1]]));
  }
  this->SlabList.reserve(this->Faces.size());
  for (const auto& f : this->Faces)
  {
    this->SlabList.push_back(
      MakeSlab({ mesh.Centers[f[0]], mesh.Centers[f[1]], mesh.Centers[f[2]] },
        { mesh.Radii[f[0]], mesh.Radii[f[1]], mesh.Radii[f[2]] }));
  }

  std::vector<double> maxRadius;
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (degree[v] == 0)
    {
      this->Active.push_back({ PrimitiveKind::Sphere, static_cast<Index>(v) });
      this->ActiveBoxes.push_back(BallBox(mesh.Centers[v], 0.0));
      maxRadius.push_back(mesh.Radii[v]);
    }
  }
  for (std::size_t e = 0; e < this->Edges.size(); ++e)
  {
    const ConePrimitive& c = this->ConeList[e];
    Box b;
    b.Extend(c.C[0]);
    b.Extend(c.C[1]);
    this->Active.push_back({ PrimitiveKind::Cone, static_cast<Index>(e) });
    this->ActiveBoxes.push_back(b);
    maxRadius.push_back(std::max(c.R[0], c.R[1]));
  }
  for (std::size_t f = 0; f < this->SlabList.size(); ++f)
  {
    const SlabPrimitive& s = this->SlabList[f];
    if (!s.HasTangentPlanes)
    {
      continue;
    }
    Box b;
    for (int i = 0; i < 3; ++i)
    {
      b.Extend(s.C[i]);
    }
    this->Active.push_back({ PrimitiveKind::Slab, static_cast<Index>(f) });
    this->ActiveBoxes.push_back(b);
    maxRadius.push_back(std::max({ s.R[0], s.R[1], s.R[2] }));
  }
  // Vertex -> incident active primitives.
  std::vector<std::vector<std::uint32_t>> incident(nv);
  for (std::uint32_t a = 0; a < this->Active.size(); ++a)
  {
    const PrimitiveRef& ref = this->Active[a];
    if (ref.Kind == PrimitiveKind::Sphere)
    {
      incident[ref.Id].push_back(a);
    }
    else if (ref.Kind == PrimitiveKind::Cone)
    {
      for (Index v : this->Edges[ref.Id])
      {
        incident[v].push_back(a);
      }
    }
    else
    {
      for (Index v : this->Faces[ref.Id])
      {
        incident[v].push_back(a);
      }
    }
  }
  this->IncidentOffsets.assign(1, 0);
  for (const auto& list : incident)
  {
    this->Incident.insert(this->Incident.end(), list.begin(), list.end());
    this->IncidentOffsets.push_back(static_cast<std::uint32_t>(this->Incident.size()));
  }

  this->Records.resize(this->Active.size());
  this->Slot.resize(this->Active.size());
  for (std::uint32_t a = 0; a < this->Active.size(); ++a)
  {
    this->Slot[a] = a;
  }
  for (std::size_t a = 0; a < this->Active.size(); ++a)
  {
    // Spheres and nested cones are kind 0 (a ball: the first four fields
    // are its centre and radius), the other cones kind 1.
    Compact& k = this->Records[a];
    const PrimitiveRef& ref = this->Active[a];
    if (ref.Kind == PrimitiveKind::Slab)
    {
      records::Slab slab;
      records::MakeSlab(this->SlabList[ref.Id], slab); // active slabs have tangent planes
      k.Kind = 2;
      std::copy(slab.begin(), slab.end(), k.D);
      continue;
    }
    const records::Round round = ref.Kind == PrimitiveKind::Sphere
      ? records::MakeRound(this->SphereList[ref.Id])
      : records::MakeRound(this->ConeList[ref.Id]);
    k.Kind = ref.Kind == PrimitiveKind::Cone && !this->ConeList[ref.Id].Nested ? 1 : 0;
    std::copy(round.begin(), round.end(), k.D);
  }

  // Each primitive has two boxes: of its balls (the primitive's own box) and
  // of its centres; the hierarchy is built on the former and keeps the
  // latter per node too (see SignedBound).
  this->ActiveRadius = maxRadius;
  this->ActiveBallBoxes.resize(this->ActiveBoxes.size());
  for (std::size_t a = 0; a < this->ActiveBoxes.size(); ++a)
  {
    const Box& b = this->ActiveBoxes[a];
    const double r = maxRadius[a];
    this->ActiveBallBoxes[a].Extend(Point3{ b.Lo[0] - r, b.Lo[1] - r, b.Lo[2] - r });
    this->ActiveBallBoxes[a].Extend(Point3{ b.Hi[0] + r, b.Hi[1] + r, b.Hi[2] + r });
    this->UnionBounds.Extend(this->ActiveBallBoxes[a]);
  }
  this->Tol = 1e-10 * this->Diagonal();
  if (this->Accelerate)
  {
    this->Tree.Build(this->ActiveBallBoxes, &maxRadius, EnvelopeLeafSize);
    this->Tree.SortLeafItems(
      [&](std::uint32_t a) { return this->Active[a].Kind == PrimitiveKind::Slab ? 1 : 0; });
    std::vector<Compact> ordered(this->Records.size());
    for (std::size_t i = 0; i < ordered.size(); ++i)
    {
      const std::uint32_t a = this->Tree.GetItems()[i];
      ordered[i] = this->Records[a];
      this->Slot[a] = static_cast<std::uint32_t>(i);
    }
    this->Records.swap(ordered);
    // Children come after their parent: fill the node hulls bottom-up.
    std::vector<Dop> itemDops(this->Active.size());
    for (std::uint32_t a = 0; a < this->Active.size(); ++a)
    {
      const PrimitiveRef& ref = this->Active[a];
      if (ref.Kind == PrimitiveKind::Sphere)
      {
        itemDops[a].Extend(this->SphereList[ref.Id]);
      }
      else if (ref.Kind == PrimitiveKind::Cone)
      {
        for (Index v : this->Edges[ref.Id])
        {
          itemDops[a].Extend(this->SphereList[v]);
        }
      }
      else
      {
        for (Index v : this->Faces[ref.Id])
        {
          itemDops[a].Extend(this->SphereList[v]);
        }
      }
    }
    const auto& nodes = this->Tree.GetNodes();
    const auto& items = this->Tree.GetItems();
    this->NodeDops.assign(nodes.size(), Dop());
    for (std::size_t n = nodes.size(); n-- > 0;)
    {
      const BoxTree::Node& node = nodes[n];
      Dop& dop = this->NodeDops[n];
      if (node.Count > 0)
      {
        for (std::uint32_t i = node.Begin; i < node.Begin + node.Count; ++i)
        {
          dop.Extend(itemDops[items[i]]);
        }
      }
      else
      {
        dop.Extend(this->NodeDops[node.Begin]);
        dop.Extend(this->NodeDops[node.Begin + 1]);
      }
    }
    this->BuildSheetPlanes();
    this->BuildLeafParts();
  }
}

void MedialEnvelope::BuildLeafParts()
{
  const auto& nodes = this->Tree.GetNodes();
  const auto& items = this->Tree.GetItems();
  this->Leaves.assign(nodes.size(), LeafParts());
  for (std::size_t n = 0; n < nodes.size(); ++n)
  {
    const BoxTree::Node& node = nodes[n];
    LeafParts& parts = this->Leaves[n];
    for (std::uint32_t i = node.Begin; i < node.Begin + node.Count; ++i)
    {
      const PrimitiveRef& ref = this->Active[items[i]];
      if (ref.Kind == PrimitiveKind::Sphere)
      {
        parts.Balls.Extend(this->SphereList[ref.Id]);
        ++parts.Split;
      }
      else if (ref.Kind == PrimitiveKind::Cone)
      {
        for (Index v : this->Edges[ref.Id])
        {
          parts.Balls.Extend(this->SphereList[v]);
        }
        ++parts.Split;
      }
      else
      {
        // The centres and both tangent triangles.
        const SlabPrimitive& slab = this->SlabList[ref.Id];
        for (const Point3& c : slab.C)
        {
          parts.Regions.Extend(c);
        }
        for (int side = 0; side < 2; ++side)
        {
          for (const Point3& t : SlabTangentTriangle(slab, side))
          {
            parts.Regions.Extend(t);
          }
        }
      }
    }
  }
  this->BuildLeafBlocks();
}

void MedialEnvelope::BuildLeafBlocks()
{
  const auto& nodes = this->Tree.GetNodes();
  this->RoundBlocks.clear();
  this->SlabBlocks.clear();
  const double inf = Infinity;
  // Padding lanes, whose value is +infinity at every point: a ball of radius
  // -infinity; a slab interior with offsets -infinity.
  const double roundPadding[pairs::RoundFields] = { 0, 0, 0, -inf, 0, 0, 0, 1, 0, inf, 0, 0, 0,
    -inf };
  double slabPadding[pairs::SlabFields] = {};
  slabPadding[12] = slabPadding[13] = -inf;
  slabPadding[14] = 1.0;
  // Appends records [begin, end) as blocks of two, each record's fields
  // given by fields(position, out).
  auto append = [&](std::vector<double>& blocks, std::uint32_t begin, std::uint32_t end, int count,
                  const double* padding, auto&& fields)
  {
    double record[pairs::SlabFields];
    for (std::uint32_t i = begin; i < end; i += 2)
    {
      const std::size_t at = blocks.size();
      blocks.resize(at + 2 * count);
      for (std::uint32_t lane = 0; lane < 2; ++lane)
      {
        const double* d = padding;
        if (i + lane < end)
        {
          fields(i + lane, record);
          d = record;
        }
        for (int f = 0; f < count; ++f)
        {
          blocks[at + 2 * f + lane] = d[f];
        }
      }
    }
  };
  // (Spheres and nested cones are stored as cones with a zero axis, sin 1
  // and cos 0, which always take the C0 cap: records::MakeRound.)
  auto round = [&](std::uint32_t position, double* out)
  { std::copy_n(this->Records[position].D, pairs::RoundFields, out); };
  auto slab = [&](std::uint32_t position, double* out)
  { std::copy_n(this->Records[position].D, pairs::SlabFields, out); };
  for (std::size_t n = 0; n < nodes.size(); ++n)
  {
    const BoxTree::Node& node = nodes[n];
    LeafParts& parts = this->Leaves[n];
    if (node.Count == 0)
    {
      continue;
    }
    const std::uint32_t split = node.Begin + parts.Split, end = node.Begin + node.Count;
    parts.Round = static_cast<std::uint32_t>(this->RoundBlocks.size());
    append(this->RoundBlocks, node.Begin, split, pairs::RoundFields, roundPadding, round);
    parts.Slab = static_cast<std::uint32_t>(this->SlabBlocks.size());
    append(this->SlabBlocks, split, end, pairs::SlabFields, slabPadding, slab);
  }
}

void MedialEnvelope::BuildSheetPlanes()
{
  const auto& nodes = this->Tree.GetNodes();
  const auto& items = this->Tree.GetItems();
  // Each node covers a contiguous range of items; children follow parents.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> range(nodes.size());
  for (std::size_t n = nodes.size(); n-- > 0;)
  {
    const BoxTree::Node& node = nodes[n];
    range[n] = node.Count > 0
      ? std::make_pair(node.Begin, node.Begin + node.Count)
      : std::make_pair(range[node.Begin].first, range[node.Begin + 1].second);
  }
  auto vertices = [&](std::uint32_t active, Index out[3])
  {
    const PrimitiveRef& ref = this->Active[active];
    if (ref.Kind == PrimitiveKind::Sphere)
    {
      out[0] = ref.Id;
      return 1;
    }
    if (ref.Kind == PrimitiveKind::Cone)
    {
      std::copy_n(this->Edges[ref.Id].begin(), 2, out);
      return 2;
    }
    std::copy_n(this->Faces[ref.Id].begin(), 3, out);
    return 3;
  };
  this->NodePlanes.assign(
    nodes.size(), SheetPlanes{ { { 0, 0 }, { 0, 0 }, { 0, 0 } }, { Infinity, Infinity } });
  for (std::size_t n = 0; n < nodes.size(); ++n)
  {
    // Side normals of the slabs, each pair oriented like the first one.
    Point3 sum[2] = { { 0, 0, 0 }, { 0, 0, 0 } };
    const Point3* reference = nullptr;
    for (std::uint32_t i = range[n].first; i < range[n].second; ++i)
    {
      const PrimitiveRef& ref = this->Active[items[i]];
      if (ref.Kind != PrimitiveKind::Slab)
      {
        continue;
      }
      const SlabPrimitive& slab = this->SlabList[ref.Id];
      reference = reference ? reference : &slab.Normals[0];
      const int first = Dot(slab.Normals[0], *reference) >= 0.0 ? 0 : 1;
      sum[0] = sum[0] + slab.Normals[first];
      sum[1] = sum[1] + slab.Normals[1 - first];
    }
    SheetPlanes& planes = this->NodePlanes[n];
    for (int side = 0; side < 2 && reference; ++side)
    {
      const double length = Norm(sum[side]);
      if (!(length > 0.0))
      {
        continue;
      }
      const Point3 u = (1.0 / length) * sum[side];
      double h = -Infinity;
      for (std::uint32_t i = range[n].first; i < range[n].second; ++i)
      {
        Index v[3];
        const int count = vertices(items[i], v);
        for (int k = 0; k < count; ++k)
        {
          const SpherePrimitive& ball = this->SphereList[v[k]];
          h = std::max(h, Dot(u, ball.Center) + ball.Radius);
        }
      }
      // Rounding of u . x: a relative margin keeps the half-space containing.
      h += 1e-12 * (std::abs(h) + this->Diagonal());
      for (int c = 0; c < 3; ++c)
      {
        planes.U[c][side] = u[c];
      }
      planes.H[side] = h;
    }
  }
}
}
