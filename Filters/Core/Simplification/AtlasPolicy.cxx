// SPDX-License-Identifier: GPL-3.0-or-later
#include "Simplification/AtlasPolicy.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/Vec3.h"
#include "Support/SortedLists.h"

#include <LBFGS.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace medialaxis
{
namespace
{
// Adds lambda x the uniform Laplacian (Eq. 12) over `count` neighbours with
// centre sum `sum` and squared-norm sum `sumSquares`.
void AddLaplacian(
  SphereQuadric& q, double lambda, const Point3& sum, double sumSquares, std::size_t count)
{
  if (count == 0)
  {
    return;
  }
  const double w = lambda / static_cast<double>(count);
  for (int k = 0; k < 3; ++k)
  {
    q.A(k, k) += lambda;
    q.B(k) += w * sum[k];
  }
  q.C() += w * sumSquares;
}

// Nonlinear fidelity of Eq. 11 plus the quadratic part, for L-BFGS.
struct InvaginatedEnergy
{
  const SphereQuadric* Quadratic;
  const std::vector<std::pair<Point3, double>>* Anchors; // site, cell area

  double operator()(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const
  {
    const Sphere s{ x[0], x[1], x[2], x[3] };
    double energy = this->Quadratic->Evaluate(s);
    const Sphere as = this->Quadratic->Times(s);
    for (int i = 0; i < 4; ++i)
    {
      gradient[i] = 2.0 * as[i] - 2.0 * this->Quadratic->B(i);
    }
    for (const auto& [site, area] : *this->Anchors)
    {
      const Point3 d = Point3{ s[0], s[1], s[2] } - site;
      const double length = std::max(Norm(d), 1e-300);
      const double residual = length - s[3];
      energy += area * residual * residual;
      for (int k = 0; k < 3; ++k)
      {
        gradient[k] += 2.0 * area * residual * d[k] / length;
      }
      gradient[3] -= 2.0 * area * residual;
    }
    return energy;
  }
};

// Eq. 11: the quadric of the regular cells plus, for cells on concave edges
// (anchors: site and area), the squared distance from the sphere to the site.
double EnergyAt(
  const SphereQuadric& q, const std::vector<std::pair<Point3, double>>& anchors, const Sphere& x)
{
  double e = q.Evaluate(x);
  for (const auto& [site, area] : anchors)
  {
    const double r = Norm(Point3{ x[0], x[1], x[2] } - site) - x[3];
    e += area * r * r;
  }
  return e;
}
}

AtlasSiteCells::AtlasSiteCells(const RestrictedVoronoiDiagram& rvd,
  const std::vector<Point3>& sites, const AtlasSimplifierOptions& options)
{
  // Normalisation from the sites' bounding box (the surface's extent).
  Point3 lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
  if (!sites.empty())
  {
    std::tie(lo, hi) = BoundingBox(sites);
  }
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  this->UnitFrame.Origin = lo;
  this->UnitFrame.Scale = extent > 0.0 ? 1.0 / extent : 1.0;
  this->Diagonal = this->UnitFrame.Scale * std::sqrt(Distance2(lo, hi));

  // Per-cell quadrics from the RVD polygons (normal and area by Newell's
  // formula: every polygon is planar, a piece of one surface triangle).
  const std::size_t ns = sites.size();
  this->Site.resize(ns);
  for (std::size_t i = 0; i < ns; ++i)
  {
    this->Site[i] = this->UnitFrame.To(sites[i]);
  }
  const double bound = UsesErrorBands(options) ? options.InitialErrorBand : options.ErrorBound;
  if (bound * this->Diagonal > 0.0)
  {
    this->SiteTree = std::make_unique<KdTree>(this->Site);
  }
  this->CellQuadric.assign(ns, SphereQuadric());
  this->CellArea.assign(ns, 0.0);
  this->CellReach.assign(ns, 0.0);
  for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
  {
    const Index site = rvd.PolygonSite[p];
    if (site < 0 || static_cast<std::size_t>(site) >= ns)
    {
      continue;
    }
    Point3 twiceNormal{ 0, 0, 0 };
    const Index first = rvd.Offsets[p], count = rvd.Offsets[p + 1] - first;
    const Point3 anchor = this->UnitFrame.To(rvd.Vertices[first]);
    for (Index k = 1; k + 1 < count; ++k)
    {
      twiceNormal = twiceNormal +
        Cross(this->UnitFrame.To(rvd.Vertices[first + k]) - anchor,
          this->UnitFrame.To(rvd.Vertices[first + k + 1]) - anchor);
    }
    const double area = 0.5 * Norm(twiceNormal);
    if (!(area > 0.0))
    {
      continue;
    }
    for (Index k = 0; k < count; ++k)
    {
      this->CellReach[site] = std::max(this->CellReach[site],
        Distance2(this->UnitFrame.To(rvd.Vertices[first + k]), this->Site[site]));
    }
    const Point3 n = Normalized(twiceNormal);
    this->CellQuadric[site].AddFacet(n, Dot(n, anchor), area);
    this->CellArea[site] += area;
  }
  this->SitePolygonOffsets.assign(ns + 1, 0);
  for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
  {
    const Index site = rvd.PolygonSite[p];
    if (site >= 0 && static_cast<std::size_t>(site) < ns)
    {
      ++this->SitePolygonOffsets[site + 1];
    }
  }
  for (std::size_t s = 0; s < ns; ++s)
  {
    this->SitePolygonOffsets[s + 1] += this->SitePolygonOffsets[s];
  }
  this->SitePolygons.resize(this->SitePolygonOffsets[ns]);
  {
    std::vector<Index> fill(this->SitePolygonOffsets.begin(), this->SitePolygonOffsets.end() - 1);
    for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
    {
      const Index site = rvd.PolygonSite[p];
      if (site >= 0 && static_cast<std::size_t>(site) < ns)
      {
        this->SitePolygons[fill[site]++] = static_cast<Index>(p);
      }
    }
  }
  this->Convex.assign(ns, 0);
  this->Invaginated.assign(ns, 0);
  if (rvd.ConvexFeature.size() == ns)
  {
    this->Convex = rvd.ConvexFeature;
  }
  if (rvd.ConcaveFeature.size() == ns && options.InvaginatedTerm)
  {
    this->Invaginated = rvd.ConcaveFeature;
  }
}

AtlasPolicy::AtlasPolicy(const AtlasMedialMesh& input, const RestrictedVoronoiDiagram& rvd,
  const std::vector<Point3>& sites, const AtlasSimplifierOptions& options)
  : AtlasPolicy(input, rvd, std::make_unique<const AtlasSiteCells>(rvd, sites, options), options)
{
}

AtlasPolicy::AtlasPolicy(const AtlasMedialMesh& input, const RestrictedVoronoiDiagram& rvd,
  std::unique_ptr<const AtlasSiteCells> cells, const AtlasSimplifierOptions& options)
  : Options(options)
  , Rvd(rvd)
  , Cells(std::move(cells))
  , UnitFrame(this->Cells->UnitFrame)
  , Diagonal(this->Cells->Diagonal)
  , SiteTree(this->Cells->SiteTree)
  , CellQuadric(this->Cells->CellQuadric)
  , CellArea(this->Cells->CellArea)
  , CellReach(this->Cells->CellReach)
  , SitePolygonOffsets(this->Cells->SitePolygonOffsets)
  , SitePolygons(this->Cells->SitePolygons)
  , Site(this->Cells->Site)
  , Convex(this->Cells->Convex)
  , Invaginated(this->Cells->Invaginated)
{
  this->RaisingBound = UsesErrorBands(options);
  this->ErrorBound =
    (this->RaisingBound ? options.InitialErrorBand : options.ErrorBound) * this->Diagonal;
  const std::size_t ns = this->Site.size();
  // Vertices, Atlases and their quadrics.
  const MedialMesh& mesh = input.Mesh;
  const std::size_t nv = mesh.Centers.size();
  this->Atlas.resize(nv);
  this->AtlasQuadric.assign(nv, SphereQuadric());
  this->Feature.assign(nv, 0);
  this->AnyInvaginated.assign(nv, 0);
  if (this->SiteTree)
  {
    this->Clearance.assign(nv, SiteClearanceBound());
    if (input.SiteClearance.size() == nv)
    {
      for (std::size_t v = 0; v < nv; ++v)
      {
        const double value = input.SiteClearance[v] * this->UnitFrame.Scale;
        if (value >= 0.0 && std::isfinite(value))
        {
          this->Clearance[v] = { this->UnitFrame.To(mesh.Centers[v]), value };
        }
      }
    }
  }
  // Vertex by vertex, independently: in parallel.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 2048),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t v = range.begin(); v != range.end(); ++v)
      {
        auto& atlas = this->Atlas[v];
        for (Index k = input.AtlasOffsets[v]; k < input.AtlasOffsets[v + 1]; ++k)
        {
          const Index s = input.AtlasSites[k];
          if (s >= 0 && static_cast<std::size_t>(s) < ns)
          {
            atlas.push_back(s);
          }
        }
        std::sort(atlas.begin(), atlas.end());
        atlas.erase(std::unique(atlas.begin(), atlas.end()), atlas.end());
        for (Index s : atlas)
        {
          if (!this->Invaginated[s])
          {
            this->AtlasQuadric[v] += this->CellQuadric[s];
          }
          else
          {
            this->AnyInvaginated[v] = 1;
          }
        }
        this->UpdateFeature(static_cast<Index>(v));
      }
    });
}

// A feature vertex's Atlas touches a sharp convex edge and no concave one.
void AtlasPolicy::UpdateFeature(Index v)
{
  if (!this->Options.PreserveSharpFeatures)
  {
    this->Feature[v] = 0;
    return;
  }
  bool convex = false, concave = false;
  for (Index s : this->Atlas[v])
  {
    convex = convex || this->Convex[s];
    concave = concave || this->Invaginated[s];
  }
  this->Feature[v] = convex && !concave ? 1 : 0;
}

double AtlasPolicy::Weight(double spike, bool absorbed) const
{
  const double sharpness =
    absorbed ? this->Options.SpikeRemovalSharpness : this->Options.SpikeSharpness;
  const double t = sharpness * (spike - this->Options.SpikeThreshold);
  // Past 40, exp(-t) < 2^-57 and 1 + exp(-t) rounds to exactly 1: most
  // edges (stability ratio above 0.43 at the default sharpness) skip the call.
  if (t > 40.0)
  {
    return 1.0;
  }
  return 1.0 / (1.0 + std::exp(-t));
}

Placement AtlasPolicy::Solve(const MedialEdgeCollapse& mesh, const SphereQuadric& q,
  const std::vector<std::pair<Point3, double>>& anchors, Index a, Index b) const
{
  const Sphere& pa = mesh.SphereOf(a);
  const Sphere& pb = mesh.SphereOf(b);
  const Sphere mid{ 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2]),
    0.5 * (pa[3] + pb[3]) };
  auto energyAt = [&](const Sphere& x) { return EnergyAt(q, anchors, x); };
  Placement best;
  auto consider = [&](const Sphere& x)
  {
    // A zero-radius sphere is a point of the envelope: it belongs on the
    // surface (a sharp edge), not where the planes of the Atlas' cells meet
    // beyond it (see NearAtlas).
    if (x[3] < 0.0 ||
      (x[3] == 0.0 && !this->NearAtlas({ x[0], x[1], x[2] }, this->Atlas[a], this->Atlas[b])))
    {
      return;
    }
    const double e = energyAt(x);
    if (e < best.Energy)
    {
      best.Energy = e;
      best.Target = x;
    }
  };

  const bool aFeature = this->OnFeature(mesh, a), bFeature = this->OnFeature(mesh, b);
  if (this->Options.PreserveSharpFeatures && (aFeature || bFeature) && anchors.empty())
  {
    // Eq. 18: discrete candidates with zero radius.
    auto atZero = [](const Sphere& s) { return Sphere{ s[0], s[1], s[2], 0.0 }; };
    if (aFeature && !bFeature)
    {
      consider(atZero(pa));
    }
    else if (bFeature && !aFeature)
    {
      consider(atZero(pb));
    }
    else
    {
      consider(atZero(pa));
      consider(atZero(pb));
      consider(atZero(mid));
    }
    return best;
  }

  if (anchors.empty())
  {
    // Closed form (4 x 4); a negative radius is replaced by the best centre
    // with r = 0 (the 3 x 3 block).
    Eigen::Vector4d x;
    if (SolveQuadric<4>(q, x))
    {
      Sphere s{ x[0], x[1], x[2], x[3] };
      Eigen::Vector3d y;
      if (s[3] < 0.0 && SolveQuadric<3>(q, y))
      {
        s = { y[0], y[1], y[2], 0.0 };
      }
      consider(s);
    }
  }
  else
  {
    // Eq. 11 is nonlinear: L-BFGS from the midpoint, radius = distance to
    // the nearest Atlas site (paper section 4.2).
    Eigen::VectorXd x(4);
    x << mid[0], mid[1], mid[2], HUGE_VAL;
    for (const auto& [site, area] : anchors)
    {
      x[3] = std::min(x[3], Norm(Point3{ mid[0], mid[1], mid[2] } - site));
    }
    InvaginatedEnergy f{ &q, &anchors };
    LBFGSpp::LBFGSParam<double> param;
    param.epsilon = 1e-10;
    param.max_iterations = 50;
    LBFGSpp::LBFGSSolver<double> solver(param);
    double fx = 0.0;
    try
    {
      solver.minimize(f, x, fx);
    }
    catch (const std::exception&)
    {
      // Line search trouble: keep the best point reached.
    }
    if (x.allFinite())
    {
      consider({ x[0], x[1], x[2], std::max(0.0, x[3]) });
    }
  }
  if (!(best.Energy < HUGE_VAL))
  {
    // Singular or failed: the best of the endpoints and the midpoint.
    consider(pa);
    consider(pb);
    consider(mid);
  }
  return best;
}

CollapsePolicy::Evaluation AtlasPolicy::Evaluate(
  const MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch) const
{
  auto& anchors = scratch.Anchors;
  // Union of the Atlases, each cell once: Q(A u B) = Q(A) + Q(B) - Q(A n B).
  SphereQuadric q = this->AtlasQuadric[a];
  q += this->AtlasQuadric[b];
  anchors.clear();
  const auto& A = this->Atlas[a];
  const auto& B = this->Atlas[b];
  if (!this->AnyInvaginated[a] && !this->AnyInvaginated[b])
  {
    // No anchors: only the shared cells matter (the same subtractions, in
    // the same order, as below).
    ForEachShared(A, B, [&](Index s) { q -= this->CellQuadric[s]; });
  }
  else
  {
    ForEachInUnion(A, B,
      [&](Index s, bool shared)
      {
        if (this->Invaginated[s])
        {
          anchors.emplace_back(this->Site[s], this->CellArea[s]);
        }
        else if (shared)
        {
          q -= this->CellQuadric[s];
        }
      });
  }
  // Uniform Laplacian over the merged one-ring (Eq. 12).
  Point3 sum{ 0, 0, 0 };
  double sumSquares = 0.0;
  const std::size_t count = mesh.MergedRingSums(a, b, sum, sumSquares);
  AddLaplacian(q, this->Options.Lambda, sum, sumSquares, count);
  Placement p = this->Solve(mesh, q, anchors, a, b);
  const double ratio = mesh.StabilityRatio(a, b);
  const bool absorbed = this->Options.AbsorbSpikes && ratio < this->Options.SpikeThreshold &&
    p.Energy < HUGE_VAL && !this->OnFeature(mesh, a) && !this->OnFeature(mesh, b);
  if (absorbed)
  {
    // The smaller ball, almost inside the larger, is absorbed by it.
    const Sphere& larger =
      mesh.SphereOf(b)[3] > mesh.SphereOf(a)[3] ? mesh.SphereOf(b) : mesh.SphereOf(a);
    p.Target = larger;
    p.Energy = EnergyAt(q, anchors, larger);
  }
  if (this->Options.ClampRadiiToAtlas && p.Energy < HUGE_VAL && p.Target[3] > 0.0)
  {
    this->ClampToAtlas(q, anchors, A, B, p);
  }
  const double cost =
    p.Energy < HUGE_VAL ? std::max(0.0, p.Energy) * this->Weight(ratio, absorbed) : HUGE_VAL;
  return { cost, p.Target };
}

// Distance from `centre` to the nearest site of the union of two Atlases.
double AtlasPolicy::NearestAtlasSite(
  const Point3& centre, const std::vector<Index>& A, const std::vector<Index>& B) const
{
  double nearest = HUGE_VAL;
  for (const auto* atlas : { &A, &B })
  {
    for (Index s : *atlas)
    {
      nearest = std::min(nearest, Distance2(centre, this->Site[s]));
    }
  }
  return std::sqrt(nearest);
}

// No deeper into the surface than the nearest site of the merged Atlas
// (ClampRadiiToAtlas); the energy at the clamped sphere.
void AtlasPolicy::ClampToAtlas(const SphereQuadric& q,
  const std::vector<std::pair<Point3, double>>& anchors, const std::vector<Index>& A,
  const std::vector<Index>& B, Placement& p) const
{
  const double nearest = this->NearestAtlasSite({ p.Target[0], p.Target[1], p.Target[2] }, A, B);
  if (p.Target[3] > nearest)
  {
    p.Target[3] = nearest;
    p.Energy = EnergyAt(q, anchors, p.Target);
  }
}

// The endpoints and the midpoint, cheapest first by the fidelity of the
// merged Atlas, with each one's own radius (0 for feature ones; with
// ClampRadiiToAtlas, no deeper than the merged Atlas' nearest site).
std::array<Sphere, 3> AtlasPolicy::FallbackSpheres(
  const MedialEdgeCollapse& mesh, Index a, Index b) const
{
  const Sphere pa = mesh.SphereOf(a), pb = mesh.SphereOf(b);
  Sphere candidates[3] = { pa, pb,
    { 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2]),
      0.5 * (pa[3] + pb[3]) } };
  if (this->OnFeature(mesh, a) && !this->OnFeature(mesh, b))
  {
    candidates[1] = candidates[2] = pa;
  }
  else if (this->OnFeature(mesh, b) && !this->OnFeature(mesh, a))
  {
    candidates[0] = candidates[2] = pb;
  }
  if (this->Options.ClampRadiiToAtlas)
  {
    for (Sphere& c : candidates)
    {
      c[3] = std::min(
        c[3], this->NearestAtlasSite({ c[0], c[1], c[2] }, this->Atlas[a], this->Atlas[b]));
    }
  }
  SphereQuadric q = this->AtlasQuadric[a];
  q += this->AtlasQuadric[b];
  std::array<int, 3> order{ 0, 1, 2 };
  double energy[3];
  for (int k = 0; k < 3; ++k)
  {
    energy[k] = q.Evaluate(candidates[k]);
  }
  std::sort(order.begin(), order.end(),
    [&energy](int x, int y) { return energy[x] != energy[y] ? energy[x] < energy[y] : x < y; });
  return { candidates[order[0]], candidates[order[1]], candidates[order[2]] };
}

void AtlasPolicy::Merged(MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch)
{
  // Atlas and its quadric: Q(A u B) = Q(A) + Q(B) - Q(A n B).
  auto& atlas = scratch.Indices;
  atlas.clear();
  atlas.reserve(this->Atlas[a].size() + this->Atlas[b].size());
  this->AtlasQuadric[a] += this->AtlasQuadric[b];
  ForEachInUnion(this->Atlas[a], this->Atlas[b],
    [&](Index s, bool shared)
    {
      if (shared && !this->Invaginated[s])
      {
        this->AtlasQuadric[a] -= this->CellQuadric[s];
      }
      atlas.push_back(s);
    });
  this->Atlas[a].swap(atlas); // the old list becomes the next scratch
  std::vector<Index>().swap(this->Atlas[b]);
  this->AnyInvaginated[a] = this->AnyInvaginated[a] || this->AnyInvaginated[b];
  this->UpdateFeature(a);
  if (!this->Clearance.empty())
  {
    // The merged ball's bound: proved for it, or carried over from the two
    // it replaces.
    const Sphere& s = mesh.SphereOf(a);
    const Point3 c{ s[0], s[1], s[2] };
    double value = std::max(this->ClearanceAt(a, c), this->ClearanceAt(b, c));
    if (scratch.ProvenClearance >= 0.0 && scratch.ProvenTarget == s)
    {
      value = std::max(value, scratch.ProvenClearance);
    }
    this->Clearance[a] = { c, value >= 0.0 ? value : -1.0 };
  }
}

// Eq. 17: a feature vertex moves onto its sharp edge with r = 0.
// Feature vertices on one straight edge are collinear: a triangle of three
// of them would have zero area, and a snap can fold a triangle over its
// neighbour.
AtlasPolicy::SnapResult AtlasPolicy::Snap(
  MedialEdgeCollapse& mesh, Index v, bool keepValid, CollapseScratch& scratch)
{
  SphereQuadric q = this->AtlasQuadric[v];
  Point3 sum{ 0, 0, 0 };
  double sumSquares = 0.0;
  for (Index u : mesh.Neighbours(v))
  {
    const Point3 p = mesh.Position(u);
    sum = sum + p;
    sumSquares += Dot(p, p);
  }
  AddLaplacian(q, this->Options.Lambda, sum, sumSquares, mesh.Neighbours(v).size());
  Eigen::Vector3d x;
  if (!SolveQuadric<3>(q, x))
  {
    return SnapResult::NoTarget;
  }
  const Point3 target{ x[0], x[1], x[2] };
  if (!this->NearAtlas(v, target))
  {
    return SnapResult::NoTarget;
  }
  if (keepValid && !mesh.MoveKeepsValid(v, target, scratch))
  {
    return SnapResult::Refused;
  }
  mesh.Move(v, { x[0], x[1], x[2], 0.0 });
  ++this->Snapped;
  return SnapResult::Moved;
}

// The point where the planes of an Atlas's cells meet (with r = 0) is on the
// sharp edge when the cells lie on the two faces along it. Where they lie
// on faces that meet only beyond the part (the flanks of a gear tooth cut
// off by its tip, a chamfer), that point is outside: a snap there would put
// the envelope outside the surface. A zero-radius sphere is a point of the
// envelope, so it must lie on the surface, within the sampling's resolution
// (the size of the Atlas' largest cell) of one of its cells. Measuring from
// the sites instead (twice that size from the nearest one) let a gearwheel
// keep a zero-radius sphere 1.1% of its diagonal outside it.
bool AtlasPolicy::NearAtlas(
  const Point3& target, const std::vector<Index>& A, const std::vector<Index>& B) const
{
  double largestArea = 0.0;
  for (const auto* atlas : { &A, &B })
  {
    for (Index s : *atlas)
    {
      largestArea = std::max(largestArea, this->CellArea[s]);
    }
  }
  const double tolerance = std::sqrt(largestArea);
  for (const auto* atlas : { &A, &B })
  {
    for (Index s : *atlas)
    {
      const double reach = std::sqrt(this->CellReach[s]) + tolerance;
      if (Distance2(this->Site[s], target) > reach * reach)
      {
        continue;
      }
      for (Index i = this->SitePolygonOffsets[s]; i < this->SitePolygonOffsets[s + 1]; ++i)
      {
        // The polygon as a fan of triangles, in the unit frame.
        const Index p = this->SitePolygons[i], first = this->Rvd.Offsets[p],
                    count = this->Rvd.Offsets[p + 1] - first;
        if (count < 3)
        {
          continue;
        }
        const Point3 anchor = this->UnitFrame.To(this->Rvd.Vertices[first]);
        for (Index k = 1; k + 1 < count; ++k)
        {
          const Point3 q = ClosestPointOnTriangle(target, anchor,
            this->UnitFrame.To(this->Rvd.Vertices[first + k]),
            this->UnitFrame.To(this->Rvd.Vertices[first + k + 1]));
          if (Distance2(q, target) <= tolerance * tolerance)
          {
            return true;
          }
        }
      }
    }
  }
  return false;
}

// Eq. 17: every feature vertex onto its sharp edge. First those whose snap
// keeps the mesh valid; then the rest anyway (a feature vertex off its edge
// would spoil the boundary), and the edges around those are collapsed first,
// which removes most of the zero-area or folded triangles they make (the
// others: MedialEdgeCollapse::CollapseFolds).
std::vector<Index> AtlasPolicy::Prepare(MedialEdgeCollapse& mesh)
{
  std::vector<Index> forced;
  if (this->Options.PreserveSharpFeatures)
  {
    CollapseScratch scratch;
    for (std::size_t v = 0; v < mesh.NumberOfVertices(); ++v)
    {
      if (this->Feature[v] &&
        this->Snap(mesh, static_cast<Index>(v), true, scratch) == SnapResult::Refused)
      {
        forced.push_back(static_cast<Index>(v));
      }
    }
    for (Index v : forced)
    {
      this->Snap(mesh, v, false, scratch);
    }
  }
  this->ForcedSnaps = forced.size();
  return forced;
}

// Retries the snap of feature vertices off their edge at and around a.
void AtlasPolicy::AfterCollapse(MedialEdgeCollapse& mesh, Index a, CollapseScratch& scratch)
{
  if (this->Feature[a] && !this->OnFeature(mesh, a))
  {
    this->Snap(mesh, a, true, scratch);
  }
  for (Index u : mesh.Neighbours(a))
  {
    if (this->Feature[u] && !this->OnFeature(mesh, u))
    {
      this->Snap(mesh, u, true, scratch);
    }
  }
}

AtlasMedialMesh AtlasPolicy::Output(const MedialEdgeCollapse& mesh) const
{
  AtlasMedialMesh out;
  std::vector<Index> inputId;
  out.Mesh = mesh.Output(inputId);
  for (Index v : inputId)
  {
    out.AtlasSites.insert(out.AtlasSites.end(), this->Atlas[v].begin(), this->Atlas[v].end());
    out.AtlasOffsets.push_back(static_cast<Index>(out.AtlasSites.size()));
    out.FeatureVertex.push_back(this->Feature[v]);
  }
  return out;
}
} // namespace medialaxis
