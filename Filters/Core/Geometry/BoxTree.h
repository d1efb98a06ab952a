// SPDX-License-Identifier: GPL-3.0-or-later
// A bounding-box hierarchy over extended objects (medial primitives, surface
// triangles) for nearest-object and any-hit queries.
//
// Hand-written rather than nanoflann (KdTree.h indexes points only, while
// primitives have very different extents) or CGAL's AABB tree (its traits
// cannot prune with the signed lower bound that medial primitives allow, and
// every CGAL translation unit costs a minute of build time).
#ifndef medialaxis_BoxTree_h
#define medialaxis_BoxTree_h

#include "Geometry/Types.h"
#include "Support/Prefetch.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace medialaxis
{
struct Box
{
  Point3 Lo{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  Point3 Hi{ -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
    -std::numeric_limits<double>::infinity() };

  void Extend(const Point3& p)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Lo[k] = std::min(this->Lo[k], p[k]);
      this->Hi[k] = std::max(this->Hi[k], p[k]);
    }
  }
  void Extend(const Box& b)
  {
    this->Extend(b.Lo);
    this->Extend(b.Hi);
  }
  bool IsEmpty() const { return !(this->Lo[0] <= this->Hi[0]); }
};

/// Squared distance from p to the box (0 inside).
inline double SquaredDistanceToBox(const Point3& p, const Box& b)
{
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = std::max({ b.Lo[k] - p[k], 0.0, p[k] - b.Hi[k] });
    d2 += d * d;
  }
  return d2;
}

class BoxTree
{
public:
  struct Node
  {
    Box Bounds;
    double Value;        // largest item value below this node (see Build)
    std::uint32_t Begin; // leaf: first entry in Items(); inner: index of the first child
    std::uint32_t Count; // leaf: number of items; inner: 0 (children are Begin, Begin + 1)
  };

  /// Builds the hierarchy over `boxes` (item i has box i). `values`, if given,
  /// holds one number per item; every node keeps the largest of its items'
  /// values (e.g. the largest radius, for signed lower bounds). Leaves hold
  /// at most `leafSize` items. Deterministic.
  void Build(
    const std::vector<Box>& boxes, const std::vector<double>* values = nullptr, int leafSize = 4);

  bool Empty() const { return this->Nodes.empty(); }
  const std::vector<Node>& GetNodes() const { return this->Nodes; }
  const std::vector<std::uint32_t>& GetItems() const { return this->Items; }

  /// Depth-first search, nearer child first. `bound(node)` is a lower bound
  /// of what any item below the node can give; nodes whose bound is not
  /// below `cutoff` are skipped (cutoff may shrink while searching: pass a
  /// reference to the caller's best value). `visit(item)` returns true to
  /// stop the whole search (any-hit queries).
  template <typename BoundFunction, typename VisitFunction>
  void Search(BoundFunction&& bound, VisitFunction&& visit, const double& cutoff) const
  {
    const std::uint32_t* items = this->Items.data();
    this->SearchPositions(
      bound, [&](std::uint32_t position) { return visit(items[position]); }, cutoff);
  }

  /// The same, but `visit` receives the item's position in GetItems() (so
  /// that callers may keep per-item data in that order, for locality).
  template <typename BoundFunction, typename VisitFunction>
  void SearchPositions(BoundFunction&& bound, VisitFunction&& visit, const double& cutoff) const
  {
    this->SearchLeaves(
      bound,
      [&](const Node& leaf)
      {
        for (std::uint32_t i = leaf.Begin; i < leaf.Begin + leaf.Count; ++i)
        {
          if (visit(i))
          {
            return true;
          }
        }
        return false;
      },
      cutoff);
  }

  /// The same, leaf by leaf: `visitLeaf(leaf)` looks at the positions
  /// [leaf.Begin, leaf.Begin + leaf.Count) itself and returns true to stop.
  template <typename BoundFunction, typename LeafFunction>
  void SearchLeaves(BoundFunction&& bound, LeafFunction&& visitLeaf, const double& cutoff) const
  {
    if (this->Nodes.empty())
    {
      return;
    }
    struct Entry
    {
      std::uint32_t Node;
      double Bound;
    };
    Entry stack[128];
    int top = 0;
    const Node* nodes = this->Nodes.data();
    stack[top++] = { 0, bound(nodes[0]) };
    while (top > 0)
    {
      const Entry e = stack[--top];
      if (!(e.Bound < cutoff))
      {
        continue;
      }
      // Down the nearer children without a round trip through the stack;
      // the farther ones are pushed only when they can pass (the cutoff
      // never grows, so a child that fails now fails when popped too). The
      // nodes are visited in the same order as with every child pushed, in
      // fewer, mostly branch-free steps.
      const Node* n = &nodes[e.Node];
      while (n != nullptr && n->Count == 0)
      {
        // The children's records are read when they are visited: requested
        // now, while their bounds are computed (a cache miss per node).
        Prefetch(&nodes[n->Begin]);
        Prefetch(&nodes[n->Begin + 1]);
        const double b0 = bound(nodes[n->Begin]), b1 = bound(nodes[n->Begin + 1]);
        const bool firstNearer = b0 <= b1;
        const std::uint32_t nearer = firstNearer ? n->Begin : n->Begin + 1;
        const double nearBound = firstNearer ? b0 : b1, farBound = firstNearer ? b1 : b0;
        stack[top] = { firstNearer ? n->Begin + 1 : n->Begin, farBound };
        top += farBound < cutoff ? 1 : 0;
        n = nearBound < cutoff ? &nodes[nearer] : nullptr;
      }
      if (n != nullptr && visitLeaf(*n))
      {
        return;
      }
    }
  }

  /// Orders the items inside every leaf by key(item), stably (e.g. to group
  /// them by kind); the hierarchy does not change.
  template <typename KeyFunction>
  void SortLeafItems(KeyFunction&& key)
  {
    for (const Node& n : this->Nodes)
    {
      if (n.Count > 0)
      {
        std::stable_sort(this->Items.begin() + n.Begin, this->Items.begin() + n.Begin + n.Count,
          [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
      }
    }
  }

private:
  void BuildNodes(const std::vector<Box>& boxes, const std::vector<Point3>& centres,
    const std::vector<double>* values, std::uint32_t leafSize);

  std::vector<Node> Nodes;
  std::vector<std::uint32_t> Items;
};
}

#endif
