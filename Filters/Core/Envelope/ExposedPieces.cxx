// SPDX-License-Identifier: GPL-3.0-or-later
#include "Envelope/ExposedPieces.h"

#include "Geometry/MortonOrder.h"
#include "Geometry/Vec3.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace medialaxis
{
namespace
{
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
}

ExposedPieceSet EnvelopePieces(const MedialEnvelope& envelope)
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
  auto pieceArea = [&](const ExposedPiece& p)
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
  std::vector<std::vector<ExposedPiece>> perPrimitive(nv + nc + nf);
  const auto& coarse = CoarseCells();
  const auto& fine = FineCells();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, perPrimitive.size(), 16),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t i = r.begin(); i < r.end(); ++i)
      {
        std::vector<ExposedPiece>& out = perPrimitive[i];
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
        for (ExposedPiece& p : out)
        {
          p.Area = pieceArea(p);
        }
        out.erase(std::remove_if(
                    out.begin(), out.end(), [](const ExposedPiece& p) { return !(p.Area > 0.0); }),
          out.end());
      }
    });
  ExposedPieceSet set;
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
}
