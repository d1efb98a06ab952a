// SPDX-License-Identifier: GPL-3.0-or-later
#include "AtlasSimplifier.h"

#include "CollapseQueue.h"
#include "MedialMeshQuality.h"
#include "SphereQuadric.h"
#include "Vec3.h"

#include <Eigen/Dense>
#include <LBFGS.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

namespace medialaxis
{
namespace
{
using Sphere = std::array<double, 4>; // centre and radius

// Cost of a collapse and where it puts the merged sphere.
struct Placement
{
  double Energy = HUGE_VAL;
  Sphere Target{};
};

// The model is scaled into the unit box so that lambda, tau and costs mean
// the same for every input; results are mapped back at the end.
struct Normalisation
{
  Point3 Origin{ 0, 0, 0 };
  double Scale = 1.0;
  Point3 To(const Point3& p) const { return this->Scale * (p - this->Origin); }
  Point3 From(const Point3& p) const { return (1.0 / this->Scale) * p + this->Origin; }
};

// Solves the top-left N x N block of the quadric's system A x = B. A is a
// sum of outer products (plus the Laplacian on x, y, z): symmetric positive
// semi-definite, so LDL^T, refusing nearly singular systems.
template <int N>
bool SolveQuadric(const SphereQuadric& q, Eigen::Matrix<double, N, 1>& x)
{
  Eigen::Matrix<double, N, N> A;
  Eigen::Matrix<double, N, 1> B;
  for (int i = 0; i < N; ++i)
  {
    for (int j = 0; j < N; ++j)
    {
      A(i, j) = q.A(i, j);
    }
    B[i] = q.B(i);
  }
  const Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(A);
  const Eigen::Matrix<double, N, 1> pivots = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff()))
  {
    return false;
  }
  x = ldlt.solve(B);
  return x.allFinite();
}

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

// Zero area up to rounding: twice the area at most 1e-10 x the longest edge
// squared (the sine of the largest angle below 1e-10).
bool IsDegenerate(const Point3& p, const Point3& q, const Point3& r)
{
  const double longest = std::max({ Distance2(p, q), Distance2(q, r), Distance2(r, p) });
  return !(Norm(Cross(q - p, r - p)) > 1e-10 * longest);
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

class Simplifier
{
public:
  Simplifier(const AtlasMedialMesh& input, const RestrictedVoronoiDiagram& rvd,
    const std::vector<Point3>& sites, const AtlasSimplifierOptions& options)
    : Options(options)
    , Queue(
        [this](const Candidate& c)
        {
          return this->Alive[c.A] && this->Alive[c.B] && c.VersionA == this->Version[c.A] &&
            c.VersionB == this->Version[c.B];
        })
  {
    this->FoldGuard = options.PreventFolds;
    this->Setup(input, rvd, sites);
  }

  AtlasSimplifierResult Run();
  std::chrono::steady_clock::time_point SetupEnd() const { return this->RunStart; }

private:
  void Setup(const AtlasMedialMesh& input, const RestrictedVoronoiDiagram& rvd,
    const std::vector<Point3>& sites);
  Placement Evaluate(Index a, Index b, std::vector<std::pair<Point3, double>>& anchors) const;
  Placement Solve(const SphereQuadric& q, const std::vector<std::pair<Point3, double>>& anchors,
    Index a, Index b) const;
  double Spike(Index a, Index b) const;
  // Accumulates a neighbour's centre for the uniform Laplacian.
  void AddToRing(Index u, Point3& sum, double& sumSquares) const
  {
    const Point3 p{ this->Spheres[u][0], this->Spheres[u][1], this->Spheres[u][2] };
    sum = sum + p;
    sumSquares += Dot(p, p);
  }
  double Weight(double spike) const;
  bool Collapse(Index a, Index b, const Sphere& target);
  bool CollapseAtFallback(Index a, Index b);
  bool LinkConditionHolds(Index a, Index b) const;
  bool CreatesFold(Index a, Index b, const Point3& newPosition);
  std::size_t FoldsAroundMerged(Index a, Index b, const Point3& newPosition);
  std::size_t CountFolds(
    const std::vector<std::array<Index, 3>>& centre, Index moved, const Point3& movedTo);
  // Moves feature vertex v onto its sharp edge (r = 0); with keepValid, not
  // when that would make a zero-area or folded triangle. True if moved.
  bool Snap(Index v, bool keepValid);
  bool SnapKeepsValid(Index v, const Point3& target);
  // Retries the snap of feature vertices off their edge at and around v.
  void SnapPending(Index v)
  {
    if (this->Feature[v] && !this->OnFeature(v))
    {
      this->Snap(v, true);
    }
    for (Index u : this->Neighbours[v])
    {
      if (this->Feature[u] && !this->OnFeature(u))
      {
        this->Snap(u, true);
      }
    }
  }
  void UpdateFeature(Index v);
  // A feature vertex already on its sharp edge (snapped, radius 0).
  bool OnFeature(Index v) const { return this->Feature[v] && this->Spheres[v][3] == 0.0; }
  void Push(Index a, Index b);
  using Candidate = CollapseQueue<Sphere>::Entry;
  Candidate MakeCandidate(Index a, Index b, std::vector<std::pair<Point3, double>>& anchors) const;
  AtlasMedialMesh Output() const;
  void PushAllEdges();
  bool CollapseUntil(std::size_t target, const std::function<bool(std::size_t)>& progress);

  const AtlasSimplifierOptions& Options;
  Normalisation Frame;
  // Per site.
  std::vector<SphereQuadric> CellQuadric;
  std::vector<double> CellArea;
  std::vector<Point3> Site;
  std::vector<std::uint8_t> Convex, Invaginated;
  // Per vertex.
  std::vector<Sphere> Spheres;
  std::vector<std::vector<Index>> Atlas;
  std::vector<SphereQuadric> AtlasQuadric;    // regular cells of the Atlas, each once
  std::vector<std::vector<Index>> Neighbours; // sorted
  std::vector<std::vector<Index>> VertexFaces;
  std::vector<std::uint32_t> Version;
  std::vector<char> Alive;
  std::vector<char> Feature;
  std::size_t AliveCount = 0;
  // Faces.
  std::vector<std::array<Index, 3>> Faces;
  std::vector<char> FaceAlive;

  CollapseQueue<Sphere> Queue;
  // Scratch buffers, reused to spare allocations on every collapse.
  std::vector<std::pair<Point3, double>> Anchors;
  std::vector<std::pair<std::array<Index, 3>, Index>> FaceKeys;
  std::vector<Index> MergedAway, MergedNeighbours, MergedAtlas;
  std::vector<std::array<Index, 3>> CentreBefore, Outer;
  std::vector<std::array<Index, 4>> EdgeIncidences; // (min, max, apex, centre?)
  std::vector<std::array<Index, 2>> RingPairs, Spokes;
  std::size_t Rejected = 0, Collapses = 0, Snapped = 0, RelaxedCollapses = 0, Merged = 0;
  std::chrono::steady_clock::time_point RunStart;
  bool Relaxed = false;            // the link condition no longer guards collapses
  bool FoldGuard = true;           // collapses may not fold triangles onto each other
  bool FoldsAllowedAtLast = false; // the fold guard was lifted after a stall
  std::size_t FoldingAllowedCollapses = 0, ForcedSnaps = 0;
};

void Simplifier::Setup(const AtlasMedialMesh& input, const RestrictedVoronoiDiagram& rvd,
  const std::vector<Point3>& sites)
{
  // Normalisation from the sites' bounding box (the surface's extent).
  Point3 lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
  if (!sites.empty())
  {
    std::tie(lo, hi) = BoundingBox(sites);
  }
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  this->Frame.Origin = lo;
  this->Frame.Scale = extent > 0.0 ? 1.0 / extent : 1.0;

  // Per-cell quadrics from the RVD polygons (normal and area by Newell's
  // formula: every polygon is planar, a piece of one surface triangle).
  const std::size_t ns = sites.size();
  this->Site.resize(ns);
  for (std::size_t i = 0; i < ns; ++i)
  {
    this->Site[i] = this->Frame.To(sites[i]);
  }
  this->CellQuadric.assign(ns, SphereQuadric());
  this->CellArea.assign(ns, 0.0);
  for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
  {
    const Index site = rvd.PolygonSite[p];
    if (site < 0 || static_cast<std::size_t>(site) >= ns)
    {
      continue;
    }
    Point3 twiceNormal{ 0, 0, 0 };
    const Index first = rvd.Offsets[p], count = rvd.Offsets[p + 1] - first;
    const Point3 anchor = this->Frame.To(rvd.Vertices[first]);
    for (Index k = 1; k + 1 < count; ++k)
    {
      twiceNormal = twiceNormal +
        Cross(this->Frame.To(rvd.Vertices[first + k]) - anchor,
          this->Frame.To(rvd.Vertices[first + k + 1]) - anchor);
    }
    const double area = 0.5 * Norm(twiceNormal);
    if (!(area > 0.0))
    {
      continue;
    }
    const Point3 n = Normalized(twiceNormal);
    this->CellQuadric[site].AddFacet(n, Dot(n, anchor), area);
    this->CellArea[site] += area;
  }
  this->Convex.assign(ns, 0);
  this->Invaginated.assign(ns, 0);
  if (rvd.ConvexFeature.size() == ns)
  {
    this->Convex = rvd.ConvexFeature;
  }
  if (rvd.ConcaveFeature.size() == ns && this->Options.InvaginatedTerm)
  {
    this->Invaginated = rvd.ConcaveFeature;
  }

  // Vertices, Atlases and their quadrics.
  const MedialMesh& mesh = input.Mesh;
  const std::size_t nv = mesh.Centers.size();
  this->Spheres.resize(nv);
  this->Atlas.resize(nv);
  this->AtlasQuadric.assign(nv, SphereQuadric());
  for (std::size_t v = 0; v < nv; ++v)
  {
    const Point3 c = this->Frame.To(mesh.Centers[v]);
    this->Spheres[v] = { c[0], c[1], c[2], mesh.Radii[v] * this->Frame.Scale };
    for (Index k = input.AtlasOffsets[v]; k < input.AtlasOffsets[v + 1]; ++k)
    {
      const Index s = input.AtlasSites[k];
      if (s >= 0 && static_cast<std::size_t>(s) < ns)
      {
        this->Atlas[v].push_back(s);
      }
    }
    std::sort(this->Atlas[v].begin(), this->Atlas[v].end());
    this->Atlas[v].erase(
      std::unique(this->Atlas[v].begin(), this->Atlas[v].end()), this->Atlas[v].end());
    for (Index s : this->Atlas[v])
    {
      if (!this->Invaginated[s])
      {
        this->AtlasQuadric[v] += this->CellQuadric[s];
      }
    }
  }

  // Connectivity.
  this->Neighbours.assign(nv, {});
  this->VertexFaces.assign(nv, {});
  auto link = [this](Index a, Index b)
  {
    this->Neighbours[a].push_back(b);
    this->Neighbours[b].push_back(a);
  };
  for (const auto& e : mesh.Edges)
  {
    link(e[0], e[1]);
  }
  this->Faces = mesh.Faces;
  this->FaceAlive.assign(this->Faces.size(), 1);
  for (std::size_t f = 0; f < this->Faces.size(); ++f)
  {
    const auto& t = this->Faces[f];
    link(t[0], t[1]);
    link(t[1], t[2]);
    link(t[2], t[0]);
    for (Index v : t)
    {
      this->VertexFaces[v].push_back(static_cast<Index>(f));
    }
  }
  for (auto& n : this->Neighbours)
  {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  this->Version.assign(nv, 0);
  this->Alive.assign(nv, 1);
  this->AliveCount = nv;
  this->Feature.assign(nv, 0);
  for (std::size_t v = 0; v < nv; ++v)
  {
    this->UpdateFeature(static_cast<Index>(v));
  }
}

// A feature vertex's Atlas touches a sharp convex edge and no concave one.
void Simplifier::UpdateFeature(Index v)
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

double Simplifier::Spike(Index a, Index b) const
{
  const Sphere &p = this->Spheres[a], &q = this->Spheres[b];
  const double d = Norm(Point3{ p[0] - q[0], p[1] - q[1], p[2] - q[2] });
  if (!(d > 0.0))
  {
    return 0.0;
  }
  return std::max(0.0, d - std::fabs(p[3] - q[3])) / d;
}

double Simplifier::Weight(double spike) const
{
  return 1.0 /
    (1.0 + std::exp(-this->Options.SpikeSharpness * (spike - this->Options.SpikeThreshold)));
}

Placement Simplifier::Solve(const SphereQuadric& q,
  const std::vector<std::pair<Point3, double>>& anchors, Index a, Index b) const
{
  const Sphere& pa = this->Spheres[a];
  const Sphere& pb = this->Spheres[b];
  const Sphere mid{ 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2]),
    0.5 * (pa[3] + pb[3]) };
  auto energyAt = [&](const Sphere& x)
  {
    double e = q.Evaluate(x);
    for (const auto& [site, area] : anchors)
    {
      const double r = Norm(Point3{ x[0], x[1], x[2] } - site) - x[3];
      e += area * r * r;
    }
    return e;
  };
  Placement best;
  auto consider = [&](const Sphere& x)
  {
    if (x[3] < 0.0)
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

  const bool aFeature = this->OnFeature(a), bFeature = this->OnFeature(b);
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

Placement Simplifier::Evaluate(
  Index a, Index b, std::vector<std::pair<Point3, double>>& anchors) const
{
  // Union of the Atlases, each cell once: Q(A u B) = Q(A) + Q(B) - Q(A n B).
  SphereQuadric q = this->AtlasQuadric[a];
  q += this->AtlasQuadric[b];
  anchors.clear();
  const auto& A = this->Atlas[a];
  const auto& B = this->Atlas[b];
  std::size_t i = 0, j = 0;
  while (i < A.size() || j < B.size())
  {
    Index s;
    bool shared = false;
    if (j == B.size() || (i < A.size() && A[i] < B[j]))
    {
      s = A[i++];
    }
    else if (i == A.size() || B[j] < A[i])
    {
      s = B[j++];
    }
    else
    {
      s = A[i];
      ++i;
      ++j;
      shared = true;
    }
    if (this->Invaginated[s])
    {
      anchors.emplace_back(this->Site[s], this->CellArea[s]);
    }
    else if (shared)
    {
      q -= this->CellQuadric[s];
    }
  }
  // Uniform Laplacian over the merged one-ring (Eq. 12).
  Point3 sum{ 0, 0, 0 };
  double sumSquares = 0.0;
  std::size_t count = 0;
  {
    // Both lists are sorted: merge them, shared neighbours once.
    const auto& na = this->Neighbours[a];
    const auto& nb = this->Neighbours[b];
    std::size_t i = 0, j = 0;
    while (i < na.size() || j < nb.size())
    {
      Index u;
      if (j == nb.size() || (i < na.size() && na[i] < nb[j]))
      {
        u = na[i++];
      }
      else if (i == na.size() || nb[j] < na[i])
      {
        u = nb[j++];
      }
      else
      {
        u = na[i++];
        ++j;
      }
      if (u != a && u != b)
      {
        this->AddToRing(u, sum, sumSquares);
        ++count;
      }
    }
  }
  AddLaplacian(q, this->Options.Lambda, sum, sumSquares, count);
  return this->Solve(q, anchors, a, b);
}

Simplifier::Candidate Simplifier::MakeCandidate(
  Index a, Index b, std::vector<std::pair<Point3, double>>& anchors) const
{
  if (a > b)
  {
    std::swap(a, b);
  }
  const Placement p = this->Evaluate(a, b, anchors);
  const double cost =
    p.Energy < HUGE_VAL ? std::max(0.0, p.Energy) * this->Weight(this->Spike(a, b)) : HUGE_VAL;
  return { cost, a, b, this->Version[a], this->Version[b], p.Target };
}

void Simplifier::Push(Index a, Index b)
{
  const Candidate c = this->MakeCandidate(a, b, this->Anchors);
  if (c.Cost < HUGE_VAL)
  {
    this->Queue.Push(c);
  }
}

bool Simplifier::LinkConditionHolds(Index a, Index b) const
{
  // Dey's vertex condition: the common neighbours of a and b must be exactly
  // the apices of faces (a, b, x). With FringeCollapses, where it fails the
  // collapse is still taken when it keeps the Euler characteristic: every
  // extra common neighbour x closes the loop (a, b, x), raising the
  // characteristic by one, and every face pair (a, x, y), (b, x, y) that
  // merges lowers it by one (e.g. the fins of a fringe along a fillet's
  // centre line, where (a, x, y), (b, x, y) and (a, b, x) form a disk).
  Index apices[16];
  std::size_t apexCount = 0;
  for (Index f : this->VertexFaces[a])
  {
    const auto& t = this->Faces[f];
    if (this->FaceAlive[f] && (t[0] == b || t[1] == b || t[2] == b))
    {
      const Index x = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
      if (apexCount < 16)
      {
        apices[apexCount++] = x;
      }
      else
      {
        return false; // an edge in more than 16 faces: too tangled to collapse
                      // safely
      }
    }
  }
  const auto& na = this->Neighbours[a];
  const auto& nb = this->Neighbours[b];
  std::size_t extra = 0;
  std::size_t i = 0, j = 0;
  while (i < na.size() && j < nb.size())
  {
    if (na[i] < nb[j])
    {
      ++i;
    }
    else if (nb[j] < na[i])
    {
      ++j;
    }
    else
    {
      extra += std::find(apices, apices + apexCount, na[i]) == apices + apexCount ? 1 : 0;
      ++i;
      ++j;
    }
  }
  if (extra == 0)
  {
    return true;
  }
  if (!this->Options.FringeCollapses ||
    this->AliveCount <= this->Options.StrictLinkConditionVertexCount)
  {
    return false;
  }
  std::size_t merges = 0;
  for (Index f : this->VertexFaces[b])
  {
    const auto& t = this->Faces[f];
    if (!this->FaceAlive[f] || t[0] == a || t[1] == a || t[2] == a)
    {
      continue;
    }
    const int k = t[0] == b ? 0 : (t[1] == b ? 1 : 2);
    const Index x = t[(k + 1) % 3], y = t[(k + 2) % 3];
    for (Index g : this->VertexFaces[a])
    {
      const auto& u = this->Faces[g];
      if (this->FaceAlive[g] && (u[0] == x || u[1] == x || u[2] == x) &&
        (u[0] == y || u[1] == y || u[2] == y))
      {
        ++merges;
        break;
      }
    }
  }
  return extra == merges;
}

// Merges b into a at `target` if the result stays a valid medial mesh (the
// caller has checked the link condition).
bool Simplifier::Collapse(Index a, Index b, const Sphere& target)
{
  const Point3 newPosition{ target[0], target[1], target[2] };
  auto position = [this](Index v) {
    return Point3{ this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  };
  // Removing an unstable spike edge turns its needle triangles in any
  // direction: the flip test is meaningless there and only guards stable
  // parts of the medial mesh.
  const bool spike = this->Spike(a, b) < this->Options.SpikeThreshold;
  // Faces that survive: no zero area and no flip (for faces that had a
  // well-defined normal). Two faces that become one are merged. With the
  // vertex part of the link condition holding, that only happens when
  // (a, b, x, y) bound a tetrahedral bubble, which the merge removes: the
  // edge part of Dey's link condition is relaxed on purpose, since a bubble
  // in the medial axis of a solid without cavities is always spurious.
  auto& keys = this->FaceKeys;
  keys.clear();
  for (Index v : { a, b })
  {
    for (Index f : this->VertexFaces[v])
    {
      if (!this->FaceAlive[f])
      {
        continue;
      }
      const auto& t = this->Faces[f];
      const bool hasA = t[0] == a || t[1] == a || t[2] == a;
      const bool hasB = t[0] == b || t[1] == b || t[2] == b;
      if (hasA && hasB)
      {
        continue; // vanishes with the edge
      }
      if (v == b && hasA)
      {
        continue; // seen from a
      }
      std::array<Index, 3> after = t;
      Point3 before[3], moved[3];
      for (int k = 0; k < 3; ++k)
      {
        before[k] = position(t[k]);
        moved[k] = (t[k] == a || t[k] == b) ? newPosition : before[k];
        if (after[k] == b)
        {
          after[k] = a;
        }
      }
      const Point3 n0 = Cross(before[1] - before[0], before[2] - before[0]);
      const Point3 n1 = Cross(moved[1] - moved[0], moved[2] - moved[0]);
      const double l0 = std::max({ Distance2(before[0], before[1]), Distance2(before[1], before[2]),
        Distance2(before[2], before[0]) });
      if (IsDegenerate(moved[0], moved[1], moved[2]))
      {
        return false; // would be degenerate
      }
      if (!spike && Norm(n0) > 1e-6 * l0 && Dot(n0, n1) <= 0.0)
      {
        return false; // would flip
      }
      std::sort(after.begin(), after.end());
      keys.emplace_back(after, f);
    }
  }
  std::sort(keys.begin(), keys.end());
  auto& mergedAway = this->MergedAway;
  mergedAway.clear();
  for (std::size_t i = 1; i < keys.size(); ++i)
  {
    if (keys[i].first == keys[i - 1].first)
    {
      mergedAway.push_back(keys[i].second);
    }
  }

  if (this->FoldGuard && this->CreatesFold(a, b, newPosition))
  {
    return false;
  }

  // Apply.
  for (Index f : mergedAway)
  {
    this->FaceAlive[f] = 0;
  }
  this->Merged += mergedAway.size();
  for (Index f : this->VertexFaces[b])
  {
    if (!this->FaceAlive[f])
    {
      continue;
    }
    auto& t = this->Faces[f];
    if (t[0] == a || t[1] == a || t[2] == a)
    {
      this->FaceAlive[f] = 0;
      continue;
    }
    for (Index& v : t)
    {
      v = v == b ? a : v;
    }
    this->VertexFaces[a].push_back(f);
  }
  auto& faces = this->VertexFaces[a];
  faces.erase(
    std::remove_if(faces.begin(), faces.end(), [this](Index f) { return !this->FaceAlive[f]; }),
    faces.end());
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  for (Index u : this->Neighbours[b])
  {
    auto& n = this->Neighbours[u];
    n.erase(std::lower_bound(n.begin(), n.end(), b));
    if (u != a)
    {
      n.insert(std::lower_bound(n.begin(), n.end(), a), a);
      n.erase(std::unique(n.begin(), n.end()), n.end());
    }
  }
  auto& merged = this->MergedNeighbours;
  merged.clear();
  std::set_union(this->Neighbours[a].begin(), this->Neighbours[a].end(),
    this->Neighbours[b].begin(), this->Neighbours[b].end(), std::back_inserter(merged));
  merged.erase(
    std::remove_if(merged.begin(), merged.end(), [a, b](Index u) { return u == a || u == b; }),
    merged.end());
  this->Neighbours[a].swap(merged); // the old list becomes the next scratch
  std::vector<Index>().swap(this->Neighbours[b]);
  std::vector<Index>().swap(this->VertexFaces[b]);

  // Atlas and its quadric: Q(A u B) = Q(A) + Q(B) - Q(A n B).
  auto& atlas = this->MergedAtlas;
  atlas.clear();
  atlas.reserve(this->Atlas[a].size() + this->Atlas[b].size());
  this->AtlasQuadric[a] += this->AtlasQuadric[b];
  {
    const auto& A = this->Atlas[a];
    const auto& B = this->Atlas[b];
    std::size_t i = 0, j = 0;
    while (i < A.size() || j < B.size())
    {
      if (j == B.size() || (i < A.size() && A[i] < B[j]))
      {
        atlas.push_back(A[i++]);
      }
      else if (i == A.size() || B[j] < A[i])
      {
        atlas.push_back(B[j++]);
      }
      else
      {
        if (!this->Invaginated[A[i]])
        {
          this->AtlasQuadric[a] -= this->CellQuadric[A[i]];
        }
        atlas.push_back(A[i]);
        ++i;
        ++j;
      }
    }
  }
  this->Atlas[a].swap(atlas); // the old list becomes the next scratch
  std::vector<Index>().swap(this->Atlas[b]);
  this->Spheres[a] = target;
  this->Alive[b] = 0;
  --this->AliveCount;
  ++this->Version[a];
  ++this->Version[b];
  this->UpdateFeature(a);
  return true;
}

// Folded manifold edges among the edges of the `centre` faces, with the
// faces across them taken from `centre` and this->Outer; vertex `moved` sits
// at `movedTo`.
std::size_t Simplifier::CountFolds(
  const std::vector<std::array<Index, 3>>& centre, Index moved, const Point3& movedTo)
{
  auto position = [&](Index v)
  {
    return v == moved ? movedTo
                      : Point3{ this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  };
  auto& incidences = this->EdgeIncidences;
  incidences.clear();
  auto add = [&incidences](const std::vector<std::array<Index, 3>>& faces, Index isCentre)
  {
    for (const auto& t : faces)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Index u = t[k], v = t[(k + 1) % 3];
        incidences.push_back({ std::min(u, v), std::max(u, v), t[(k + 2) % 3], isCentre });
      }
    }
  };
  add(centre, 1);
  add(this->Outer, 0);
  std::sort(incidences.begin(), incidences.end());
  std::size_t folds = 0;
  for (std::size_t i = 0; i < incidences.size();)
  {
    std::size_t j = i + 1;
    while (j < incidences.size() && incidences[j][0] == incidences[i][0] &&
      incidences[j][1] == incidences[i][1])
    {
      ++j;
    }
    const auto &p = incidences[i], &q = incidences[i + 1];
    if (j - i == 2 && (p[3] || q[3]) &&
      IsFold(position(p[0]), position(p[1]), position(p[2]), position(q[2])))
    {
      ++folds;
    }
    i = j;
  }
  return folds;
}

// Folded edges around a after merging b into it at `newPosition`, from the
// collapse's face keys. Every face around a is then (a, u, v): spokes (a, u)
// lie between two such faces, ring edges (u, v) between one and the faces
// across that do not move. A fast path for the common case (no fold): no
// sorting, and the pre-collapse state is looked at only when needed.
std::size_t Simplifier::FoldsAroundMerged(Index a, Index b, const Point3& newPosition)
{
  auto position = [this](Index v) {
    return Point3{ this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  };
  auto& ring = this->RingPairs;
  ring.clear();
  const auto& keys = this->FaceKeys;
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    if (i > 0 && keys[i].first == keys[i - 1].first)
    {
      continue; // merged away
    }
    const auto& t = keys[i].first;
    ring.push_back(t[0] == a ? std::array<Index, 2>{ t[1], t[2] }
        : t[1] == a          ? std::array<Index, 2>{ t[0], t[2] }
                             : std::array<Index, 2>{ t[0], t[1] });
  }
  // Spoke (a, u) between exactly two faces (a, u, x) and (a, u, y).
  auto& spokes = this->Spokes;
  spokes.clear();
  for (const auto& pair : ring)
  {
    spokes.push_back({ pair[0], pair[1] });
    spokes.push_back({ pair[1], pair[0] });
  }
  std::sort(spokes.begin(), spokes.end());
  std::size_t folds = 0;
  for (std::size_t i = 0; i < spokes.size();)
  {
    std::size_t j = i + 1;
    while (j < spokes.size() && spokes[j][0] == spokes[i][0])
    {
      ++j;
    }
    if (j - i == 2 &&
      IsFold(
        newPosition, position(spokes[i][0]), position(spokes[i][1]), position(spokes[i + 1][1])))
    {
      ++folds;
    }
    i = j;
  }
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    // Ring edge (u, v) between (a, u, v) and the faces across it.
    const Index u = ring[i][0], v = ring[i][1];
    // Scan the shorter face list of the two; stop at a second face (the
    // edge is then non-manifold and cannot fold).
    const auto& candidates = this->VertexFaces[u].size() <= this->VertexFaces[v].size()
      ? this->VertexFaces[u]
      : this->VertexFaces[v];
    std::size_t count = 0;
    Index y = -1;
    for (Index f : candidates)
    {
      if (!this->FaceAlive[f])
      {
        continue;
      }
      const auto& o = this->Faces[f];
      const bool hasU = o[0] == u || o[1] == u || o[2] == u;
      const bool hasV = o[0] == v || o[1] == v || o[2] == v;
      const bool hasAB = o[0] == a || o[1] == a || o[2] == a || o[0] == b || o[1] == b || o[2] == b;
      if (hasU && hasV && !hasAB)
      {
        y = o[0] != u && o[0] != v ? o[0] : (o[1] != u && o[1] != v ? o[1] : o[2]);
        if (++count > 1)
        {
          break;
        }
      }
    }
    if (count == 1 && IsFold(position(u), position(v), newPosition, position(y)))
    {
      ++folds;
    }
  }
  return folds;
}

// Whether merging b into a at `newPosition` folds two triangles onto each
// other that were not folded before. (A face's own normal may turn by less
// than the flip test allows and still fold over its neighbour; and the
// flip test is skipped on spike edges.)
bool Simplifier::CreatesFold(Index a, Index b, const Point3& newPosition)
{
  const std::size_t foldsAfter = this->FoldsAroundMerged(a, b, newPosition);
  if (foldsAfter == 0)
  {
    return false;
  }
  // Rare: were there as many folds before (in a medial mesh given as input)?
  auto has = [](const std::array<Index, 3>& t, Index v)
  { return t[0] == v || t[1] == v || t[2] == v; };
  auto& before = this->CentreBefore;
  before.clear();
  for (Index v : { a, b })
  {
    for (Index f : this->VertexFaces[v])
    {
      const auto& t = this->Faces[f];
      if (this->FaceAlive[f] && !(v == b && has(t, a)))
      {
        before.push_back(t);
      }
    }
  }
  // The faces across the ring edges (those without a or b).
  auto& outer = this->Outer;
  outer.clear();
  for (const auto& t : before)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index u = t[k], v = t[(k + 1) % 3];
      if (u == a || u == b || v == a || v == b)
      {
        continue;
      }
      for (Index f : this->VertexFaces[u])
      {
        const auto& o = this->Faces[f];
        if (this->FaceAlive[f] && has(o, v) && !has(o, a) && !has(o, b))
        {
          std::array<Index, 3> sorted = o;
          std::sort(sorted.begin(), sorted.end());
          outer.push_back(sorted);
        }
      }
    }
  }
  std::sort(outer.begin(), outer.end());
  outer.erase(std::unique(outer.begin(), outer.end()), outer.end());
  return foldsAfter > this->CountFolds(before, -1, newPosition);
}

// When the optimal sphere would break validity: the endpoints and the
// midpoint, cheapest first, with each one's own radius (0 for feature ones).
bool Simplifier::CollapseAtFallback(Index a, Index b)
{
  const Sphere pa = this->Spheres[a], pb = this->Spheres[b];
  Sphere candidates[3] = { pa, pb,
    { 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2]),
      0.5 * (pa[3] + pb[3]) } };
  if (this->OnFeature(a) && !this->OnFeature(b))
  {
    candidates[1] = candidates[2] = pa;
  }
  else if (this->OnFeature(b) && !this->OnFeature(a))
  {
    candidates[0] = candidates[2] = pb;
  }
  // Cheapest by the fidelity of the merged Atlas.
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
  for (int k : order)
  {
    if (this->Collapse(a, b, candidates[k]))
    {
      return true;
    }
  }
  return false;
}

// Eq. 17: a feature vertex moves onto its sharp edge with r = 0.
// Feature vertices on one straight edge are collinear: a triangle of three
// of them would have zero area, and a snap can fold a triangle over its
// neighbour.
bool Simplifier::SnapKeepsValid(Index v, const Point3& target)
{
  auto& faces = this->FaceKeys;
  faces.clear();
  for (Index f : this->VertexFaces[v])
  {
    Point3 p[3];
    for (int k = 0; k < 3; ++k)
    {
      const Index u = this->Faces[f][k];
      p[k] =
        u == v ? target : Point3{ this->Spheres[u][0], this->Spheres[u][1], this->Spheres[u][2] };
    }
    if (IsDegenerate(p[0], p[1], p[2]))
    {
      return false;
    }
    std::array<Index, 3> sorted = this->Faces[f];
    std::sort(sorted.begin(), sorted.end());
    faces.emplace_back(sorted, f);
  }
  std::sort(faces.begin(), faces.end());
  const Point3 current{ this->Spheres[v][0], this->Spheres[v][1], this->Spheres[v][2] };
  return this->FoldsAroundMerged(v, -1, target) <= this->FoldsAroundMerged(v, -1, current);
}

bool Simplifier::Snap(Index v, bool keepValid)
{
  SphereQuadric q = this->AtlasQuadric[v];
  Point3 sum{ 0, 0, 0 };
  double sumSquares = 0.0;
  for (Index u : this->Neighbours[v])
  {
    this->AddToRing(u, sum, sumSquares);
  }
  AddLaplacian(q, this->Options.Lambda, sum, sumSquares, this->Neighbours[v].size());
  Eigen::Vector3d x;
  if (!SolveQuadric<3>(q, x))
  {
    return false;
  }
  const Point3 target{ x[0], x[1], x[2] };
  if (keepValid && !this->SnapKeepsValid(v, target))
  {
    return false;
  }
  this->Spheres[v] = { x[0], x[1], x[2], 0.0 };
  ++this->Snapped;
  return true;
}

void Simplifier::PushAllEdges()
{
  std::vector<std::array<Index, 2>> edges;
  for (std::size_t v = 0; v < this->Spheres.size(); ++v)
  {
    if (!this->Alive[v])
    {
      continue;
    }
    for (Index u : this->Neighbours[v])
    {
      if (static_cast<Index>(v) < u)
      {
        edges.push_back({ static_cast<Index>(v), u });
      }
    }
  }
  // Evaluations are independent: in parallel, each into its own slot.
  std::vector<Candidate> candidates(edges.size());
  tbb::enumerable_thread_specific<std::vector<std::pair<Point3, double>>> scratch;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, edges.size(), 512),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      auto& anchors = scratch.local();
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        candidates[k] = this->MakeCandidate(edges[k][0], edges[k][1], anchors);
      }
    });
  for (const Candidate& c : candidates)
  {
    if (c.Cost < HUGE_VAL)
    {
      this->Queue.Push(c);
    }
  }
}

// Collapses the cheapest valid edges until `target` vertices remain, the
// queue runs dry or the cost limit is reached. Returns false on abort.
bool Simplifier::CollapseUntil(std::size_t target, const std::function<bool(std::size_t)>& progress)
{
  std::size_t sinceReport = 0;
  Candidate c;
  while (this->AliveCount > target && this->Queue.PopCurrent(c))
  {
    if (c.Cost > this->Options.MaximumCost)
    {
      this->Queue.Clear();
      break;
    }
    // The link condition depends on the connectivity alone: checked once,
    // not for every placement tried.
    const bool guarded =
      this->AliveCount <= this->Options.TopologyGuardVertexCount && !this->Relaxed;
    if ((guarded && !this->LinkConditionHolds(c.A, c.B)) ||
      (!this->Collapse(c.A, c.B, c.Target) && !this->CollapseAtFallback(c.A, c.B)))
    {
      ++this->Rejected; // not retried until its neighbourhood changes
      continue;
    }
    ++this->Collapses;
    this->RelaxedCollapses += this->Relaxed ? 1 : 0;
    this->FoldingAllowedCollapses += this->FoldsAllowedAtLast ? 1 : 0;
    this->SnapPending(c.A);
    for (Index u : this->Neighbours[c.A])
    {
      this->Push(c.A, u);
    }
    if (++sinceReport >= 256)
    {
      sinceReport = 0;
      if (!progress(this->AliveCount))
      {
        return false;
      }
    }
  }
  return true;
}

AtlasSimplifierResult Simplifier::Run()
{
  AtlasSimplifierResult result;
  this->RunStart = std::chrono::steady_clock::now();
  const std::size_t nv = this->Spheres.size();
  auto report = [this](double f) { return !this->Options.Progress || this->Options.Progress(f); };

  // Eq. 17: every feature vertex onto its sharp edge. First those whose snap
  // keeps the mesh valid; then the rest anyway (a feature vertex off its
  // edge would spoil the boundary), and the edges around those are collapsed
  // first, which removes most of the zero-area or folded triangles they make.
  std::vector<Index> forced;
  if (this->Options.PreserveSharpFeatures)
  {
    for (std::size_t v = 0; v < nv; ++v)
    {
      if (this->Feature[v] && !this->Snap(static_cast<Index>(v), true))
      {
        forced.push_back(static_cast<Index>(v));
      }
    }
    for (Index v : forced)
    {
      this->Snap(v, false);
    }
  }
  this->ForcedSnaps = forced.size();
  this->PushAllEdges();
  for (Index v : forced)
  {
    for (Index u : this->Neighbours[v])
    {
      Candidate c = this->MakeCandidate(v, u, this->Anchors);
      c.Cost = -1.0; // before any other collapse
      this->Queue.Push(c);
    }
  }
  result.QueueInitialisationSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - this->RunStart).count();
  if (!report(0.1))
  {
    result.Aborted = true;
    return result;
  }

  const std::size_t target = std::max<std::size_t>(1, this->Options.TargetNumberOfVertices);
  const double toRemove = static_cast<double>(nv > target ? nv - target : 1);
  auto progress = [&](std::size_t alive)
  { return report(0.1 + 0.85 * std::min(1.0, static_cast<double>(nv - alive) / toRemove)); };
  if (!this->CollapseUntil(target, progress))
  {
    result.Aborted = true;
    return result;
  }
  // Stalled because every remaining collapse would fold triangles onto each
  // other: where a tube's thin sheets must shrink to a curve, the last
  // strips of sliver triangles cannot collapse otherwise. Go on without the
  // fold guard and count those collapses.
  if (this->AliveCount > target && this->FoldGuard)
  {
    this->FoldGuard = false;
    this->FoldsAllowedAtLast = true;
    this->PushAllEdges();
    if (!this->CollapseUntil(target, progress))
    {
      result.Aborted = true;
      return result;
    }
  }
  // Stalled below the topology guard (no collapse keeps the link condition,
  // as in a contractible but non-collapsible "foam" of sheets): unless the
  // guard is strict, reach the target anyway and count those collapses.
  if (this->AliveCount > target && this->AliveCount <= this->Options.TopologyGuardVertexCount &&
    !this->Options.StrictTopologyGuard)
  {
    this->Relaxed = true;
    this->PushAllEdges();
    if (!this->CollapseUntil(target, progress))
    {
      result.Aborted = true;
      return result;
    }
  }
  result.Medial = this->Output();
  result.ForcedSnaps = this->ForcedSnaps;
  result.Collapses = this->Collapses;
  result.RejectedCollapses = this->Rejected;
  result.RelaxedCollapses = this->RelaxedCollapses;
  result.FoldingAllowedCollapses = this->FoldingAllowedCollapses;
  result.MergedFaces = this->Merged;
  result.SnappedVertices = this->Snapped;
  report(1.0);
  return result;
}

AtlasMedialMesh Simplifier::Output() const
{
  AtlasMedialMesh out;
  std::vector<Index> newId(this->Spheres.size(), -1);
  for (std::size_t v = 0; v < this->Spheres.size(); ++v)
  {
    if (!this->Alive[v])
    {
      continue;
    }
    newId[v] = static_cast<Index>(out.Mesh.Centers.size());
    const Sphere& s = this->Spheres[v];
    out.Mesh.Centers.push_back(this->Frame.From({ s[0], s[1], s[2] }));
    out.Mesh.Radii.push_back(s[3] / this->Frame.Scale);
    out.AtlasSites.insert(out.AtlasSites.end(), this->Atlas[v].begin(), this->Atlas[v].end());
    out.AtlasOffsets.push_back(static_cast<Index>(out.AtlasSites.size()));
    out.FeatureVertex.push_back(this->Feature[v]);
  }
  for (std::size_t f = 0; f < this->Faces.size(); ++f)
  {
    if (this->FaceAlive[f])
    {
      const auto& t = this->Faces[f];
      out.Mesh.Faces.push_back({ newId[t[0]], newId[t[1]], newId[t[2]] });
    }
  }
  for (std::size_t v = 0; v < this->Spheres.size(); ++v)
  {
    if (!this->Alive[v])
    {
      continue;
    }
    for (Index u : this->Neighbours[v])
    {
      if (static_cast<Index>(v) < u)
      {
        out.Mesh.Edges.push_back({ newId[v], newId[u] });
      }
    }
  }
  return out;
}
} // namespace

AtlasSimplifierResult SimplifyMedialAxis(const AtlasMedialMesh& input,
  const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
  const AtlasSimplifierOptions& options)
{
  // Setup (per-cell quadrics, Atlases, connectivity) plus the snapping and
  // evaluation of every edge is the queue initialisation; Run() reports
  // when the latter ends.
  const auto start = std::chrono::steady_clock::now();
  Simplifier simplifier(input, rvd, sites, options);
  AtlasSimplifierResult result = simplifier.Run();
  result.QueueInitialisationSeconds +=
    std::chrono::duration<double>(simplifier.SetupEnd() - start).count();
  return result;
}
} // namespace medialaxis
