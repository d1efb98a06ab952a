// SPDX-License-Identifier: GPL-3.0-or-later
#include "Fitting/EnvelopeFit.h"

#include "Fitting/FitValidityGuard.h"

#include "Envelope/EnvelopeDistance.h"
#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialMeshQuality.h"
#include "Support/Parallel.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
namespace
{
/// A surface point's signed distance F to the envelope, the outward normal
/// at its nearest primitive's tangency point, and the spheres that
/// primitive interpolates there with their weights.
struct Correspondence
{
  double F = 0.0;
  Point3 N{ 0, 0, 1 };
  Index V[3] = { -1, -1, -1 };
  double W[3] = { 0, 0, 0 };
  int Count = 0;
  std::uint32_t Warm = 0; // the nearest primitive, as MedialEnvelope's warm start
};

/// The weights w (w_0 = 1 - the others) with x = sum w_i (c_i + r_i n): the
/// interpolated sphere that touches the tangency point x, by least squares
/// over the primitive's spheres, clamped to the simplex.
void InterpolationWeights(const MedialMesh& mesh, const Point3& x, Correspondence& c)
{
  if (c.Count == 1)
  {
    c.W[0] = 1.0;
    return;
  }
  const auto touch = [&](int i)
  {
    const Index v = c.V[i];
    return mesh.Centers[v] + mesh.Radii[v] * c.N;
  };
  const Point3 base = touch(0);
  const Point3 target = x - base;
  Point3 d[2];
  for (int i = 1; i < c.Count; ++i)
  {
    d[i - 1] = touch(i) - base;
  }
  double w[2] = { 0.0, 0.0 };
  if (c.Count == 2)
  {
    const double dd = Dot(d[0], d[0]);
    w[0] = dd > 0.0 ? Dot(d[0], target) / dd : 0.5;
  }
  else
  {
    const double g11 = Dot(d[0], d[0]), g12 = Dot(d[0], d[1]), g22 = Dot(d[1], d[1]);
    const double det = g11 * g22 - g12 * g12;
    const double b1 = Dot(d[0], target), b2 = Dot(d[1], target);
    if (det > 1e-14 * std::max(g11 * g22, 1e-300))
    {
      w[0] = (g22 * b1 - g12 * b2) / det;
      w[1] = (g11 * b2 - g12 * b1) / det;
    }
    else
    {
      w[0] = w[1] = 1.0 / 3.0;
    }
  }
  double sum = 0.0;
  for (int i = 0; i < c.Count - 1; ++i)
  {
    w[i] = std::max(w[i], 0.0);
    sum += w[i];
  }
  if (sum > 1.0)
  {
    for (int i = 0; i < c.Count - 1; ++i)
    {
      w[i] /= sum;
    }
    sum = 1.0;
  }
  c.W[0] = 1.0 - sum;
  for (int i = 1; i < c.Count; ++i)
  {
    c.W[i] = w[i - 1];
  }
}

/// Correspondences of every point with the envelope of `mesh`. Each search
/// starts from the point's primitive in `previous` (the same connectivity, so
/// the same primitives) or else from the last point's; fixed chunks (simple
/// partitioner) keep the warm starts, and so any tie between primitives, the
/// same at every thread count.
void Measure(const MedialMesh& mesh, const std::vector<Point3>& points, int threads,
  const std::vector<Correspondence>* previous, std::vector<Correspondence>& out)
{
  const MedialEnvelope envelope(mesh);
  out.assign(points.size(), Correspondence());
  RunWithThreads(threads,
    [&]
    {
      tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, points.size(), 256),
        [&](const tbb::blocked_range<std::size_t>& range)
        {
          std::uint32_t warm = MedialEnvelope::NoPrimitive;
          for (std::size_t i = range.begin(); i != range.end(); ++i)
          {
            if (previous)
            {
              warm = (*previous)[i].Warm;
            }
            const MedialEnvelope::Nearest nearest = envelope.SignedDistance(points[i], &warm);
            Correspondence& c = out[i];
            c.Warm = warm;
            c.F = nearest.Distance;
            c.N = nearest.Normal;
            c.Count = envelope.MedialVertices(nearest.Primitive, c.V);
            InterpolationWeights(mesh, points[i] - c.F * c.N, c);
          }
        },
        tbb::simple_partitioner());
    });
}

double Objective(const std::vector<Correspondence>& corr, const std::vector<double>& weights)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < corr.size(); ++i)
  {
    const double w = weights.empty() ? 1.0 : weights[i];
    sum += w * corr[i].F * corr[i].F;
  }
  return sum;
}

/// A sphere reaching out of the surface: G = r - |c - q| > 0 with q the
/// nearest surface point. U, the direction in which the centre moves to
/// draw the ball back, is (c - q) / |c - q|, averaged over the points nearly
/// as near as q (within a quarter of G, weighted by how much nearer): where
/// several points are equally near (a ball nearly concentric with a round
/// part of the surface) the nearest one alone jumps with rounding, and a
/// rounding difference in the input would send a round elsewhere.
struct Overreach
{
  Index V;
  double G;
  Point3 U;
};

/// The ball (c, r)'s overreach from `inside`, the points within `band` of c
/// (any order), or false when it does not reach out: d = c - q for the
/// nearest point q, and the points' sum sorted by id (the tree's order
/// depends on the coordinates' rounding).
bool OverreachFrom(const Point3& c, double r, const Point3& d, const std::vector<Point3>& points,
  std::vector<std::pair<std::uint32_t, double>>& inside, Overreach& o)
{
  const double length = Norm(d);
  const double g = r - length;
  if (g <= 0.0 || length <= 0.0)
  {
    return false;
  }
  const double band = length + 0.25 * g;
  std::sort(inside.begin(), inside.end());
  Point3 u{ 0, 0, 0 };
  for (const auto& [id, squared] : inside)
  {
    const double distance = std::sqrt(squared);
    if (distance > 0.0 && distance < band)
    {
      u = u + ((band - distance) / distance) * (c - points[id]);
    }
  }
  const double norm = Norm(u);
  o.G = g;
  o.U = norm > 0.0 ? (1.0 / norm) * u : (1.0 / length) * d;
  return true;
}

/// One radius search per ball: a ball reaches out only past points nearer
/// than its radius, and its band lies within that, so the points within the
/// radius give both the nearest point and the band (half the time of a
/// nearest search and a band search, 0.055 -> 0.027 s per round on the
/// kitten at 50,000 samples). The searches with the nearest and the band
/// are kept for the cases rounding could decide differently (a near tie for
/// the nearest point, a point within rounding of the band's edge, which the
/// tree's pruning may drop): then the result is theirs, bit for bit.
void MeasureOverreach(const MedialMesh& mesh, const KdTree& tree, const std::vector<Point3>& points,
  const std::vector<Index>& unknown, int threads, std::vector<Overreach>& out)
{
  constexpr double margin = 1e-9; // relative; rounding is below 1e-15
  const std::size_t nv = mesh.NumberOfVertices();
  std::vector<Overreach> all(nv, Overreach{ -1, 0.0, { 0, 0, 0 } });
  RunWithThreads(threads,
    [&]
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 256),
        [&](const tbb::blocked_range<std::size_t>& range)
        {
          std::vector<std::pair<std::uint32_t, double>> inside;
          for (std::size_t v = range.begin(); v != range.end(); ++v)
          {
            if (unknown[v] < 0)
            {
              continue;
            }
            const Point3& c = mesh.Centers[v];
            const double r = mesh.Radii[v];
            tree.WithinRadius(c, (1.0 + margin) * r, inside, false);
            if (inside.empty())
            {
              continue; // no point nearer than r (by a margin): no overreach
            }
            double nearest2 = std::numeric_limits<double>::infinity(), second2 = nearest2;
            std::uint32_t nearest = 0;
            for (const auto& [id, squared] : inside)
            {
              if (squared < nearest2)
              {
                second2 = nearest2;
                nearest2 = squared;
                nearest = id;
              }
              else if (squared < second2)
              {
                second2 = squared;
              }
            }
            const double length = std::sqrt(nearest2);
            const double band = length + 0.25 * (r - length);
            const double band2 = band * band;
            const bool nearTie = second2 <= (1.0 + margin) * nearest2;
            const bool nearEdge = std::any_of(inside.begin(), inside.end(),
              [&](const std::pair<std::uint32_t, double>& m)
              { return std::abs(m.second - band2) <= margin * band2; });
            Overreach o{ static_cast<Index>(v), 0.0, { 0, 0, 0 } };
            if (nearTie || nearEdge)
            {
              const Point3 d = c - points[tree.Nearest(c)];
              const double g = r - Norm(d);
              tree.WithinRadius(c, Norm(d) + 0.25 * g, inside, false);
              if (OverreachFrom(c, r, d, points, inside, o))
              {
                all[v] = o;
              }
              continue;
            }
            inside.erase(
              std::remove_if(inside.begin(), inside.end(),
                [band2](const std::pair<std::uint32_t, double>& m) { return !(m.second < band2); }),
              inside.end());
            if (OverreachFrom(c, r, c - points[nearest], points, inside, o))
            {
              all[v] = o;
            }
          }
        });
    });
  out.clear();
  for (const Overreach& o : all)
  {
    if (o.V >= 0)
    {
      out.push_back(o);
    }
  }
}

/// A spike edge: H = |r_a - r_b| - (1 - t) |c_a - c_b| > 0, how far the
/// smaller ball falls short of sticking out of the larger one by the
/// fraction t of their distance (SpikeClearance). dH/dc_a = -(1 - t) U, dH/dc_b = (1 - t) U
/// with U = (c_a - c_b) / |c_a - c_b|, dH/dr_a = S, dH/dr_b = -S with S the
/// sign of r_a - r_b.
struct SpikeDeficit
{
  Index A, B;
  double H;
  Point3 U;
  double S;
};

void MeasureSpikes(const MedialMesh& mesh, const std::vector<std::array<Index, 2>>& edges,
  const std::vector<Index>& unknown, double clearance, std::vector<SpikeDeficit>& out)
{
  out.clear();
  if (clearance <= 0.0)
  {
    return;
  }
  for (const auto& e : edges)
  {
    if (unknown[e[0]] < 0 && unknown[e[1]] < 0)
    {
      continue;
    }
    const Point3 d = mesh.Centers[e[0]] - mesh.Centers[e[1]];
    const double length = Norm(d);
    const double dr = mesh.Radii[e[0]] - mesh.Radii[e[1]];
    const double h = std::abs(dr) - (1.0 - clearance) * length;
    if (h > 0.0 && length > 0.0)
    {
      out.push_back({ e[0], e[1], h, (1.0 / length) * d, dr >= 0.0 ? 1.0 : -1.0 });
    }
  }
}

double SpikeObjective(const std::vector<SpikeDeficit>& spikes, double weight)
{
  double sum = 0.0;
  for (const SpikeDeficit& s : spikes)
  {
    sum += weight * s.H * s.H;
  }
  return sum;
}

double OverreachObjective(const std::vector<Overreach>& over, double weight)
{
  double sum = 0.0;
  for (const Overreach& o : over)
  {
    sum += weight * o.G * o.G;
  }
  return sum;
}

void Statistics(const std::vector<Correspondence>& corr, double& rms, double& maximum)
{
  double sum = 0.0;
  maximum = 0.0;
  for (const Correspondence& c : corr)
  {
    sum += c.F * c.F;
    maximum = std::max(maximum, std::abs(c.F));
  }
  rms = corr.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(corr.size()));
}

/// The sparsity of the normal equations: per free vertex, itself and its
/// free neighbours (sorted), in compressed rows.
struct BlockPattern
{
  std::vector<Index> Unknown;           // vertex -> free index, or -1
  std::vector<std::uint8_t> RadiusOnly; // per free index
  std::vector<Index> RowStart{ 0 };
  std::vector<Index> Columns;

  Index Find(Index row, Index column) const
  {
    const auto first = this->Columns.begin() + this->RowStart[row];
    const auto last = this->Columns.begin() + this->RowStart[row + 1];
    return static_cast<Index>(std::lower_bound(first, last, column) - this->Columns.begin());
  }
};

BlockPattern MakePattern(const MedialMesh& mesh, const std::vector<std::array<Index, 2>>& edges,
  const std::vector<SphereFreedom>& freedom)
{
  BlockPattern pattern;
  const std::size_t nv = mesh.NumberOfVertices();
  pattern.Unknown.assign(nv, -1);
  Index free = 0;
  for (std::size_t v = 0; v < nv; ++v)
  {
    const SphereFreedom f = freedom.empty() ? SphereFreedom::Free : freedom[v];
    if (f != SphereFreedom::Fixed)
    {
      pattern.Unknown[v] = free++;
      pattern.RadiusOnly.push_back(f == SphereFreedom::RadiusOnly ? 1 : 0);
    }
  }
  std::vector<std::vector<Index>> rows(static_cast<std::size_t>(free));
  for (Index u = 0; u < free; ++u)
  {
    rows[u].push_back(u);
  }
  for (const auto& e : edges)
  {
    const Index a = pattern.Unknown[e[0]], b = pattern.Unknown[e[1]];
    if (a >= 0 && b >= 0)
    {
      rows[a].push_back(b);
      rows[b].push_back(a);
    }
  }
  for (auto& row : rows)
  {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    pattern.Columns.insert(pattern.Columns.end(), row.begin(), row.end());
    pattern.RowStart.push_back(static_cast<Index>(pattern.Columns.size()));
  }
  return pattern;
}

/// Per vertex: the largest move per round (StepLimit x mean edge length, or
/// the radius for a vertex without edges).
std::vector<double> StepLimits(
  const MedialMesh& mesh, const std::vector<std::array<Index, 2>>& edges, double fraction)
{
  const std::size_t nv = mesh.NumberOfVertices();
  std::vector<double> sum(nv, 0.0);
  std::vector<int> count(nv, 0);
  for (const auto& e : edges)
  {
    const double length = std::sqrt(Distance2(mesh.Centers[e[0]], mesh.Centers[e[1]]));
    for (Index v : e)
    {
      sum[v] += length;
      ++count[v];
    }
  }
  std::vector<double> limit(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    limit[v] = fraction * (count[v] > 0 ? sum[v] / count[v] : mesh.Radii[v]);
  }
  return limit;
}

/// The normal equations of sum w_i (F_i + J_i delta)^2: 4 x 4 blocks in the
/// pattern's order, and the right-hand side -J^T W F.
void Assemble(const std::vector<Correspondence>& corr, const std::vector<double>& weights,
  const BlockPattern& pattern, std::vector<double>& blocks, Eigen::VectorXd& rhs)
{
  const Index free = static_cast<Index>(pattern.RowStart.size()) - 1;
  blocks.assign(pattern.Columns.size() * 16, 0.0);
  rhs = Eigen::VectorXd::Zero(4 * free);
  for (std::size_t i = 0; i < corr.size(); ++i)
  {
    const Correspondence& c = corr[i];
    const double a = weights.empty() ? 1.0 : weights[i];
    // dF/d(c, r) of sphere s = -w_s (n, 1).
    const double g[4] = { c.N[0], c.N[1], c.N[2], 1.0 };
    for (int s = 0; s < c.Count; ++s)
    {
      const Index us = pattern.Unknown[c.V[s]];
      if (us < 0)
      {
        continue;
      }
      for (int k = 0; k < 4; ++k)
      {
        rhs[4 * us + k] += a * c.F * c.W[s] * g[k];
      }
      for (int t = 0; t < c.Count; ++t)
      {
        const Index ut = pattern.Unknown[c.V[t]];
        if (ut < 0)
        {
          continue;
        }
        double* block = &blocks[16 * pattern.Find(us, ut)];
        const double ww = a * c.W[s] * c.W[t];
        for (int k = 0; k < 4; ++k)
        {
          for (int l = 0; l < 4; ++l)
          {
            block[4 * k + l] += ww * g[k] * g[l];
          }
        }
      }
    }
  }
}

/// Adds weight * G^2 per overreaching sphere, dG/d(c, r) = (-U, 1).
void AssembleOverreach(const std::vector<Overreach>& over, double weight,
  const BlockPattern& pattern, std::vector<double>& blocks, Eigen::VectorXd& rhs)
{
  for (const Overreach& o : over)
  {
    const Index u = pattern.Unknown[o.V];
    const double g[4] = { -o.U[0], -o.U[1], -o.U[2], 1.0 };
    double* block = &blocks[16 * pattern.Find(u, u)];
    for (int k = 0; k < 4; ++k)
    {
      rhs[4 * u + k] -= weight * o.G * g[k];
      for (int l = 0; l < 4; ++l)
      {
        block[4 * k + l] += weight * g[k] * g[l];
      }
    }
  }
}

/// Adds weight * H^2 per spike edge.
void AssembleSpikes(const std::vector<SpikeDeficit>& spikes, double weight,
  const BlockPattern& pattern, double clearance, std::vector<double>& blocks, Eigen::VectorXd& rhs)
{
  for (const SpikeDeficit& s : spikes)
  {
    const Index u[2] = { pattern.Unknown[s.A], pattern.Unknown[s.B] };
    const double k = 1.0 - clearance;
    const double g[2][4] = { { -k * s.U[0], -k * s.U[1], -k * s.U[2], s.S },
      { k * s.U[0], k * s.U[1], k * s.U[2], -s.S } };
    for (int i = 0; i < 2; ++i)
    {
      if (u[i] < 0)
      {
        continue;
      }
      for (int m = 0; m < 4; ++m)
      {
        rhs[4 * u[i] + m] -= weight * s.H * g[i][m];
      }
      for (int j = 0; j < 2; ++j)
      {
        if (u[j] < 0)
        {
          continue;
        }
        double* block = &blocks[16 * pattern.Find(u[i], u[j])];
        for (int m = 0; m < 4; ++m)
        {
          for (int n = 0; n < 4; ++n)
          {
            block[4 * m + n] += weight * g[i][m] * g[j][n];
          }
        }
      }
    }
  }
}

/// (A + damping (diag A + floor)) delta = rhs, approximately.
bool Solve(const BlockPattern& pattern, const std::vector<double>& blocks,
  const Eigen::VectorXd& rhs, double damping, double floor, Eigen::VectorXd& delta)
{
  const Index free = static_cast<Index>(pattern.RowStart.size()) - 1;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(blocks.size());
  for (Index u = 0; u < free; ++u)
  {
    for (Index j = pattern.RowStart[u]; j < pattern.RowStart[u + 1]; ++j)
    {
      const Index w = pattern.Columns[j];
      const double* block = &blocks[16 * j];
      for (int k = 0; k < 4; ++k)
      {
        for (int l = 0; l < 4; ++l)
        {
          double value = block[4 * k + l];
          if (u == w && k == l)
          {
            value += damping * (value + floor);
            if (k < 3 && pattern.RadiusOnly[u])
            {
              value += 1e12 * floor; // the centre stays
            }
          }
          if (value != 0.0)
          {
            triplets.emplace_back(static_cast<int>(4 * u + k), static_cast<int>(4 * w + l), value);
          }
        }
      }
    }
  }
  Eigen::SparseMatrix<double> matrix(4 * free, 4 * free);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  // Conjugate gradients: the damped system is well conditioned, and a
  // Levenberg-Marquardt step needs no exact solve (a sparse Cholesky
  // factorisation costs ten times more on 5,000 spheres; a relative
  // residual of 1e-3 fits as closely as 1e-6).
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
  solver.setMaxIterations(30);
  solver.setTolerance(1e-3);
  solver.compute(matrix);
  if (solver.info() != Eigen::Success)
  {
    return false;
  }
  delta = solver.solve(rhs);
  return delta.allFinite();
}
}

EnvelopeFitResult FitMedialEnvelope(MedialMesh& mesh, const FitTarget& target,
  const std::vector<SphereFreedom>& freedom, const EnvelopeFitOptions& options)
{
  const std::vector<Point3>& points = target.Points;
  const std::vector<double>& weights = target.Weights;
  EnvelopeFitResult result;
  if (mesh.NumberOfVertices() == 0 || points.empty())
  {
    return result;
  }
  const std::vector<std::array<Index, 2>> edges = AllEdges(mesh);
  const BlockPattern pattern = MakePattern(mesh, edges, freedom);
  const std::vector<double> limit = StepLimits(mesh, edges, options.StepLimit);
  const Index free = static_cast<Index>(pattern.RowStart.size()) - 1;
  const ValidityGuard guard(mesh, edges, options.SpikeThreshold, options.FoldAngle);
  std::vector<Correspondence> corr, trial;
  Measure(mesh, points, options.NumberOfThreads, nullptr, corr);
  const std::vector<Point3>& surface = target.Surface.empty() ? points : target.Surface;
  const KdTree tree(surface);
  double totalWeight = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    totalWeight += weights.empty() ? 1.0 : weights[i];
  }
  const double overreachWeight =
    options.OverreachWeight * totalWeight / static_cast<double>(mesh.NumberOfVertices());
  std::vector<Overreach> over, trialOver;
  MeasureOverreach(mesh, tree, surface, pattern.Unknown, options.NumberOfThreads, over);
  const double clearance = options.SpikeRepairWeight > 0.0 ? options.SpikeClearance : 0.0;
  const double spikeWeight = options.SpikeRepairWeight * overreachWeight;
  std::vector<SpikeDeficit> spikes, trialSpikes;
  MeasureSpikes(mesh, edges, pattern.Unknown, clearance, spikes);
  double objective = Objective(corr, weights) + OverreachObjective(over, overreachWeight) +
    SpikeObjective(spikes, spikeWeight);
  Statistics(corr, result.InitialRms, result.InitialMaximum);
  double damping = options.Damping;
  const double minimumDamping = 0.1 * damping;
  // The normal equations at the current correspondences, rebuilt after each
  // accepted round; a rejected round only raises the damping.
  std::vector<double> blocks;
  Eigen::VectorXd rhs;
  double floor = 0.0;
  bool assemble = true;
  for (int round = 0; round < options.Iterations && free > 0; ++round)
  {
    if (options.Progress && !options.Progress(static_cast<double>(round) / options.Iterations))
    {
      result.Aborted = true;
      break;
    }
    if (assemble)
    {
      Assemble(corr, weights, pattern, blocks, rhs);
      AssembleOverreach(over, overreachWeight, pattern, blocks, rhs);
      AssembleSpikes(spikes, spikeWeight, pattern, clearance, blocks, rhs);
      double diagonalSum = 0.0;
      for (Index u = 0; u < free; ++u)
      {
        const double* block = &blocks[16 * pattern.Find(u, u)];
        diagonalSum += block[0] + block[5] + block[10] + block[15];
      }
      floor = diagonalSum / static_cast<double>(4 * free) + 1e-300;
      assemble = false;
    }
    Eigen::VectorXd delta;
    if (!Solve(pattern, blocks, rhs, damping, floor, delta))
    {
      damping *= 10.0;
      ++result.RejectedRounds;
      continue;
    }
    MedialMesh candidate = mesh;
    for (std::size_t v = 0; v < mesh.NumberOfVertices(); ++v)
    {
      const Index u = pattern.Unknown[v];
      if (u < 0)
      {
        continue;
      }
      Point3 dc{ delta[4 * u], delta[4 * u + 1], delta[4 * u + 2] };
      if (pattern.RadiusOnly[u])
      {
        dc = Point3{ 0, 0, 0 }; // (moved by the stiffness of Solve by far less)
      }
      const double dr = delta[4 * u + 3];
      const double length = std::max(Norm(dc), std::abs(dr));
      const double shrink = length > limit[v] ? limit[v] / length : 1.0;
      candidate.Centers[v] = mesh.Centers[v] + shrink * dc;
      candidate.Radii[v] = std::max(0.0, mesh.Radii[v] + shrink * dr);
    }
    guard.Shorten(mesh, candidate);
    Measure(candidate, points, options.NumberOfThreads, &corr, trial);
    MeasureOverreach(candidate, tree, surface, pattern.Unknown, options.NumberOfThreads, trialOver);
    MeasureSpikes(candidate, edges, pattern.Unknown, clearance, trialSpikes);
    const double value = Objective(trial, weights) +
      OverreachObjective(trialOver, overreachWeight) + SpikeObjective(trialSpikes, spikeWeight);
    if (value < objective)
    {
      const bool converged = value > (1.0 - options.Convergence) * objective;
      objective = value;
      mesh = std::move(candidate);
      corr.swap(trial);
      over.swap(trialOver);
      spikes.swap(trialSpikes);
      damping = std::max(damping / 3.0, minimumDamping);
      assemble = true;
      ++result.AcceptedRounds;
      if (converged)
      {
        break;
      }
    }
    else
    {
      damping *= 4.0;
      ++result.RejectedRounds;
    }
  }
  Statistics(corr, result.FinalRms, result.FinalMaximum);
  return result;
}
}
