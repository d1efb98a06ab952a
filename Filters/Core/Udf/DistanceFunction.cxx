// SPDX-License-Identifier: GPL-3.0-or-later
#include "Udf/DistanceFunction.h"

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
// `distance` on all `points`, DistanceBatchSize at a time; every value must
// be a finite number, never negative.
std::string EvaluateInBatches(
  const DistanceFunction& distance, const std::vector<Point3>& points, std::vector<double>& out)
{
  out.resize(points.size());
  std::vector<Point3> batch;
  std::vector<double> values;
  for (std::size_t first = 0; first < points.size(); first += DistanceBatchSize)
  {
    const std::size_t last = std::min(points.size(), first + DistanceBatchSize);
    batch.assign(points.begin() + first, points.begin() + last);
    values.assign(batch.size(), 0.0);
    std::string problem = distance(batch, values);
    if (!problem.empty())
    {
      return problem;
    }
    if (values.size() != batch.size())
    {
      return "the distance function gave " + std::to_string(values.size()) + " values for " +
        std::to_string(batch.size()) + " points";
    }
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      if (!std::isfinite(values[i]))
      {
        return "the distance function gave a value that is not a number at a point";
      }
      out[first + i] = values[i];
    }
  }
  return {};
}
}

std::string SampleDistanceFunction(const DistanceFunction& distance, RegularField& field,
  const std::function<bool(double)>& progress)
{
  const std::size_t slice = static_cast<std::size_t>(field.Dimensions[0]) * field.Dimensions[1];
  const int slices = field.Dimensions[2];
  field.Values.assign(slice * std::max(slices, 0), 0.0);
  if (slice == 0)
  {
    return {};
  }
  const int perCall = static_cast<int>(std::max<std::size_t>(1, DistanceBatchSize / slice));
  std::vector<Point3> points;
  std::vector<double> values;
  for (int first = 0; first < slices; first += perCall)
  {
    const int last = std::min(slices, first + perCall);
    points.clear();
    for (int k = first; k < last; ++k)
    {
      for (int j = 0; j < field.Dimensions[1]; ++j)
      {
        for (int i = 0; i < field.Dimensions[0]; ++i)
        {
          points.push_back(field.PointAt(i, j, k));
        }
      }
    }
    std::string problem = EvaluateInBatches(distance, points, values);
    if (!problem.empty())
    {
      return problem;
    }
    std::copy(values.begin(), values.end(), field.Values.begin() + first * slice);
    if (progress && progress(static_cast<double>(last) / slices))
    {
      return "stopped";
    }
  }
  return {};
}

std::string FieldProbe::Values(const std::vector<Point3>& points, std::vector<double>& values) const
{
  values.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    values[i] = this->Field.Value(points[i]);
  }
  return {};
}

std::string FieldProbe::Gradients(const std::vector<Point3>& points, const std::vector<double>&,
  std::vector<Point3>& gradients) const
{
  gradients.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    gradients[i] = this->Field.Gradient(points[i]);
  }
  return {};
}

std::string FunctionProbe::Values(
  const std::vector<Point3>& points, std::vector<double>& values) const
{
  return EvaluateInBatches(this->Distance, points, values);
}

std::string FunctionProbe::Gradients(const std::vector<Point3>& points,
  const std::vector<double>& steps, std::vector<Point3>& gradients) const
{
  // The six neighbours of every point a step away along the axes, in one
  // evaluation.
  std::vector<Point3> stencil;
  stencil.reserve(6 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (const double side : { 1.0, -1.0 })
      {
        Point3 q = points[i];
        q[a] += side * steps[i];
        stencil.push_back(q);
      }
    }
  }
  std::vector<double> read;
  std::string problem = EvaluateInBatches(this->Distance, stencil, read);
  if (!problem.empty())
  {
    return problem;
  }
  gradients.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const double* r = read.data() + 6 * i;
    for (int a = 0; a < 3; ++a)
    {
      gradients[i][a] = (r[2 * a] - r[2 * a + 1]) / (2.0 * steps[i]);
    }
  }
  return {};
}
}
