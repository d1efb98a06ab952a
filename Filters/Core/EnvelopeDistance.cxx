// SPDX-License-Identifier: GPL-3.0-or-later
#include "EnvelopeDistance.h"

#include "Vec3.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

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
      this->ActiveBoxes.push_back(BallBox(mesh.Centers[v], mesh.Radii[v]));
      maxRadius.push_back(mesh.Radii[v]);
    }
  }
  for (std::size_t e = 0; e < this->Edges.size(); ++e)
  {
    const ConePrimitive& c = this->ConeList[e];
    Box b = BallBox(c.C[0], c.R[0]);
    b.Extend(BallBox(c.C[1], c.R[1]));
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
      b.Extend(BallBox(s.C[i], s.R[i]));
    }
    this->Active.push_back({ PrimitiveKind::Slab, static_cast<Index>(f) });
    this->ActiveBoxes.push_back(b);
    maxRadius.push_back(std::max({ s.R[0], s.R[1], s.R[2] }));
  }
  for (const Box& b : this->ActiveBoxes)
  {
    this->UnionBounds.Extend(b);
  }
  this->Tol = 1e-10 * this->Diagonal();
  if (this->Accelerate)
  {
    this->Tree.Build(this->ActiveBoxes, &maxRadius);
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

double MedialEnvelope::ActiveDistance(
  std::uint32_t active, const Point3& p, PrimitiveDistance& out) const
{
  const PrimitiveRef& ref = this->Active[active];
  switch (ref.Kind)
  {
    case PrimitiveKind::Sphere:
      out = SphereDistance(this->SphereList[ref.Id], p);
      break;
    case PrimitiveKind::Cone:
      out = ConeDistance(this->ConeList[ref.Id], p);
      break;
    default:
      out = SlabInteriorDistance(this->SlabList[ref.Id], p);
      break;
  }
  return out.Distance;
}

namespace
{
// Lower bound of the signed distance of any primitive below a node: the
// distance to its box outside it, minus the largest radius inside it (no
// primitive is deeper than its largest ball).
struct SignedBound
{
  const Point3& P;
  double operator()(const BoxTree::Node& n) const
  {
    const double d2 = SquaredDistanceToBox(this->P, n.Bounds);
    return d2 > 0.0 ? std::sqrt(d2) : -n.Value;
  }
};
}

MedialEnvelope::Nearest MedialEnvelope::SignedDistance(const Point3& p) const
{
  Nearest best;
  best.Distance = Infinity;
  std::uint32_t bestItem = std::numeric_limits<std::uint32_t>::max();
  PrimitiveDistance d;
  auto visit = [&](std::uint32_t item)
  {
    const double v = this->ActiveDistance(item, p, d);
    // Ties go to the lowest index, as in the brute-force loop.
    if (v < best.Distance || (v == best.Distance && item < bestItem))
    {
      best.Distance = v;
      best.Normal = d.Normal;
      bestItem = item;
    }
    return false;
  };
  if (this->Accelerate)
  {
    this->Tree.Search(SignedBound{ p }, visit, best.Distance);
  }
  else
  {
    for (std::uint32_t i = 0; i < this->Active.size(); ++i)
    {
      visit(i);
    }
  }
  if (bestItem != std::numeric_limits<std::uint32_t>::max())
  {
    best.Primitive = this->Active[bestItem];
  }
  return best;
}

bool MedialEnvelope::StrictlyInside(const Point3& p, double tolerance) const
{
  const double cutoff = -tolerance;
  bool found = false;
  PrimitiveDistance d;
  auto visit = [&](std::uint32_t item)
  {
    found = this->ActiveDistance(item, p, d) < cutoff;
    return found;
  };
  if (this->Accelerate)
  {
    this->Tree.Search(SignedBound{ p }, visit, cutoff);
  }
  else
  {
    for (std::uint32_t i = 0; i < this->Active.size() && !visit(i); ++i)
    {
    }
  }
  return found;
}

void MedialEnvelope::Containing(
  const Point3& p, std::vector<std::pair<double, std::uint32_t>>& out) const
{
  out.clear();
  const double cutoff = 0.0;
  PrimitiveDistance d;
  auto visit = [&](std::uint32_t item)
  {
    const double v = this->ActiveDistance(item, p, d);
    if (v < 0.0)
    {
      out.emplace_back(v, item);
    }
    return false;
  };
  if (this->Accelerate)
  {
    this->Tree.Search(SignedBound{ p }, visit, cutoff);
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
  const Point3& p, const Point3* hint) const
{
  const Nearest nearest = this->SignedDistance(p);
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
