// SPDX-License-Identifier: GPL-3.0-or-later
// Drawing points uniformly by area: an item picked from the cumulative areas
// of a list (plainly or through a guide table) and a uniform point in a
// triangle. Used for the samples of the surface and of the envelope.
#ifndef medialaxis_AreaSampling_h
#define medialaxis_AreaSampling_h

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace medialaxis
{
// Index of the item whose cumulative range holds u in [0, total).
inline std::size_t PickFromCdf(const std::vector<double>& cdf, double u)
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

// A uniform point of triangle (a, b, c) from two uniform numbers in [0, 1).
inline Point3 PointInTriangle(const Point3& a, const Point3& b, const Point3& c, double u, double v)
{
  const double s = std::sqrt(u);
  return (1.0 - s) * a + (s * (1.0 - v)) * b + (s * v) * c;
}
}

#endif
