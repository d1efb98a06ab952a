// SPDX-License-Identifier: GPL-3.0-or-later
#include "Envelope/EnvelopeDistance.h"

#include "Envelope/PrimitiveQuads.h"
#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
// Primitives per tree leaf: evaluating one costs less than a node's bound,
// and fewer, larger nodes mean fewer cache misses (bunny at 5,000 spheres:
// error evaluation 1.55-1.84 s with 16 against 1.81-2.15 s with 8; 24 and 32
// within noise of 16, 4 much slower).
constexpr int EnvelopeLeafSize = 16;

Box BallBox(const Point3& c, double r)
{
  Box b;
  b.Extend(Point3{ c[0] - r, c[1] - r, c[2] - r });
  b.Extend(Point3{ c[0] + r, c[1] + r, c[2] + r });
  return b;
}

// Solves the n x n (n <= 3) system g x = b by Gaussian elimination with
// partial pivoting; false when (nearly) singular.
bool SolveSmall(int n, double g[3][3], double b[3], double x[3])
{
  for (int c = 0; c < n; ++c)
  {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
    {
      if (std::abs(g[r][c]) > std::abs(g[pivot][c]))
      {
        pivot = r;
      }
    }
    if (!(std::abs(g[pivot][c]) > 1e-10))
    {
      return false;
    }
    std::swap(g[c], g[pivot]);
    std::swap(b[c], b[pivot]);
    for (int r = c + 1; r < n; ++r)
    {
      const double f = g[r][c] / g[c][c];
      for (int k = c; k < n; ++k)
      {
        g[r][k] -= f * g[c][k];
      }
      b[r] -= f * b[c];
    }
  }
  for (int r = n - 1; r >= 0; --r)
  {
    double s = b[r];
    for (int k = r + 1; k < n; ++k)
    {
      s -= g[r][k] * x[k];
    }
    x[r] = s / g[r][r];
  }
  return true;
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
    Compact& k = this->Records[a];
    double* d = k.D;
    auto store = [](double* to, const Point3& x) { std::copy(x.begin(), x.end(), to); };
    const PrimitiveRef& ref = this->Active[a];
    if (ref.Kind == PrimitiveKind::Sphere)
    {
      k.Kind = 0;
      store(d, this->SphereList[ref.Id].Center);
      d[3] = this->SphereList[ref.Id].Radius;
    }
    else if (ref.Kind == PrimitiveKind::Cone)
    {
      const ConePrimitive& cone = this->ConeList[ref.Id];
      const int big = cone.Nested ? cone.Big : 0;
      k.Kind = cone.Nested ? 0 : 1;
      store(d, cone.C[big]);
      d[3] = cone.R[big];
      store(d + 4, cone.Axis);
      d[7] = cone.SinPhi;
      d[8] = cone.CosPhi;
      d[9] = cone.Length * cone.CosPhi;
      store(d + 10, cone.C[1]);
      d[13] = cone.R[1];
    }
    else
    {
      const SlabPrimitive& slab = this->SlabList[ref.Id];
      k.Kind = 2;
      store(d, slab.C[0]);
      store(d + 3, slab.PlaneNormal);
      store(d + 6, slab.Normals[0]);
      store(d + 9, slab.Normals[1]);
      d[12] = slab.Offsets[0];
      d[13] = slab.Offsets[1];
      d[14] = slab.Gamma;
      store(d + 15, slab.E1);
      store(d + 18, slab.E2);
      d[21] = slab.InvG11;
      d[22] = slab.InvG12;
      d[23] = slab.InvG22;
    }
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
  // Spheres (and nested cones) become cones with a zero axis, sin 1 and
  // cos 0, which always take the C0 cap: the same value.
  auto round = [&](std::uint32_t position, double* out)
  {
    const Compact& k = this->Records[position];
    std::copy_n(k.D, pairs::RoundFields, out);
    if (k.Kind == 0)
    {
      const double sphere[pairs::RoundFields] = { k.D[0], k.D[1], k.D[2], k.D[3], 0, 0, 0, 1, 0,
        inf, k.D[0], k.D[1], k.D[2], k.D[3] };
      std::copy_n(sphere, pairs::RoundFields, out);
    }
  };
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

double MedialEnvelope::Diagonal() const
{
  return this->UnionBounds.IsEmpty() ? 0.0 : Norm(this->UnionBounds.Hi - this->UnionBounds.Lo);
}

PrimitiveDistance MedialEnvelope::PrimitiveSignedDistance(
  const PrimitiveRef& ref, const Point3& p) const
{
  switch (ref.Kind)
  {
    case PrimitiveKind::Sphere:
      return SphereDistance(this->SphereList[ref.Id], p);
    case PrimitiveKind::Cone:
      return ConeDistance(this->ConeList[ref.Id], p);
    default:
      return SlabDistance(this->SlabList[ref.Id], p);
  }
}

namespace
{
Point3 Load(const double* d)
{
  return { d[0], d[1], d[2] };
}
}

// The hot loop: the signed distance of one active primitive from its compact
// record (data d, kind), with the same arithmetic as SphereDistance,
// ConeDistance and SlabInteriorDistance (so the values agree bit for bit) but
// no normal. A free function so that the searches inline it.
namespace
{
inline double CompactValue(const double* d, int kind, const Point3& p)
{
  switch (kind)
  {
    case 0:
      return Norm(p - Load(d)) - d[3];
    case 1:
    {
      const Point3 c0 = Load(d), axis = Load(d + 4);
      const Point3 v = p - c0;
      const double a = Dot(v, axis);
      const Point3 w = v - a * axis;
      const double b = Norm(w);
      const double s = a * d[8] - b * d[7];
      if (s <= 0.0)
      {
        return Norm(p - c0) - d[3];
      }
      if (s >= d[9])
      {
        return Norm(p - Load(d + 10)) - d[13];
      }
      return a * d[7] + b * d[8] - d[3];
    }
    default:
    {
      const Point3 c0 = Load(d);
      const double height = Dot(p - c0, Load(d + 3));
      const int side = height >= 0.0 ? 0 : 1;
      const Point3 n = Load(d + 6 + 3 * side);
      const double t = std::abs(height) / d[14];
      const Point3 v = (p - t * n) - c0;
      const double d1 = Dot(v, Load(d + 15)), d2 = Dot(v, Load(d + 18));
      const double b1 = d[21] * d1 + d[22] * d2;
      const double b2 = d[22] * d1 + d[23] * d2;
      if (b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0)
      {
        return Infinity;
      }
      return Dot(n, p) - d[12 + side];
    }
  }
}
}

PrimitiveRef MedialEnvelope::BuryingPrimitive(std::uint32_t handle) const
{
  // Handles are positions in the tree's item order (see FindBurying).
  return this->Active[this->Accelerate ? this->Tree.GetItems()[handle] : handle];
}

int MedialEnvelope::MedialVertices(const PrimitiveRef& ref, Index vertices[3]) const
{
  switch (ref.Kind)
  {
    case PrimitiveKind::Sphere:
      vertices[0] = ref.Id;
      return 1;
    case PrimitiveKind::Cone:
      vertices[0] = this->Edges[ref.Id][0];
      vertices[1] = this->Edges[ref.Id][1];
      return 2;
    default:
      std::copy_n(this->Faces[ref.Id].begin(), 3, vertices);
      return 3;
  }
}

double MedialEnvelope::ActiveValue(std::uint32_t active, const Point3& p) const
{
  const Compact& k = this->Records[this->Slot[active]];
  return CompactValue(k.D, k.Kind, p);
}

PrimitiveDistance MedialEnvelope::ActiveDistance(std::uint32_t active, const Point3& p) const
{
  const PrimitiveRef& ref = this->Active[active];
  switch (ref.Kind)
  {
    case PrimitiveKind::Sphere:
      return SphereDistance(this->SphereList[ref.Id], p);
    case PrimitiveKind::Cone:
      return ConeDistance(this->ConeList[ref.Id], p);
    default:
      return SlabInteriorDistance(this->SlabList[ref.Id], p);
  }
}

namespace
{
// Lower bound, for every node, of the signed distance of the primitives below
// it: the signed distance to the 26-sided hull of their balls.
struct SignedBound
{
  const BoxTree::Node* First;
  const MedialEnvelope::Dop* Dops;
  const MedialEnvelope::SheetPlanes* Planes;
  pairs::Query P;
  double T[MedialEnvelope::Dop::K];
  SignedBound(const Point3& p, const BoxTree::Node* first, const MedialEnvelope::Dop* dops,
    const MedialEnvelope::SheetPlanes* planes)
    : First(first)
    , Dops(dops)
    , Planes(planes)
    , P(p.data())
  {
    MedialEnvelope::Dop::Project(p, this->T);
  }
  double operator()(const BoxTree::Node& n) const
  {
    const std::size_t i = &n - this->First;
    const MedialEnvelope::SheetPlanes& planes = this->Planes[i];
    // Both sides' plane values at once, in the scalar order of operations.
    const pairs::Lanes sides = pairs::Load(planes.U[0]) * this->P.X +
      pairs::Load(planes.U[1]) * this->P.Y + pairs::Load(planes.U[2]) * this->P.Z -
      pairs::Load(planes.H);
    const MedialEnvelope::Dop& dop = this->Dops[i];
    return pairs::Largest(
      pairs::Max(pairs::HullBound<MedialEnvelope::Dop::K>(this->T, dop.Lo, dop.Hi), sides));
  }
};
}

namespace
{
// Four lanes where the processor has them (PrimitiveQuads.h), chosen once.
const quads::BlockValues RoundQuads = quads::RoundBlockValues();
const quads::BlockValues SlabQuads = quads::SlabBlockValues();

// Values of the records [begin, end) stored in blocks of two from `block`
// on, in order, as visit(position, value); true when visit stopped it.
// With `quads`, up to eight blocks are evaluated at a time, four lanes wide.
template <int Fields, typename Values, typename Visit>
bool ScanBlocks(const double* block, std::uint32_t begin, std::uint32_t end,
  const pairs::Query& query, quads::BlockValues quads, Values&& pairValues, Visit&& visit)
{
  if (quads != nullptr)
  {
    constexpr std::uint32_t Chunk = 16; // records
    double values[Chunk];
    for (std::uint32_t first = begin; first < end; first += Chunk, block += Chunk * Fields)
    {
      const std::uint32_t last = std::min(end, first + Chunk);
      quads(block, static_cast<int>((last - first + 1) / 2), query.Point, values);
      for (std::uint32_t i = first; i < last; ++i)
      {
        if (visit(i, values[i - first]))
        {
          return true;
        }
      }
    }
    return false;
  }
  for (std::uint32_t i = begin; i < end; i += 2, block += 2 * Fields)
  {
    double values[2];
    pairValues(block, query, values);
    if (visit(i, values[0]) || (i + 1 < end && visit(i + 1, values[1])))
    {
      return true;
    }
  }
  return false;
}
}

template <typename Visit>
bool MedialEnvelope::ScanRound(const LeafParts& parts, std::uint32_t begin, std::uint32_t end,
  const pairs::Query& query, Visit&& visit) const
{
  return ScanBlocks<pairs::RoundFields>(
    this->RoundBlocks.data() + parts.Round, begin, end, query, RoundQuads,
    [](const double* block, const pairs::Query& q, double* out)
    { pairs::RoundValues(block, q, out); },
    visit);
}

template <typename Visit>
bool MedialEnvelope::ScanSlabs(const LeafParts& parts, std::uint32_t begin, std::uint32_t end,
  const pairs::Query& query, Visit&& visit) const
{
  return ScanBlocks<pairs::SlabFields>(
    this->SlabBlocks.data() + parts.Slab, begin, end, query, SlabQuads,
    [](const double* block, const pairs::Query& q, double* out)
    { pairs::SlabValues(block, q, out); },
    visit);
}

MedialEnvelope::Nearest MedialEnvelope::SignedDistance(const Point3& p, std::uint32_t* warm) const
{
  Nearest best;
  best.Distance = Infinity;
  std::uint32_t bestItem = std::numeric_limits<std::uint32_t>::max();
  if (this->Accelerate)
  {
    // Records are in the tree's item order: visit by position.
    const Compact* records = this->Records.data();
    const std::uint32_t* items = this->Tree.GetItems().data();
    std::uint32_t bestPosition = NoPrimitive;
    if (warm && *warm < this->Records.size())
    {
      bestPosition = *warm;
      best.Distance = CompactValue(records[bestPosition].D, records[bestPosition].Kind, p);
      bestItem = items[bestPosition];
    }
    const BoxTree::Node* first = this->Tree.GetNodes().data();
    const SignedBound bound(p, first, this->NodeDops.data(), this->NodePlanes.data());
    const pairs::Query query(p.data());
    auto keep = [&](std::uint32_t position, double v)
    {
      // Ties go to the lowest index, as in the brute-force loop.
      if (v < best.Distance || (v == best.Distance && items[position] < bestItem))
      {
        best.Distance = v;
        bestItem = items[position];
        bestPosition = position;
      }
      return false;
    };
    this->Tree.SearchLeaves(
      bound,
      [&](const BoxTree::Node& leaf)
      {
        const LeafParts& parts = this->Leaves[&leaf - first];
        const std::uint32_t split = leaf.Begin + parts.Split, end = leaf.Begin + leaf.Count;
        if (split > leaf.Begin && parts.Balls.Bound(bound.T) < best.Distance)
        {
          this->ScanRound(parts, leaf.Begin, split, query, keep);
        }
        // Outside the hull of the slab interiors' regions, their values are
        // at least the distance to it (the hull bound); inside it, a value
        // can be anything below 0, so they are evaluated.
        const double regions = parts.Regions.Bound(bound.T);
        if (end > split && !(regions > 0.0 && regions >= best.Distance))
        {
          this->ScanSlabs(parts, split, end, query, keep);
        }
        return false;
      },
      best.Distance);
    if (warm)
    {
      *warm = bestPosition;
    }
  }
  else
  {
    for (std::uint32_t i = 0; i < this->Active.size(); ++i)
    {
      const double v = this->ActiveValue(i, p);
      if (v < best.Distance || (v == best.Distance && i < bestItem))
      {
        best.Distance = v;
        bestItem = i;
      }
    }
  }
  if (bestItem != std::numeric_limits<std::uint32_t>::max())
  {
    best.Primitive = this->Active[bestItem];
    best.Normal = this->ActiveDistance(bestItem, p).Normal;
  }
  return best;
}

template <typename Visit>
void MedialEnvelope::SearchBurial(const Point3& p, double tolerance, Visit&& visit) const
{
  const double cutoff = -tolerance;
  const BoxTree::Node* first = this->Tree.GetNodes().data();
  const SignedBound bound(p, first, this->NodeDops.data(), this->NodePlanes.data());
  const pairs::Query query(p.data());
  this->Tree.SearchLeaves(
    bound,
    [&](const BoxTree::Node& leaf)
    {
      const LeafParts& parts = this->Leaves[&leaf - first];
      const std::uint32_t split = leaf.Begin + parts.Split, end = leaf.Begin + leaf.Count;
      // A point strictly buried by a slab interior is in its region, maybe
      // within rounding of the region's side: hence +tolerance.
      return (split > leaf.Begin && parts.Balls.Bound(bound.T) < cutoff &&
               this->ScanRound(parts, leaf.Begin, split, query, visit)) ||
        (end > split && parts.Regions.Bound(bound.T) < tolerance &&
          this->ScanSlabs(parts, split, end, query, visit));
    },
    cutoff);
}

bool MedialEnvelope::StrictlyInside(const Point3& p, double tolerance) const
{
  const double cutoff = -tolerance;
  bool found = false;
  if (this->Accelerate)
  {
    this->SearchBurial(p, tolerance,
      [&](std::uint32_t, double value)
      {
        found = value < cutoff;
        return found;
      });
  }
  else
  {
    for (std::uint32_t i = 0; i < this->Active.size() && !found; ++i)
    {
      found = this->ActiveValue(i, p) < cutoff;
    }
  }
  return found;
}

bool MedialEnvelope::StrictlyInside(
  const Point3& p, double tolerance, const Index* vertices, int count) const
{
  for (int i = 0; i < count; ++i)
  {
    for (std::uint32_t k = this->IncidentOffsets[vertices[i]];
         k < this->IncidentOffsets[vertices[i] + 1]; ++k)
    {
      const Compact& record = this->Records[this->Slot[this->Incident[k]]];
      if (CompactValue(record.D, record.Kind, p) < -tolerance)
      {
        return true;
      }
    }
  }
  return this->StrictlyInside(p, tolerance);
}

std::uint32_t MedialEnvelope::FindBurying(const Point3& p, double tolerance, const Index* vertices,
  int count, std::uint32_t hint, std::size_t maxItems) const
{
  const double cutoff = -tolerance;
  const Compact* records = this->Records.data();
  auto buries = [&](std::uint32_t slot)
  { return CompactValue(records[slot].D, records[slot].Kind, p) < cutoff; };
  if (hint != NoBurial && buries(hint))
  {
    return hint;
  }
  for (int i = 0; i < count; ++i)
  {
    for (std::uint32_t k = this->IncidentOffsets[vertices[i]];
         k < this->IncidentOffsets[vertices[i] + 1]; ++k)
    {
      const std::uint32_t slot = this->Slot[this->Incident[k]];
      if (buries(slot))
      {
        return slot;
      }
    }
  }
  std::uint32_t found = NoBurial;
  if (this->Accelerate)
  {
    std::size_t evaluated = 0;
    this->SearchBurial(p, tolerance,
      [&](std::uint32_t position, double value)
      {
        if (value < cutoff)
        {
          found = position;
          return true;
        }
        return ++evaluated >= maxItems;
      });
  }
  else
  {
    for (std::uint32_t slot = 0; slot < this->Records.size() && found == NoBurial; ++slot)
    {
      found = buries(slot) ? slot : NoBurial;
    }
  }
  return found;
}

void MedialEnvelope::Containing(
  const Point3& p, std::vector<std::pair<double, std::uint32_t>>& out) const
{
  out.clear();
  const double cutoff = 0.0;
  auto visit = [&](std::uint32_t item)
  {
    const double v = this->ActiveValue(item, p);
    if (v < 0.0)
    {
      out.emplace_back(v, item);
    }
    return false;
  };
  if (this->Accelerate)
  {
    this->Tree.Search(
      SignedBound(p, this->Tree.GetNodes().data(), this->NodeDops.data(), this->NodePlanes.data()),
      visit, cutoff);
  }
  else
  {
    for (std::uint32_t i = 0; i < this->Active.size(); ++i)
    {
      visit(i);
    }
  }
  std::sort(out.begin(), out.end());
}

// Closest point to p on the intersection of the boundaries of an active set
// of up to three primitives, starting with {start}: Gauss-Newton steps on
// the linearised constraints f_a(x) + n_a . (y - x) = 0 with y = p + sum c_a
// n_a (the Lagrange form of the closest point; linear convergence, at a rate
// set by the curvature of the primitives relative to the distance). When the
// converged point is strictly inside another primitive, that primitive joins
// the set. Returns the distance from p to the nearest point reached that lies
// outside the open union (infinity if none): an upper bound of the distance
// from p to the union's boundary whether or not the iteration converged.
double MedialEnvelope::ProjectOntoBoundary(const Point3& p, std::uint32_t start) const
{
  PrimitiveRef active[3] = { this->Active[start] };
  int count = 1;
  const PrimitiveDistance d0 = this->PrimitiveSignedDistance(active[0], p);
  Point3 x = p - d0.Distance * d0.Normal;
  const double stepTolerance = 1e-9 * this->Diagonal();
  double best = Infinity;
  for (int iteration = 0; iteration < 200; ++iteration)
  {
    PrimitiveDistance pd[3];
    for (int a = 0; a < count; ++a)
    {
      pd[a] = this->PrimitiveSignedDistance(active[a], x);
    }
    double g[3][3], b[3], c[3];
    for (int a = 0; a < count; ++a)
    {
      for (int k = 0; k < count; ++k)
      {
        g[a][k] = Dot(pd[a].Normal, pd[k].Normal);
      }
      b[a] = Dot(pd[a].Normal, x - p) - pd[a].Distance;
    }
    if (!SolveSmall(count, g, b, c))
    {
      break;
    }
    Point3 y = p;
    for (int a = 0; a < count; ++a)
    {
      y = y + c[a] * pd[a].Normal;
    }
    const double step = Norm(y - x);
    x = y;
    if (step > stepTolerance && iteration + 1 < 200)
    {
      continue;
    }
    const Nearest n = this->SignedDistance(x);
    if (n.Distance >= -this->Tol)
    {
      best = std::min(best, Norm(x - p));
      break;
    }
    bool known = count == 3;
    for (int a = 0; a < count; ++a)
    {
      known = known || (active[a].Kind == n.Primitive.Kind && active[a].Id == n.Primitive.Id);
    }
    if (known)
    {
      break;
    }
    active[count++] = n.Primitive;
  }
  return best;
}

// Sphere tracing from p (inside U) along a unit direction: each step of -F
// stays inside U, and the trace stops where F >= -tolerance. Returns the
// distance travelled, or infinity beyond `limit` or without convergence.
double MedialEnvelope::TraceExit(const Point3& p, const Point3& direction, double limit) const
{
  double t = 0.0;
  for (int iteration = 0; iteration < 400; ++iteration)
  {
    const double f = this->SignedDistance(p + t * direction).Distance;
    if (f >= -this->Tol)
    {
      return t;
    }
    t -= f;
    if (t >= limit)
    {
      return Infinity;
    }
  }
  return Infinity;
}

MedialEnvelope::BoundaryDistance MedialEnvelope::DistanceToBoundary(
  const Point3& p, const Point3* hint, std::uint32_t* warm) const
{
  const Nearest nearest = this->SignedDistance(p, warm);
  if (nearest.Distance >= 0.0)
  {
    return { nearest.Distance, nearest.Distance, nearest.Distance, false, true };
  }
  const double lower = -nearest.Distance;
  // 1. The deepest primitive's own closest boundary point, when exposed.
  const Point3 x = p + lower * nearest.Normal;
  if (!this->StrictlyInside(x, this->Tol))
  {
    return { -lower, lower, lower, true, true };
  }
  // 2. A crease or corner: candidate boundary points, each checked exposed.
  double upper = Infinity;
  std::vector<std::pair<double, std::uint32_t>> containing;
  this->Containing(p, containing);
  const std::size_t starts = std::min<std::size_t>(containing.size(), 4);
  for (std::size_t i = 0; i < starts; ++i)
  {
    upper = std::min(upper, this->ProjectOntoBoundary(p, containing[i].second));
  }
  Point3 directions[2] = { nearest.Normal, nearest.Normal };
  int nd = 1;
  if (hint)
  {
    const Point3 h = Normalized(*hint);
    if (Dot(h, h) > 0.0)
    {
      directions[nd++] = h;
    }
  }
  for (int i = 0; i < nd; ++i)
  {
    upper = std::min(upper, this->TraceExit(p, directions[i], upper));
  }
  if (!(upper < Infinity))
  {
    // Leaving the union's bounding box always exits U.
    double exit = Infinity;
    for (int k = 0; k < 3; ++k)
    {
      exit = std::min({ exit, p[k] - this->UnionBounds.Lo[k], this->UnionBounds.Hi[k] - p[k] });
    }
    upper = std::max(exit, 0.0);
  }
  upper = std::max(upper, lower);
  return { -upper, lower, upper, true, upper - lower <= 2.0 * this->Tol };
}
}
