// SPDX-License-Identifier: GPL-3.0-or-later
// A 3D k-d tree over a vector of points (nanoflann), for k-nearest and
// radius queries. Queries are const and safe to run from several threads.
#ifndef medialaxis_KdTree_h
#define medialaxis_KdTree_h

#include "Geometry/Types.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace medialaxis
{
class KdTree
{
public:
  /// Keeps a reference to `points`: they must outlive the tree.
  explicit KdTree(const std::vector<Point3>& points)
    : Cloud{ &points }
    , Tree(3, Cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16))
  {
    this->Tree.buildIndex();
  }

  /// The k nearest points (fewer if there are fewer points), nearest first.
  void Nearest(const Point3& query, std::size_t k, std::vector<std::uint32_t>& ids,
    std::vector<double>& squaredDistances) const
  {
    k = std::min(k, this->Cloud.Points->size());
    ids.resize(k);
    squaredDistances.resize(k);
    const std::size_t found =
      this->Tree.knnSearch(query.data(), k, ids.data(), squaredDistances.data());
    ids.resize(found);
    squaredDistances.resize(found);
  }

  /// Index of the nearest point.
  std::uint32_t Nearest(const Point3& query) const
  {
    std::uint32_t id = 0;
    double d2 = 0.0;
    this->Tree.knnSearch(query.data(), 1, &id, &d2);
    return id;
  }

  /// Whether some point at squared distance d2 < `squaredRadius` from
  /// `query` has stop(d2) true; the search ends at the first one. Where a
  /// single hit decides (is any point nearer than ...?), this prunes
  /// sooner than finding the nearest point and testing it.
  template <typename Stop>
  bool AnyWithin(const Point3& query, double squaredRadius, Stop&& stop) const
  {
    struct FirstHit
    {
      double Radius;
      Stop* Test;
      bool Found;
      bool full() const { return true; }
      double worstDist() const { return this->Radius; }
      bool addPoint(double d2, std::uint32_t)
      {
        this->Found = d2 < this->Radius && (*this->Test)(d2);
        return !this->Found;
      }
    } result{ squaredRadius, &stop, false };
    this->Tree.findNeighbors(result, query.data(), nanoflann::SearchParams());
    return result.Found;
  }

  /// The squared distance from `query` to the nearest point, unless some
  /// point at squared distance d2 < `squaredRadius` has stop(d2) true: then
  /// the search ends there and returns -1. With stop monotone (true for all
  /// nearer points once true), -1 exactly when AnyWithin would find a hit;
  /// otherwise the nearest distance comes at about the price of that search.
  template <typename Stop>
  double NearestUnless(const Point3& query, double squaredRadius, Stop&& stop) const
  {
    struct NearestOrHit
    {
      double Radius;
      Stop* Test;
      double Best;
      bool Found;
      bool full() const { return true; }
      double worstDist() const { return this->Best; }
      bool addPoint(double d2, std::uint32_t)
      {
        this->Found = d2 < this->Radius && (*this->Test)(d2);
        this->Best = std::min(this->Best, d2);
        return !this->Found;
      }
    } result{ squaredRadius, &stop, std::numeric_limits<double>::infinity(), false };
    this->Tree.findNeighbors(result, query.data(), nanoflann::SearchParams());
    return result.Found ? -1.0 : result.Best;
  }

  /// Points within `radius` (inclusive), with squared distances; sorted by
  /// distance if `sorted`, else in the tree's own (deterministic) order.
  void WithinRadius(const Point3& query, double radius,
    std::vector<std::pair<std::uint32_t, double>>& matches, bool sorted = true) const
  {
    matches.clear();
    this->Tree.radiusSearch(
      query.data(), radius * radius, matches, nanoflann::SearchParams(32, 0.f, sorted));
  }

private:
  struct CloudAdaptor
  {
    const std::vector<Point3>* Points;
    std::size_t kdtree_get_point_count() const { return this->Points->size(); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*this->Points)[i][dim]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const
    {
      return false;
    }
  };
  using Tree_t =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, CloudAdaptor>,
      CloudAdaptor, 3, std::uint32_t>;

  CloudAdaptor Cloud;
  Tree_t Tree;
};
}

#endif
