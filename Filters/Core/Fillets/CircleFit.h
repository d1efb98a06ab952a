// SPDX-License-Identifier: GPL-3.0-or-later
// Least-squares circle through planar points, robust to a minority of
// outliers: the cross-section of a fillet around its rolling-ball centre.
#ifndef medialaxis_CircleFit_h
#define medialaxis_CircleFit_h

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace medialaxis
{
struct FittedCircle
{
  double X = 0.0, Y = 0.0, Radius = 0.0;
  bool Valid = false;
  double InlierFraction = 0.0; // set by FitCircleRobust
  double InlierArc = 0.0;      // radians the inliers span; set by FitCircleRobust
};

/// The arc (radians) that points around centre (x, y) span: the full turn
/// less the largest angular gap between them.
inline double SpannedArc(const std::vector<std::array<double, 2>>& points, double x, double y)
{
  if (points.size() < 2)
  {
    return 0.0;
  }
  std::vector<double> angles;
  angles.reserve(points.size());
  for (const auto& p : points)
  {
    angles.push_back(std::atan2(p[1] - y, p[0] - x));
  }
  std::sort(angles.begin(), angles.end());
  constexpr double Turn = 6.283185307179586;
  double gap = angles.front() + Turn - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i)
  {
    gap = std::max(gap, angles[i] - angles[i - 1]);
  }
  return Turn - gap;
}

/// Algebraic (Kasa) fit as the start, then Gauss-Newton on the geometric
/// distances; points farther than trim * radius from the circle are dropped
/// and the fit repeated. Needs 3 points not on a line.
inline FittedCircle FitCircle(std::vector<std::array<double, 2>> points, double trim)
{
  FittedCircle circle;
  for (int round = 0; round < 3; ++round)
  {
    if (points.size() < 3)
    {
      return FittedCircle();
    }
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (const auto& p : points)
    {
      const Eigen::Vector3d row(p[0], p[1], 1.0);
      normal += row * row.transpose();
      rhs -= row * (p[0] * p[0] + p[1] * p[1]);
    }
    const Eigen::Vector3d def = normal.ldlt().solve(rhs);
    double a = -0.5 * def[0], b = -0.5 * def[1];
    const double r2 = a * a + b * b - def[2];
    if (!(r2 > 0.0) || !std::isfinite(r2))
    {
      return FittedCircle();
    }
    double r = std::sqrt(r2);
    for (int iteration = 0; iteration < 10; ++iteration)
    {
      Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
      Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
      for (const auto& p : points)
      {
        const double dx = p[0] - a, dy = p[1] - b, d = std::hypot(dx, dy);
        if (d == 0.0)
        {
          continue;
        }
        const Eigen::Vector3d j(-dx / d, -dy / d, -1.0);
        jtj += j * j.transpose();
        jtr += j * (d - r);
      }
      const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
      if (!step.allFinite())
      {
        break;
      }
      a += step[0];
      b += step[1];
      r += step[2];
      if (step.norm() < 1e-12 * r)
      {
        break;
      }
    }
    circle = { a, b, r, r > 0.0 && std::isfinite(r) };
    std::vector<std::array<double, 2>> kept;
    for (const auto& p : points)
    {
      if (std::abs(std::hypot(p[0] - a, p[1] - b) - r) <= trim * r)
      {
        kept.push_back(p);
      }
    }
    if (kept.size() == points.size())
    {
      break;
    }
    points.swap(kept);
  }
  return circle;
}

/// Circle through most points: the circle through three of them that most
/// points lie on (within `inlier` times its radius) is refined by FitCircle
/// on those points. Deterministic: all triples of up to 24 points, a fixed
/// pseudo-random set of 2,000 triples otherwise. Points off the circle, e.g.
/// on the flat faces beside a fillet, however many, do not bias it.
inline FittedCircle FitCircleRobust(const std::vector<std::array<double, 2>>& points, double inlier)
{
  const std::size_t n = points.size();
  if (n < 3)
  {
    return FittedCircle();
  }
  auto through = [&](std::size_t i, std::size_t j, std::size_t k, FittedCircle& c)
  {
    const double ax = points[i][0], ay = points[i][1], bx = points[j][0], by = points[j][1],
                 cx = points[k][0], cy = points[k][1];
    const double d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
    if (std::abs(d) < 1e-300)
    {
      return false;
    }
    const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    c.X = (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d;
    c.Y = (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d;
    c.Radius = std::hypot(ax - c.X, ay - c.Y);
    return std::isfinite(c.Radius);
  };
  auto support = [&](const FittedCircle& c)
  {
    std::size_t count = 0;
    for (const auto& p : points)
    {
      count += std::abs(std::hypot(p[0] - c.X, p[1] - c.Y) - c.Radius) <= inlier * c.Radius;
    }
    return count;
  };
  FittedCircle best;
  std::size_t bestSupport = 0;
  auto consider = [&](std::size_t i, std::size_t j, std::size_t k)
  {
    FittedCircle c;
    if (i != j && j != k && i != k && through(i, j, k, c))
    {
      const std::size_t s = support(c);
      if (s > bestSupport)
      {
        best = c;
        bestSupport = s;
      }
    }
  };
  if (n <= 24)
  {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (std::size_t k = j + 1; k < n; ++k)
          consider(i, j, k);
  }
  else
  {
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    auto next = [&]()
    {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<std::size_t>((state >> 33) % n);
    };
    for (int trial = 0; trial < 2000; ++trial)
    {
      const std::size_t i = next(), j = next(), k = next();
      consider(i, j, k);
    }
  }
  if (bestSupport < 3)
  {
    return FittedCircle();
  }
  std::vector<std::array<double, 2>> inliers;
  for (const auto& p : points)
  {
    if (std::abs(std::hypot(p[0] - best.X, p[1] - best.Y) - best.Radius) <= inlier * best.Radius)
    {
      inliers.push_back(p);
    }
  }
  FittedCircle refined = FitCircle(inliers, inlier);
  refined.InlierFraction = static_cast<double>(bestSupport) / static_cast<double>(n);
  refined.InlierArc = refined.Valid ? SpannedArc(inliers, refined.X, refined.Y) : 0.0;
  return refined;
}
}

#endif
