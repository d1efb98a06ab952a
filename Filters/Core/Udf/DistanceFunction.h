// SPDX-License-Identifier: GPL-3.0-or-later
// An unsigned distance given as a function (a closed form, a neural field),
// evaluated on batches of points, and the probes that read distances and
// their gradients from it or from a sampled grid.
#ifndef medialaxis_DistanceFunction_h
#define medialaxis_DistanceFunction_h

#include "Geometry/Types.h"
#include "Udf/RegularField.h"

#include <functional>
#include <string>
#include <vector>

namespace medialaxis
{
/// Fills `distances` (resized by the caller to points.size()) with the
/// unsigned distance at each point. Returns an empty string, or why it
/// failed (which stops the caller). Called from one thread at a time, on
/// batches of at most DistanceBatchSize points: a function that is not
/// thread-safe (Python) is fine, one that evaluates a batch at once (a
/// network) is fast.
using DistanceFunction =
  std::function<std::string(const std::vector<Point3>& points, std::vector<double>& distances)>;

constexpr std::size_t DistanceBatchSize = 1 << 16;

/// Fills field.Values (Origin, Spacing and Dimensions set) with `distance`
/// at every grid point, a few z-slices per call. `progress(fraction)` may
/// return true to stop. Returns an empty string, or the function's error
/// (also "stopped" when progress stopped it).
std::string SampleDistanceFunction(const DistanceFunction& distance, RegularField& field,
  const std::function<bool(double)>& progress = nullptr);

/// Distances and their gradients at many points at once.
class DistanceProbe
{
public:
  virtual ~DistanceProbe() = default;
  /// Fills `values` (resized here) with the distance at every point.
  /// Returns an empty string, or why it failed.
  virtual std::string Values(
    const std::vector<Point3>& points, std::vector<double>& values) const = 0;
  /// Fills `gradients` (resized here) with the distance's gradient at every
  /// point; steps[i] is a length around point i over which the distance is
  /// smooth (a function's central differences use it).
  virtual std::string Gradients(const std::vector<Point3>& points, const std::vector<double>& steps,
    std::vector<Point3>& gradients) const = 0;
  /// Whether the values are the exact distance everywhere (a function),
  /// not an interpolant that is only accurate away from the zero set.
  virtual bool Exact() const = 0;
};

/// A sampled field's trilinear interpolant and its gradient.
class FieldProbe final : public DistanceProbe
{
public:
  explicit FieldProbe(const RegularField& field)
    : Field(field)
  {
  }
  std::string Values(const std::vector<Point3>& points, std::vector<double>& values) const override;
  std::string Gradients(const std::vector<Point3>& points, const std::vector<double>& steps,
    std::vector<Point3>& gradients) const override;
  bool Exact() const override { return false; }

private:
  const RegularField& Field;
};

/// A distance function, its gradient by central differences.
class FunctionProbe final : public DistanceProbe
{
public:
  explicit FunctionProbe(const DistanceFunction& distance)
    : Distance(distance)
  {
  }
  std::string Values(const std::vector<Point3>& points, std::vector<double>& values) const override;
  std::string Gradients(const std::vector<Point3>& points, const std::vector<double>& steps,
    std::vector<Point3>& gradients) const override;
  bool Exact() const override { return true; }

private:
  const DistanceFunction& Distance;
};
}

#endif
