// SPDX-License-Identifier: GPL-3.0-or-later
// The envelope's queries: signed distance to the union, burial and
// containment tests, projection onto and distance to its boundary (the
// construction is in EnvelopeBuild.cxx).
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
