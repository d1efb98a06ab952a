// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeletal/PrimitiveFit.h"

#include "Mesh/TriangleAdjacency.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

namespace medialaxis
{
namespace
{
// The template's graph Laplacian (uniform weights): (L r)_j = r_j - mean of
// its neighbours.
Eigen::SparseMatrix<double> Laplacian(const PrimitiveTemplate& shape)
{
  const std::size_t n = shape.Base.size();
  std::vector<std::set<Index>> neighbours(n);
  for (const Triangle& t : shape.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      neighbours[t[k]].insert(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].insert(t[k]);
    }
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t j = 0; j < n; ++j)
  {
    const auto row = static_cast<Eigen::Index>(j);
    entries.emplace_back(row, row, 1.0);
    const double w = neighbours[j].empty() ? 0.0 : 1.0 / static_cast<double>(neighbours[j].size());
    for (Index k : neighbours[j])
    {
      entries.emplace_back(row, static_cast<Eigen::Index>(k), -w);
    }
  }
  Eigen::SparseMatrix<double> L(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

// Where the ray from `base` along unit `direction` first leaves the
// surface; negative when it enters it first or never meets it (the base
// is not inside).
double RayExit(
  const TriangleMesh& surface, const TriangleLocator& locator, const Point3& base, const Point3& d)
{
  const auto hit = locator.FirstHit(base, d, 0.0, std::numeric_limits<double>::infinity());
  if (hit.Triangle < 0 || !(Dot(TriangleNormal(surface, hit.Triangle), d) > 0.0))
  {
    return -1.0;
  }
  return hit.Distance;
}

// Whether the fitted mesh passes the surface by more than `tolerance` at
// the middle of the template points (an edge's or a triangle's): from the
// base points' mean along the directions' normalised mean; with
// `bothWays`, also whether it stops short of it by more than that.
template <std::size_t N>
bool CrossesBetween(const TriangleMesh& surface, const TriangleLocator& locator,
  const PrimitiveTemplate& shape, const std::vector<double>& radius,
  const std::array<Index, N>& points, double tolerance, bool bothWays)
{
  Point3 base{ 0, 0, 0 }, direction{ 0, 0, 0 }, middle{ 0, 0, 0 };
  double meanRadius = 0.0;
  for (Index j : points)
  {
    base = base + (1.0 / N) * shape.Base[j];
    direction = direction + shape.Direction[j];
    middle = middle + (1.0 / N) * (shape.Base[j] + radius[j] * shape.Direction[j]);
    meanRadius += radius[j] / N;
  }
  const double length = Norm(direction);
  if (!(length > 1e-12))
  {
    return false; // opposite directions: no middle to test
  }
  // Passing the surface is judged by the mean radius, which overstates how
  // far the primitive's flat face reaches along the middle ray by 1 / cos
  // of the directions' spread (1.5% at 17 degrees): a split too many only
  // costs time. Stopping short is judged by the face itself, its middle
  // point projected onto the ray, or the overstatement would hide it.
  const Point3 unit = (1.0 / length) * direction;
  const double reach = Dot(middle - base, unit);
  // A ray that grazes the surface, or starts outside it (the middle of a
  // skeletal edge that touches the surface), tells nothing.
  const double exit = RayExit(surface, locator, base, unit);
  return exit >= 0.0 && (meanRadius > exit + tolerance || (bothWays && reach < exit - tolerance));
}

// Splits the marked edges at their middles and every triangle to match
// (red-green: 1, 2 or 3 split edges give 2, 3 or 4 triangles), keeping
// the orientation.
// The new template points are appended in the order of `split`.
void SplitEdges(PrimitiveTemplate& shape, const std::set<std::pair<Index, Index>>& split)
{
  std::map<std::pair<Index, Index>, Index> middle;
  for (const auto& e : split)
  {
    const Point3 d = shape.Direction[e.first] + shape.Direction[e.second];
    middle.emplace(e, static_cast<Index>(shape.Base.size()));
    shape.Base.push_back(0.5 * (shape.Base[e.first] + shape.Base[e.second]));
    shape.Direction.push_back(Normalized(d));
  }
  std::vector<Triangle> finer;
  for (const Triangle& t : shape.Triangles)
  {
    Index m[3]; // the middle of edge (t[k], t[k + 1]), or -1
    int count = 0, first = -1;
    for (int k = 0; k < 3; ++k)
    {
      const auto found = middle.find(std::minmax(t[k], t[(k + 1) % 3]));
      m[k] = found == middle.end() ? -1 : found->second;
      if (m[k] >= 0)
      {
        ++count;
        first = first < 0 ? k : first;
      }
    }
    const Index a = t[0], b = t[1], c = t[2];
    if (count == 0)
    {
      finer.push_back(t);
    }
    else if (count == 3)
    {
      finer.push_back({ a, m[0], m[2] });
      finer.push_back({ b, m[1], m[0] });
      finer.push_back({ c, m[2], m[1] });
      finer.push_back({ m[0], m[1], m[2] });
    }
    else if (count == 1)
    {
      const int k = first;
      finer.push_back({ t[k], m[k], t[(k + 2) % 3] });
      finer.push_back({ m[k], t[(k + 1) % 3], t[(k + 2) % 3] });
    }
    else
    {
      // Two split edges: k is the one not split; the corner between the
      // split ones is cut off, the rest split along a diagonal.
      const int k = m[0] < 0 ? 0 : (m[1] < 0 ? 1 : 2);
      const Index p = t[k], q = t[(k + 1) % 3], r = t[(k + 2) % 3];
      const Index mq = m[(k + 1) % 3], mr = m[(k + 2) % 3]; // on q-r and r-p
      finer.push_back({ mq, r, mr });
      finer.push_back({ p, q, mq });
      finer.push_back({ p, mq, mr });
    }
  }
  shape.Triangles.swap(finer);
}

// The radii from `initial` (each at most its maximum) by the growth and
// active-set iterations described in the header.
FittedPrimitive SolveRadii(const PrimitiveTemplate& shape, std::vector<double> maximum,
  const std::vector<double>& initial, const PrimitiveFitOptions& options)
{
  FittedPrimitive fit;
  const std::size_t n = shape.Base.size();
  const Eigen::SparseMatrix<double> L = Laplacian(shape);
  Eigen::SparseMatrix<double> fixedPart = options.Smoothness * (L.transpose() * L);
  Eigen::SparseMatrix<double> identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  identity.setIdentity();
  fixedPart += options.Expansion * identity;

  Eigen::VectorXd r(static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n; ++j)
  {
    r[static_cast<Eigen::Index>(j)] = initial[j];
  }
  const double scale = *std::max_element(maximum.begin(), maximum.end());
  // The system is well conditioned (the expansion term bounds it below,
  // the Laplacian's spectrum above; the stiff active rows are what the
  // diagonal preconditioner takes care of): conjugate gradients from the
  // last radii converge in a few dozen steps, far cheaper than factorising
  // it anew for each active set.
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
  solver.setTolerance(1e-9);
  for (int progression = 0; progression < options.Progressions; ++progression)
  {
    Eigen::VectorXd target = r;
    for (std::size_t j = 0; j < n; ++j)
    {
      const auto i = static_cast<Eigen::Index>(j);
      target[i] = r[i] + std::clamp(maximum[j] - r[i], 0.0, options.StepFraction * maximum[j]);
    }
    std::vector<std::uint8_t> active(n, 0);
    Eigen::VectorXd next = r;
    for (int iteration = 0; iteration < options.Iterations; ++iteration)
    {
      Eigen::SparseMatrix<double> system = fixedPart;
      Eigen::VectorXd rhs = options.Expansion * target;
      for (std::size_t j = 0; j < n; ++j)
      {
        if (active[j])
        {
          const auto i = static_cast<Eigen::Index>(j);
          system.coeffRef(i, i) += options.Stiffness;
          rhs[i] += options.Stiffness * maximum[j];
        }
      }
      solver.compute(system);
      next = solver.solveWithGuess(rhs, next);
      if (solver.info() != Eigen::Success)
      {
        fit.Error = "the radius system did not converge";
        return fit;
      }
      bool changed = false;
      for (std::size_t j = 0; j < n; ++j)
      {
        // Once active, a direction stays so within the progression.
        if (!active[j] && next[static_cast<Eigen::Index>(j)] > maximum[j])
        {
          active[j] = 1;
          changed = true;
        }
      }
      if (!changed)
      {
        break;
      }
    }
    const double change = (next - r).cwiseAbs().maxCoeff();
    r = next;
    ++fit.Progressions;
    if (change < 1e-5 * scale)
    {
      break;
    }
  }
  fit.Radius.resize(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    fit.Radius[j] = std::clamp(r[static_cast<Eigen::Index>(j)], 0.0, maximum[j]);
  }

  fit.MaximumRadius = std::move(maximum);
  return fit;
}
}

FittedPrimitive FitPrimitive(const TriangleMesh& surface, const TriangleLocator& locator,
  const PrimitiveTemplate& shape, const PrimitiveFitOptions& options)
{
  FittedPrimitive fit;
  const std::size_t n = shape.Base.size();
  if (n == 0)
  {
    fit.Error = "the template has no vertex";
    return fit;
  }
  // r_max: where each ray first leaves the surface. A first crossing into
  // it (a triangle facing the ray), or none, means the base point is not
  // inside a closed surface.
  std::vector<double> maximum(n), initial(n);
  // Templates repeat their base points (a vertex's is one point): the
  // inscribed distance once per point.
  std::map<Point3, double> inscribed;
  for (std::size_t j = 0; j < n; ++j)
  {
    maximum[j] = RayExit(surface, locator, shape.Base[j], shape.Direction[j]);
    if (maximum[j] < 0.0)
    {
      fit.Error = "the element is not inside the surface (a ray from it enters the surface "
                  "first, or never leaves it: is the surface closed and outward?)";
      return fit;
    }
    if (options.ExactRadii)
    {
      continue; // no growth: the inscribed distances are not needed
    }
    auto known = inscribed.find(shape.Base[j]);
    if (known == inscribed.end())
    {
      known = inscribed.emplace(shape.Base[j], locator.Distance(shape.Base[j])).first;
    }
    initial[j] = std::min(known->second, maximum[j]);
  }

  if (options.ExactRadii)
  {
    fit.Radius = maximum;
    fit.MaximumRadius = std::move(maximum);
    return fit;
  }
  return SolveRadii(shape, std::move(maximum), initial, options);
}

FittedPrimitive FitPrimitiveRefined(const TriangleMesh& surface, const TriangleLocator& locator,
  PrimitiveTemplate& shape, const PrimitiveFitOptions& options)
{
  FittedPrimitive fit = FitPrimitive(surface, locator, shape, options);
  RefinePrimitive(surface, locator, shape, fit, options);
  return fit;
}

void RefinePrimitive(const TriangleMesh& surface, const TriangleLocator& locator,
  PrimitiveTemplate& shape, FittedPrimitive& fit, const PrimitiveFitOptions& options)
{
  const std::size_t most = options.RefinementGrowth * shape.Base.size();
  for (int round = 0; round < options.MaximumRefinements && options.RefinementTolerance > 0.0 &&
       !fit.Radius.empty() && shape.Base.size() < most;
       ++round)
  {
    // Triangles a surface point lies deeper than the tolerance under: the
    // nearest one to each such point.
    const TriangleMesh primitive = PrimitiveSurface(shape, fit);
    const TriangleLocator within(primitive);
    Box bounds;
    for (const Point3& p : primitive.Points)
    {
      bounds.Extend(p);
    }
    std::vector<std::uint8_t> under(shape.Triangles.size(), 0);
    auto test = [&](const Point3& x)
    {
      if (SquaredDistanceToBox(x, bounds) == 0.0 && within.Inside(x))
      {
        const auto nearest = within.Closest(x, [](Index) { return true; });
        if (nearest.Distance2 > options.RefinementTolerance * options.RefinementTolerance)
        {
          under[nearest.Triangle] = 1;
        }
      }
    };
    for (const Point3& x : surface.Points)
    {
      test(x);
    }
    for (const Triangle& t : surface.Triangles)
    {
      test((1.0 / 3.0) * (surface.Points[t[0]] + surface.Points[t[1]] + surface.Points[t[2]]));
    }
    std::set<std::pair<Index, Index>> split;
    for (std::size_t f = 0; f < shape.Triangles.size(); ++f)
    {
      const Triangle& t = shape.Triangles[f];
      const bool whole = under[f] ||
        CrossesBetween(surface, locator, shape, fit.Radius,
          std::array<Index, 3>{ t[0], t[1], t[2] }, options.RefinementTolerance,
          options.ExactRadii);
      for (int k = 0; k < 3; ++k)
      {
        const auto edge = std::minmax(t[k], t[(k + 1) % 3]);
        if (whole ||
          (!split.count(edge) &&
            CrossesBetween(surface, locator, shape, fit.Radius,
              std::array<Index, 2>{ edge.first, edge.second }, options.RefinementTolerance,
              options.ExactRadii)))
        {
          split.insert(edge);
        }
      }
    }
    if (split.empty())
    {
      break;
    }
    // The new points start between their edge's radii, the others where
    // they were.
    std::vector<double> maximum = fit.MaximumRadius, initial = fit.Radius;
    PrimitiveTemplate finer = shape;
    SplitEdges(finer, split);
    auto edge = split.begin();
    for (std::size_t j = shape.Base.size(); j < finer.Base.size(); ++j, ++edge)
    {
      const double parents = std::min(fit.Radius[edge->first], fit.Radius[edge->second]);
      const double exit = RayExit(surface, locator, finer.Base[j], finer.Direction[j]);
      // A ray that grazes the surface has no clear exit: the smaller radius
      // of its edge's ends stands for it.
      maximum.push_back(exit < 0.0 ? parents : exit);
      initial.push_back(options.ExactRadii
          ? maximum.back()
          : std::min(0.5 * (fit.Radius[edge->first] + fit.Radius[edge->second]), maximum.back()));
    }
    const int progressions = fit.Progressions;
    FittedPrimitive refined;
    if (options.ExactRadii)
    {
      refined.Radius = std::move(initial);
      refined.MaximumRadius = std::move(maximum);
    }
    else
    {
      // From radii that were settled, the growth can aim at the surface at
      // once (the fixed point the steps of growth lead to): a few rounds.
      PrimitiveFitOptions settle = options;
      settle.StepFraction = 1.0;
      settle.Progressions = std::min(options.Progressions, 3);
      refined = SolveRadii(finer, std::move(maximum), initial, settle);
      if (refined.Radius.empty())
      {
        return;
      }
    }
    shape = std::move(finer);
    fit = std::move(refined);
    fit.Progressions += progressions;
  }
}

TriangleMesh PrimitiveSurface(const PrimitiveTemplate& shape, const FittedPrimitive& fit)
{
  TriangleMesh mesh;
  if (!fit.Radius.empty())
  {
    mesh.Points = PrimitivePoints(shape, fit.Radius);
    mesh.Triangles = shape.Triangles;
  }
  return mesh;
}
}
