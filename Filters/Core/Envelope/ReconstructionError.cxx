// SPDX-License-Identifier: GPL-3.0-or-later
#include "Envelope/ReconstructionError.h"

#include "Envelope/EnvelopeMaximum.h"

#include "Geometry/KdTree.h"
#include "Geometry/MortonOrder.h"
#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Support/Random.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace medialaxis
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr std::size_t Chunk = 16384;

// The generator of sample k: independent of how samples are split over threads.
Random SampleRandom(std::uint64_t seed, std::size_t k)
{
  return Random(seed ^ (0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(k) + 1)));
}

// Index of the item whose cumulative range holds u in [0, total).
std::size_t PickFromCdf(const std::vector<double>& cdf, double u)
{
  const auto it = std::upper_bound(cdf.begin(), cdf.end(), u * cdf.back());
  return std::min<std::size_t>(static_cast<std::size_t>(it - cdf.begin()), cdf.size() - 1);
}

// PickFromCdf with a guide table: bucket j of equal width remembers where
// its values start, so that a pick reads a few entries instead of binary
// searching a long cumulative array (cache misses on ~1M pieces). The range
// found is checked and the plain search used if rounding put the value in a
// neighbouring bucket, so picks are identical to PickFromCdf's.
class GuidedCdf
{
public:
  void Build(std::vector<double> cdf)
  {
    this->Cdf = std::move(cdf);
    const std::size_t buckets = std::max<std::size_t>(this->Cdf.size(), 1);
    this->Scale = this->Cdf.empty() ? 0.0 : double(buckets) / this->Cdf.back();
    this->Guide.resize(buckets + 1);
    std::size_t i = 0;
    for (std::size_t j = 0; j <= buckets; ++j)
    {
      const double start = this->Cdf.empty() ? 0.0 : double(j) / this->Scale;
      while (i < this->Cdf.size() && this->Cdf[i] <= start)
      {
        ++i;
      }
      this->Guide[j] = static_cast<std::uint32_t>(i);
    }
  }
  bool Empty() const { return this->Cdf.empty(); }
  double Total() const { return this->Cdf.empty() ? 0.0 : this->Cdf.back(); }
  /// Pick(u) for u >= the value that gave `from`: a walk forward, for
  /// increasing values (reads neighbouring entries instead of searching).
  std::size_t PickFrom(double u, std::size_t from) const
  {
    const double v = u * this->Cdf.back();
    if (from > 0 && this->Cdf[from - 1] > v)
    {
      return this->Pick(u);
    }
    while (from + 1 < this->Cdf.size() && this->Cdf[from] <= v)
    {
      ++from;
    }
    return from;
  }
  std::size_t Pick(double u) const
  {
    const double v = u * this->Cdf.back();
    const std::size_t j =
      std::min(static_cast<std::size_t>(v * this->Scale), this->Guide.size() - 2);
    const std::size_t lo = this->Guide[j],
                      hi = std::min<std::size_t>(this->Guide[j + 1] + 1, this->Cdf.size());
    if ((lo > 0 && this->Cdf[lo - 1] > v) || (lo >= hi) || (this->Cdf[hi - 1] <= v))
    {
      return PickFromCdf(this->Cdf, u);
    }
    const auto it = std::upper_bound(this->Cdf.begin() + lo, this->Cdf.begin() + hi, v);
    return std::min<std::size_t>(
      static_cast<std::size_t>(it - this->Cdf.begin()), this->Cdf.size() - 1);
  }

private:
  std::vector<double> Cdf;
  std::vector<std::uint32_t> Guide; // first index whose value exceeds bucket j's start
  double Scale = 0.0;               // buckets per unit of cumulative value
};

Point3 PointInTriangle(const Point3& a, const Point3& b, const Point3& c, double u, double v)
{
  const double s = std::sqrt(u);
  return (1.0 - s) * a + (s * (1.0 - v)) * b + (s * v) * c;
}

// Runs f(i, state) for i in [begin, end) in parallel, in chunks, reporting
// progress as first + span x fraction; false when aborted. `state` is a
// State made afresh for every range of indices run in order on one thread.
template <typename State = int, typename F>
bool ForEachChunked(
  std::size_t n, double first, double span, const std::function<bool(double)>& progress, F&& f)
{
  for (std::size_t begin = 0; begin < n; begin += Chunk)
  {
    const std::size_t end = std::min(n, begin + Chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 64),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        State state{};
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          f(i, state);
        }
      });
    if (progress && !progress(first + span * double(end) / double(n)))
    {
      return false;
    }
  }
  return true;
}

// Candidate envelope samples are drawn only where a primitive surface can
// be on the boundary of the union. A point x = c_v + r_v n of ball v (or of a
// cone band, with its normal n) is strictly inside a convex primitive H that
// contains the ball (the band) whenever H's support value in direction n
// exceeds n . x: the supporting plane of H at x would have to support the
// ball (band) too, whose only normal there is n. So:
//  - ball v: only directions n with n . (c_j - c_v) <= r_v - r_j for every
//    neighbour j (the cone v-j contains the ball); that region is covered
//    conservatively by equal-area direction cells (64 z-bands x 128 angle
//    sectors, searched from 16 x 32 coarse ones) tested with their angular
//    radius;
//  - cone band (v, w): only angles where no third vertex k of an incident
//    slab supports further, n(angle) . (c_v - c_k) + r_v - r_k >= 0, which is
//    an exact union of angle intervals.
// Coarse ball cells and band pieces are also dropped when certified buried
// (see EnvelopePieces). Everything excluded is strictly inside the union, so
// the kept candidates are still uniform on its boundary after the exact
// acceptance test.
constexpr int Bands = 16, Sectors = 32, Split = 4; // coarse cells, each split 4 x 4
constexpr double TwoPi = 2.0 * Pi;

// Seconds since `start`, restarting it.
double Lap(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

// Burial tests of pieces only cull: past this many primitives evaluated in
// the tree, a piece is kept (its candidates get the exact test), which costs
// less than proving an exposed piece unburied. Most pieces tested are not
// buried (bunny, 5,000 spheres: 244K of 400K), so the limit is low: 8 keeps
// 5% more candidates than 32 but the pieces take a quarter less time.
constexpr std::size_t BurialSearchItems = 8;

struct DirectionCell
{
  double Z0, Z1, Theta0, Width;
  Point3 Centre;
  double Radius; // angular radius, with a safety margin
  double CosRadius, SinRadius;
};

std::vector<DirectionCell> MakeCells(int bands, int sectors)
{
  std::vector<DirectionCell> out;
  auto direction = [](double z, double theta)
  {
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Point3{ s * std::cos(theta), s * std::sin(theta), z };
  };
  for (int b = 0; b < bands; ++b)
  {
    for (int s = 0; s < sectors; ++s)
    {
      DirectionCell cell;
      cell.Z0 = -1.0 + 2.0 * b / bands;
      cell.Z1 = -1.0 + 2.0 * (b + 1) / bands;
      cell.Theta0 = TwoPi * s / sectors;
      cell.Width = TwoPi / sectors;
      const double t1 = cell.Theta0 + cell.Width, zm = 0.5 * (cell.Z0 + cell.Z1),
                   tm = cell.Theta0 + 0.5 * cell.Width;
      cell.Centre = direction(zm, tm);
      double radius = 0.0;
      for (double z : { cell.Z0, zm, cell.Z1 })
      {
        for (double t : { cell.Theta0, tm, t1 })
        {
          radius =
            std::max(radius, std::acos(std::clamp(Dot(cell.Centre, direction(z, t)), -1.0, 1.0)));
        }
      }
      cell.Radius = 1.2 * radius;
      cell.CosRadius = std::cos(cell.Radius);
      cell.SinRadius = std::sin(cell.Radius);
      out.push_back(cell);
    }
  }
  return out;
}

// Equal-area cells in (z, angle): coarse ones to search, fine ones to sample.
const std::vector<DirectionCell>& CoarseCells()
{
  static const std::vector<DirectionCell> cells = MakeCells(Bands, Sectors);
  return cells;
}
const std::vector<DirectionCell>& FineCells()
{
  static const std::vector<DirectionCell> cells = MakeCells(Bands * Split, Sectors * Split);
  return cells;
}

using Intervals = std::vector<std::pair<double, double>>; // disjoint, sorted, in [0, 2 pi)

Intervals Intersect(const Intervals& a, const Intervals& b)
{
  Intervals out;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size())
  {
    const double lo = std::max(a[i].first, b[j].first), hi = std::min(a[i].second, b[j].second);
    if (lo < hi)
    {
      out.emplace_back(lo, hi);
    }
    (a[i].second < b[j].second ? i : j)++;
  }
  return out;
}

// Angles t with alpha cos t + beta sin t + gamma >= 0 (a superset by 1e-9).
Intervals AllowedAngles(double alpha, double beta, double gamma)
{
  const double r = std::hypot(alpha, beta);
  if (!(r > 0.0))
  {
    return gamma >= 0.0 ? Intervals{ { 0.0, TwoPi } } : Intervals{};
  }
  const double t = -gamma / r;
  if (t <= -1.0)
  {
    return { { 0.0, TwoPi } };
  }
  if (t > 1.0 + 1e-12)
  {
    return {};
  }
  const double half = std::acos(std::min(t, 1.0)) + 1e-9;
  double lo = std::atan2(beta, alpha) - half;
  lo -= TwoPi * std::floor(lo / TwoPi);
  const double hi = lo + 2.0 * half;
  if (hi <= TwoPi)
  {
    return { { lo, hi } };
  }
  return { { 0.0, hi - TwoPi }, { lo, TwoPi } };
}

// A piece of a primitive surface that candidates are drawn from: a direction
// cell of a ball (A = z range, B = angle range), a slant and angle range of a
// cone band (A = fraction of the slant, B = angle), or a slab's tangent
// triangle (Side).
struct Piece
{
  PrimitiveRef Ref;
  int Side;
  double A0, A1, B0, B1;
  double Area = 0.0;
};

Point3 Direction(double z, double theta)
{
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  return { rho * std::cos(theta), rho * std::sin(theta), z };
}

// Point of a cone band at slant fraction sigma and angle theta.
Point3 BandPoint(const ConePrimitive& c, double sigma, double theta)
{
  const Point3 radial = std::cos(theta) * c.Perp1 + std::sin(theta) * c.Perp2;
  const Point3 slant = c.CosPhi * c.Axis - c.SinPhi * radial;
  return ConeTangentPoint(c, 0, theta) + (sigma * c.Length * c.CosPhi) * slant;
}

Point3 SamplePiece(const MedialEnvelope& envelope, const Piece& piece, Random& rng)
{
  const double u = rng.Uniform(), v = rng.Uniform();
  switch (piece.Ref.Kind)
  {
    case PrimitiveKind::Sphere:
    {
      const SpherePrimitive& s = envelope.Spheres()[piece.Ref.Id];
      return s.Center +
        s.Radius *
        Direction(piece.A0 + u * (piece.A1 - piece.A0), piece.B0 + v * (piece.B1 - piece.B0));
    }
    case PrimitiveKind::Cone:
    {
      // Area density along the slant grows linearly with the ring radius:
      // rho(sigma) = rho0 + k sigma; invert its integral from A0.
      const ConePrimitive& c = envelope.Cones()[piece.Ref.Id];
      const double rho0 = c.R[0] * c.CosPhi, k = (c.R[1] - c.R[0]) * c.CosPhi;
      const double s0 = piece.A0, s1 = piece.A1;
      double sigma = s0 + u * (s1 - s0);
      if (std::abs(k) > 1e-12 * (std::abs(rho0) + std::abs(k)))
      {
        const double total = rho0 * (s1 - s0) + 0.5 * k * (s1 * s1 - s0 * s0);
        const double q = rho0 * s0 + 0.5 * k * s0 * s0 + u * total;
        sigma =
          std::clamp((std::sqrt(std::max(0.0, rho0 * rho0 + 2.0 * k * q)) - rho0) / k, s0, s1);
      }
      return BandPoint(c, sigma, piece.B0 + v * (piece.B1 - piece.B0));
    }
    default:
    {
      const auto t = SlabTangentTriangle(envelope.Slabs()[piece.Ref.Id], piece.Side);
      return PointInTriangle(t[0], t[1], t[2], u, v);
    }
  }
}

// The pieces of every primitive surface that can be on the boundary of the
// union, with their areas: a piece is dropped when the support-function test
// (file comment) or a burial test excludes it. Burial: a point x of the piece
// with every point of the piece within g of x, and some primitive containing
// x deeper than g + tolerance: since signed distances are 1-Lipschitz, the
// whole piece is strictly inside that primitive.
struct PieceSet
{
  std::vector<Piece> Pieces;
  GuidedCdf Cdf; // of the pieces' areas
};

PieceSet EnvelopePieces(const MedialEnvelope& envelope)
{
  const double tol = envelope.Tolerance();
  const auto& edges = envelope.ConeEdges();
  const std::size_t nv = envelope.Spheres().size();
  std::vector<std::vector<Index>> neighbours(nv);
  for (const auto& e : edges)
  {
    neighbours[e[0]].push_back(e[1]);
    neighbours[e[1]].push_back(e[0]);
  }
  // Third vertices of the slabs on each edge.
  std::vector<std::vector<Index>> third(edges.size());
  for (const auto& f : envelope.SlabFaces())
  {
    for (int i = 0; i < 3; ++i)
    {
      const std::array<Index, 2> key{ std::min(f[i], f[(i + 1) % 3]),
        std::max(f[i], f[(i + 1) % 3]) };
      const auto it = std::lower_bound(edges.begin(), edges.end(), key);
      if (it != edges.end() && *it == key)
      {
        third[it - edges.begin()].push_back(f[(i + 2) % 3]);
      }
    }
  }
  // Can a direction of `cell` satisfy n . (c_j - c_v) <= r_v - r_j for
  // every neighbour j of v?
  // The constraints of ball v's neighbours j, as unit direction u_j and
  // sigma_j = (r_v - r_j) / |c_j - c_v|; false when some neighbour's ball
  // contains ball v (then nothing of v is exposed).
  struct Constraint
  {
    Point3 Direction;
    double Sigma;
  };
  auto constraints = [&](std::size_t v, std::vector<Constraint>& out)
  {
    out.clear();
    const SpherePrimitive& s = envelope.Spheres()[v];
    for (Index j : neighbours[v])
    {
      const SpherePrimitive& o = envelope.Spheres()[j];
      const Point3 d = o.Center - s.Center;
      const double length = Norm(d);
      if (!(length > 0.0))
      {
        if (s.Radius < o.Radius)
        {
          return false;
        }
        continue;
      }
      out.push_back({ (1.0 / length) * d, (s.Radius - o.Radius) / length });
    }
    return true;
  };
  // Can a direction of `cell` satisfy n . u_j <= sigma_j for every
  // constraint? The farthest direction of the cell from u_j is at angle
  // a + Radius, a = the centre's angle: excluded when cos(a + Radius) >
  // sigma_j (+ margin), with cos(a + Radius) expanded so that no acos is
  // needed (a + Radius < pi iff cos a > -cos Radius).
  auto supports = [](const std::vector<Constraint>& list, const DirectionCell& cell)
  {
    for (const Constraint& c : list)
    {
      const double cosA = std::clamp(Dot(cell.Centre, c.Direction), -1.0, 1.0);
      // cos(a + Radius) <= cos a: most constraints are met at the centre
      // already, without the square root.
      if (cosA <= c.Sigma + 1e-12)
      {
        continue;
      }
      if (cosA > -cell.CosRadius &&
        cosA * cell.CosRadius - std::sqrt(1.0 - cosA * cosA) * cell.SinRadius > c.Sigma + 1e-12)
      {
        return false;
      }
    }
    return true;
  };
  // `hint` carries the burying primitive from one piece to the next of the
  // same primitive (neighbouring pieces are mostly buried by the same one).
  // The primitive's own neighbours are not tried first, unlike for
  // candidates: the support-function tests above already left out what they
  // bury (on the bunny, 5,000 spheres, they certified no ball piece and 1%
  // of band pieces, for a third of the evaluations).
  auto buried = [&](const Point3& x, double g, std::uint32_t& hint)
  {
    const std::uint32_t by = envelope.FindBurying(x, g + tol, nullptr, 0, hint, BurialSearchItems);
    hint = by == MedialEnvelope::NoBurial ? hint : by;
    return by != MedialEnvelope::NoBurial;
  };

  // The area of a piece (computed in the parallel pass).
  auto pieceArea = [&](const Piece& p)
  {
    double area = 0.0;
    switch (p.Ref.Kind)
    {
      case PrimitiveKind::Sphere:
      {
        const double r = envelope.Spheres()[p.Ref.Id].Radius;
        area = r * r * (p.A1 - p.A0) * (p.B1 - p.B0);
        break;
      }
      case PrimitiveKind::Cone:
      {
        const ConePrimitive& c = envelope.Cones()[p.Ref.Id];
        const double slant = c.Length * c.CosPhi;
        const double rho0 = c.R[0] * c.CosPhi, k = (c.R[1] - c.R[0]) * c.CosPhi;
        area =
          (p.B1 - p.B0) * slant * (rho0 * (p.A1 - p.A0) + 0.5 * k * (p.A1 * p.A1 - p.A0 * p.A0));
        break;
      }
      default:
      {
        const auto t = SlabTangentTriangle(envelope.Slabs()[p.Ref.Id], p.Side);
        area = 0.5 * Norm(Cross(t[1] - t[0], t[2] - t[0]));
        break;
      }
    }
    return area;
  };
  // Pieces per primitive, in parallel; concatenated in primitive order.
  const std::size_t nc = edges.size(), nf = envelope.SlabFaces().size();
  std::vector<std::vector<Piece>> perPrimitive(nv + nc + nf);
  const auto& coarse = CoarseCells();
  const auto& fine = FineCells();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, perPrimitive.size(), 16),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t i = r.begin(); i < r.end(); ++i)
      {
        std::vector<Piece>& out = perPrimitive[i];
        std::uint32_t hint = MedialEnvelope::NoBurial;
        std::vector<Constraint> list;
        if (i < nv)
        {
          const SpherePrimitive& s = envelope.Spheres()[i];
          const PrimitiveRef ref{ PrimitiveKind::Sphere, static_cast<Index>(i) };
          if (!(s.Radius > 0.0) || !constraints(i, list))
          {
            continue;
          }
          for (std::size_t k = 0; k < coarse.size(); ++k)
          {
            if (!supports(list, coarse[k]))
            {
              continue;
            }
            // The fine cells first: for a third of the coarse cells that
            // pass (bunny, 5,000 spheres) none does, and the burial test
            // is spared.
            const DirectionCell* kept[Split * Split];
            int count = 0;
            const std::size_t b = k / Sectors, sector = k % Sectors;
            for (int zi = 0; zi < Split; ++zi)
            {
              for (int ti = 0; ti < Split; ++ti)
              {
                const DirectionCell& cell =
                  fine[(b * Split + zi) * (Sectors * Split) + sector * Split + ti];
                if (supports(list, cell))
                {
                  kept[count++] = &cell;
                }
              }
            }
            if (count == 0 ||
              buried(s.Center + s.Radius * coarse[k].Centre, s.Radius * coarse[k].Radius, hint))
            {
              continue;
            }
            for (int i = 0; i < count; ++i)
            {
              const DirectionCell& cell = *kept[i];
              out.push_back({ ref, 0, cell.Z0, cell.Z1, cell.Theta0, cell.Theta0 + cell.Width });
            }
          }
        }
        else if (i < nv + nc)
        {
          const std::size_t e = i - nv;
          const ConePrimitive& c = envelope.Cones()[e];
          const PrimitiveRef ref{ PrimitiveKind::Cone, static_cast<Index>(e) };
          if (!(ConeLateralArea(c) > 0.0))
          {
            continue;
          }
          // Angles where no third vertex of an incident slab supports further.
          Intervals allowed{ { 0.0, TwoPi } };
          for (Index k : third[e])
          {
            const SpherePrimitive& o = envelope.Spheres()[k];
            const Point3 d = c.C[0] - o.Center;
            allowed = Intersect(allowed,
              AllowedAngles(c.CosPhi * Dot(c.Perp1, d), c.CosPhi * Dot(c.Perp2, d),
                c.SinPhi * Dot(c.Axis, d) + c.R[0] - o.Radius));
          }
          constexpr int Slices = 4, Wedges = 32;
          const double slant = c.Length * c.CosPhi;
          const double rhoMax = std::max(c.R[0], c.R[1]) * c.CosPhi;
          for (int w = 0; w < Wedges; ++w)
          {
            // The allowed angles within the wedge (as Intersect, in place).
            const double w0 = TwoPi * w / Wedges, w1 = TwoPi * (w + 1) / Wedges;
            for (const auto& [a0, a1] : allowed)
            {
              const double t0 = std::max(a0, w0), t1 = std::min(a1, w1);
              if (!(t0 < t1))
              {
                continue;
              }
              for (int sl = 0; sl < Slices; ++sl)
              {
                const double s0 = double(sl) / Slices, s1 = double(sl + 1) / Slices;
                const double g = 0.5 * (s1 - s0) * slant + 0.5 * (t1 - t0) * rhoMax;
                if (!buried(BandPoint(c, 0.5 * (s0 + s1), 0.5 * (t0 + t1)), g, hint))
                {
                  out.push_back({ ref, 0, s0, s1, t0, t1 });
                }
              }
            }
          }
        }
        else
        {
          const std::size_t f = i - nv - nc;
          if (envelope.Slabs()[f].HasTangentPlanes)
          {
            for (int side = 0; side < 2; ++side)
            {
              out.push_back({ { PrimitiveKind::Slab, static_cast<Index>(f) }, side, 0, 0, 0, 0 });
            }
          }
        }
        for (Piece& p : out)
        {
          p.Area = pieceArea(p);
        }
        out.erase(
          std::remove_if(out.begin(), out.end(), [](const Piece& p) { return !(p.Area > 0.0); }),
          out.end());
      }
    });
  PieceSet set;
  // Concatenated along a Morton curve through the primitives: candidates,
  // drawn stratified over the pieces in this order, then come out close to
  // the ones before them without being sorted (see the candidate loop).
  const std::vector<std::uint32_t> primitiveOrder = MortonOrder(perPrimitive.size(),
    [&](std::size_t i)
    {
      if (i < nv)
      {
        return envelope.Spheres()[i].Center;
      }
      if (i < nv + nc)
      {
        const auto& e = edges[i - nv];
        return 0.5 * (envelope.Spheres()[e[0]].Center + envelope.Spheres()[e[1]].Center);
      }
      const auto& f = envelope.SlabFaces()[i - nv - nc];
      return (1.0 / 3.0) *
        (envelope.Spheres()[f[0]].Center + envelope.Spheres()[f[1]].Center +
          envelope.Spheres()[f[2]].Center);
    });
  // Copied in parallel to their places; the cumulative areas are summed in
  // order, as the sampling's distribution must not depend on the threads.
  std::vector<std::size_t> offsets(primitiveOrder.size() + 1, 0);
  for (std::size_t k = 0; k < primitiveOrder.size(); ++k)
  {
    offsets[k + 1] = offsets[k] + perPrimitive[primitiveOrder[k]].size();
  }
  set.Pieces.resize(offsets.back());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, primitiveOrder.size(), 256),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t k = r.begin(); k < r.end(); ++k)
      {
        const auto& list = perPrimitive[primitiveOrder[k]];
        std::copy(list.begin(), list.end(), set.Pieces.begin() + offsets[k]);
      }
    });
  std::vector<double> cdf(set.Pieces.size());
  double total = 0.0;
  for (std::size_t i = 0; i < cdf.size(); ++i)
  {
    total += set.Pieces[i].Area;
    cdf[i] = total;
  }
  set.Cdf.Build(std::move(cdf));
  return set;
}

void Summarise(const std::vector<double>& values, std::size_t meanBegin, OneSidedError& out)
{
  out.Samples = values.size();
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    out.Hausdorff = std::max(out.Hausdorff, values[i]);
    if (i >= meanBegin)
    {
      sum += values[i];
      sum2 += values[i] * values[i];
    }
  }
  const std::size_t n = values.size() - meanBegin;
  if (n > 0)
  {
    out.Mean = sum / double(n);
    out.RMS = std::sqrt(sum2 / double(n));
  }
}
}

void SampleTriangleMesh(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed,
  std::vector<Point3>& points, std::vector<Point3>& normals)
{
  points.resize(count);
  normals.resize(count);
  if (count == 0 || mesh.Triangles.empty())
  {
    points.clear();
    normals.clear();
    return;
  }
  std::vector<double> cdf(mesh.Triangles.size());
  double total = 0.0;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const Triangle& tri = mesh.Triangles[t];
    const Point3& a = mesh.Points[tri[0]];
    total += 0.5 * Norm(Cross(mesh.Points[tri[1]] - a, mesh.Points[tri[2]] - a));
    cdf[t] = total;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t k = r.begin(); k < r.end(); ++k)
      {
        Random rng = SampleRandom(seed, k);
        const Triangle& tri = mesh.Triangles[PickFromCdf(cdf, rng.Uniform())];
        const Point3 &a = mesh.Points[tri[0]], &b = mesh.Points[tri[1]], &c = mesh.Points[tri[2]];
        const double u = rng.Uniform(), v = rng.Uniform();
        points[k] = PointInTriangle(a, b, c, u, v);
        normals[k] = Normalized(Cross(b - a, c - a));
      }
    });
}

ReconstructionErrorResult ComputeReconstructionError(const TriangleMesh& surface,
  const MedialEnvelope& envelope, const ReconstructionErrorOptions& options)
{
  ReconstructionErrorResult result;
  if (surface.Points.empty() || surface.Triangles.empty() || envelope.Empty())
  {
    return result;
  }
  const auto box = BoundingBox(surface.Points);
  result.Diagonal = Norm(box.second - box.first);
  auto clock = std::chrono::steady_clock::now();
  // Two serial builds run in the background while the other threads work:
  // the surface's triangle hierarchy (for envelope -> surface) during
  // surface -> envelope, and the tree over the envelope samples (for the
  // inside bounds) during envelope -> surface. Waited for before anything
  // they use is moved or destroyed, and by the guard on other ways out.
  std::optional<TriangleLocator> locator;
  std::optional<KdTree> boundary;
  tbb::task_group background;
  struct WaitOnExit
  {
    tbb::task_group& Tasks;
    ~WaitOnExit() { this->Tasks.wait(); }
  } waitOnExit{ background };

  // Surface -> envelope, at the vertices (normals: area-weighted) and samples.
  std::vector<Point3> samples, sampleNormals;
  SampleTriangleMesh(surface, options.NumberOfSamples, options.RandomSeed, samples, sampleNormals);
  background.run([&] { locator.emplace(surface); });
  const std::size_t nv = surface.Points.size();
  std::vector<Point3> vertexNormals(nv, Point3{ 0, 0, 0 });
  for (const Triangle& t : surface.Triangles)
  {
    const Point3 n = Cross(
      surface.Points[t[1]] - surface.Points[t[0]], surface.Points[t[2]] - surface.Points[t[0]]);
    for (Index v : t)
    {
      vertexNormals[v] = vertexNormals[v] + n;
    }
  }
  const std::size_t ns = samples.size();
  std::vector<MedialEnvelope::BoundaryDistance> distances(nv + ns);
  const std::vector<std::uint32_t> surfaceOrder = MortonOrder(
    nv + ns, [&](std::size_t i) { return i < nv ? surface.Points[i] : samples[i - nv]; });
  // Along the Morton curve each point's search starts from the previous
  // point's nearest primitive (the values do not depend on it).
  struct Warm
  {
    std::uint32_t Position = MedialEnvelope::NoPrimitive;
  };
  // Isolated, so that this thread, waiting for its loops, does not take up
  // the background task and leave the loops to the others.
  const bool surfaceDone = tbb::this_task_arena::isolate(
    [&]
    {
      return ForEachChunked<Warm>(nv + ns, 0.0, 0.6, options.Progress,
        [&](std::size_t k, Warm& warm)
        {
          const std::size_t i = surfaceOrder[k];
          distances[i] = i < nv
            ? envelope.DistanceToBoundary(surface.Points[i], &vertexNormals[i], &warm.Position)
            : envelope.DistanceToBoundary(samples[i - nv], &sampleNormals[i - nv], &warm.Position);
        });
    });
  if (!surfaceDone)
  {
    result.Aborted = true;
    return result;
  }
  // Envelope -> surface: candidates on the primitive surfaces (where they
  // can be exposed, see EnvelopePieces), area-uniform, kept when on the
  // boundary of the union; drawn in batches until enough are kept.
  // Candidate k depends only on (seed, k).
  result.SurfaceSeconds = Lap(clock);
  const PieceSet pieces = EnvelopePieces(envelope);
  result.PiecesSeconds = Lap(clock);
  const std::size_t target = pieces.Pieces.empty() ? 0 : options.NumberOfEnvelopeSamples;
  const std::size_t limit = 1000 * target;
  const std::uint64_t envelopeSeed = options.RandomSeed ^ 0x5DEECE66Dull;
  std::size_t drawn = 0;
  std::vector<Point3> batchPoints;
  std::vector<std::uint32_t> batchPieces;
  std::vector<std::uint8_t> keep;
  std::vector<double> batchKeys;
  std::vector<std::uint32_t> accepted;
  while (result.EnvelopeSamples.size() < target && drawn < limit)
  {
    const std::size_t have = result.EnvelopeSamples.size();
    const double rate = drawn > 0 ? std::max(double(have) / double(drawn), 1e-3) : 0.5;
    const std::size_t batch =
      std::min<std::size_t>({ static_cast<std::size_t>(1.2 * double(target - have) / rate) + 1024,
        std::size_t(1) << 18, limit - drawn });
    batchPoints.resize(batch);
    batchPieces.resize(batch);
    keep.assign(batch, 0);
    // Stratified over the pieces' cumulative area: candidate i of the batch
    // takes u in [i, i + 1) / batch, so that a range of candidates walks
    // through the pieces in order (a random pick per candidate was mostly
    // cache misses). Each candidate is still uniform on the pieces.
    batchKeys.resize(batch);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        std::size_t piece = 0;
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          Random rng = SampleRandom(envelopeSeed, drawn + i);
          const double u = std::min((double(i) + rng.Uniform()) / double(batch), 1.0);
          piece = i == r.begin() ? pieces.Cdf.Pick(u) : pieces.Cdf.PickFrom(u, piece);
          batchPieces[i] = static_cast<std::uint32_t>(piece);
          batchPoints[i] = SamplePiece(envelope, pieces.Pieces[piece], rng);
          batchKeys[i] = rng.Uniform();
        }
      });
    // Tested in order: consecutive candidates are close (the pieces are in
    // Morton order), so a primitive that buried one is tried first on the
    // next, and they share cached tree nodes. keep[i] does not depend on
    // that order.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        std::uint32_t hint = MedialEnvelope::NoBurial;
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          // Neighbours next: they bury most rejected candidates.
          Index vertices[3];
          const int count = envelope.MedialVertices(pieces.Pieces[batchPieces[i]].Ref, vertices);
          const std::uint32_t by =
            envelope.FindBurying(batchPoints[i], envelope.Tolerance(), vertices, count, hint);
          keep[i] = by == MedialEnvelope::NoBurial ? 1 : 0;
          hint = keep[i] ? hint : by;
        }
      });
    // Kept candidates beyond the target: a random subset (by key), not the
    // first ones, which would favour the pieces at the start of the order.
    accepted.clear();
    for (std::size_t i = 0; i < batch; ++i)
    {
      if (keep[i])
      {
        accepted.push_back(static_cast<std::uint32_t>(i));
      }
    }
    const std::size_t wanted = target - result.EnvelopeSamples.size();
    if (accepted.size() > wanted)
    {
      auto byKey = [&](std::uint32_t a, std::uint32_t b)
      { return batchKeys[a] < batchKeys[b] || (batchKeys[a] == batchKeys[b] && a < b); };
      std::nth_element(accepted.begin(), accepted.begin() + wanted, accepted.end(), byKey);
      accepted.resize(wanted);
      std::sort(accepted.begin(), accepted.end());
    }
    for (const std::uint32_t i : accepted)
    {
      result.EnvelopeSamples.push_back(batchPoints[i]);
      result.EnvelopeSamplePrimitive.push_back(pieces.Pieces[batchPieces[i]].Ref);
    }
    result.EnvelopeCandidates = drawn + batch;
    drawn += batch;
    if (options.Progress &&
      !options.Progress(0.6 + 0.2 * double(result.EnvelopeSamples.size()) / double(target)))
    {
      result.Aborted = true;
      return result;
    }
  }
  result.CandidatesSeconds = Lap(clock);
  background.wait();
  if (!result.EnvelopeSamples.empty())
  {
    background.run([&] { boundary.emplace(result.EnvelopeSamples); });
  }
  result.EnvelopeSampleDistance.resize(result.EnvelopeSamples.size());
  const bool envelopeDone = tbb::this_task_arena::isolate(
    [&]
    {
      return ForEachChunked(result.EnvelopeSamples.size(), 0.8, 0.2, options.Progress,
        [&](std::size_t i, int)
        { result.EnvelopeSampleDistance[i] = locator->Distance(result.EnvelopeSamples[i]); });
    });
  if (!envelopeDone)
  {
    background.wait();
    result.Aborted = true;
    return result;
  }
  Summarise(result.EnvelopeSampleDistance, 0, result.EnvelopeToSurface);
  // The samples' largest distance, raised by climbing from the farthest ones
  // (EnvelopeMaximum.h). First step: the samples' spacing, from the exposed
  // area estimated as the pieces' area times the share of candidates kept.
  if (!result.EnvelopeSamples.empty())
  {
    const auto farthest =
      std::max_element(result.EnvelopeSampleDistance.begin(), result.EnvelopeSampleDistance.end());
    result.EnvelopeFarthestPoint =
      result.EnvelopeSamples[farthest - result.EnvelopeSampleDistance.begin()];
    const double kept = double(result.EnvelopeSamples.size()) / double(result.EnvelopeCandidates);
    EnvelopeMaximumOptions climb;
    climb.Seeds = options.MaximumSearches;
    climb.Step = std::sqrt(pieces.Cdf.Total() * kept / double(result.EnvelopeSamples.size()));
    const EnvelopeMaximum refined = RefineEnvelopeMaximum(
      envelope, result.EnvelopeSamples, result.EnvelopeSamplePrimitive,
      result.EnvelopeSampleDistance, [&](const Point3& p) { return locator->Distance(p); }, climb);
    if (refined.Distance > result.EnvelopeToSurface.Hausdorff)
    {
      result.EnvelopeToSurface.Hausdorff = refined.Distance;
      result.EnvelopeFarthestPoint = refined.Point;
    }
  }
  result.EnvelopeToSurface.HausdorffLowerBound = result.EnvelopeToSurface.Hausdorff;
  result.EnvelopeSeconds = Lap(clock);

  // Inside points whose distance to the union's boundary is not certified
  // exact carry an upper bound from projections and ray traces, which can be
  // far off where many primitives meet. Every envelope sample is a point of
  // that boundary, so the nearest one bounds the distance from above too.
  background.wait();
  if (boundary)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv + ns, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          auto& d = distances[i];
          if (d.Inside && !d.Exact)
          {
            const Point3& p = i < nv ? surface.Points[i] : samples[i - nv];
            const double nearest = Norm(p - result.EnvelopeSamples[boundary->Nearest(p)]);
            d.Upper = std::max(d.Lower, std::min(d.Upper, nearest));
          }
        }
      });
  }
  result.TighteningSeconds = Lap(clock);
  result.VertexDistance.resize(nv);
  result.VertexLowerBound.resize(nv);
  result.VertexSignedDistance.resize(nv);
  std::vector<double> upper(nv + ns);
  for (std::size_t i = 0; i < nv + ns; ++i)
  {
    const auto& d = distances[i];
    upper[i] = d.Upper;
    if (i < nv)
    {
      result.VertexDistance[i] = d.Upper;
      result.VertexLowerBound[i] = d.Lower;
      result.VertexSignedDistance[i] = d.Signed;
    }
    result.SurfaceToEnvelope.HausdorffLowerBound =
      std::max(result.SurfaceToEnvelope.HausdorffLowerBound, d.Lower);
    result.InsidePoints += d.Inside ? 1 : 0;
    result.UncertifiedPoints += d.Exact ? 0 : 1;
    result.LargestBoundGap = std::max(result.LargestBoundGap, d.Upper - d.Lower);
  }
  // Mean and RMS over the area-uniform samples (over the vertices if none).
  Summarise(upper, ns > 0 ? nv : 0, result.SurfaceToEnvelope);

  result.Hausdorff =
    std::max(result.SurfaceToEnvelope.Hausdorff, result.EnvelopeToSurface.Hausdorff);
  result.Mean = std::max(result.SurfaceToEnvelope.Mean, result.EnvelopeToSurface.Mean);
  result.RMS = std::max(result.SurfaceToEnvelope.RMS, result.EnvelopeToSurface.RMS);
  return result;
}
}
