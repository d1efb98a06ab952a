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
    const Point3& d = shape.Direction[j];
    const auto hit =
      locator.FirstHit(shape.Base[j], d, 0.0, std::numeric_limits<double>::infinity());
    if (hit.Triangle < 0 || !(Dot(TriangleNormal(surface, hit.Triangle), d) > 0.0))
    {
      fit.Error = "the element is not inside the surface (a ray from it enters the surface "
                  "first, or never leaves it: is the surface closed and outward?)";
      return fit;
    }
    maximum[j] = hit.Distance;
    auto known = inscribed.find(shape.Base[j]);
    if (known == inscribed.end())
    {
      known = inscribed.emplace(shape.Base[j], locator.Distance(shape.Base[j])).first;
    }
    initial[j] = std::min(known->second, maximum[j]);
  }

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
  solver.setTolerance(1e-12);
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
