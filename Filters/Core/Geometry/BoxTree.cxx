// SPDX-License-Identifier: GPL-3.0-or-later
#include "Geometry/BoxTree.h"

namespace medialaxis
{
void BoxTree::Build(const std::vector<Box>& boxes, const std::vector<double>* values, int leafSize)
{
  this->Nodes.clear();
  this->Items.resize(boxes.size());
  if (boxes.empty())
  {
    return;
  }
  std::vector<Point3> centres(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    this->Items[i] = static_cast<std::uint32_t>(i);
    for (int k = 0; k < 3; ++k)
    {
      centres[i][k] = 0.5 * (boxes[i].Lo[k] + boxes[i].Hi[k]);
    }
  }
  const std::uint32_t leaf = static_cast<std::uint32_t>(std::max(1, leafSize));
  this->Nodes.reserve(2 * boxes.size() / leaf + 2);
  this->Nodes.emplace_back();
  this->BuildNodes(boxes, centres, values, leaf);
}

// Splits at the median of the longest axis of the item centres, without
// recursion: each task fills one reserved node for a range of Items; an inner
// node reserves its two children next to each other.
void BoxTree::BuildNodes(const std::vector<Box>& boxes, const std::vector<Point3>& centres,
  const std::vector<double>* values, std::uint32_t leafSize)
{
  struct Task
  {
    std::uint32_t Node, Begin, End;
  };
  std::vector<Task> tasks{ { 0, 0, static_cast<std::uint32_t>(this->Items.size()) } };
  while (!tasks.empty())
  {
    const Task t = tasks.back();
    tasks.pop_back();
    Node node;
    Box centreBox;
    node.Value = -std::numeric_limits<double>::infinity();
    for (std::uint32_t i = t.Begin; i < t.End; ++i)
    {
      const std::uint32_t item = this->Items[i];
      node.Bounds.Extend(boxes[item]);
      centreBox.Extend(centres[item]);
      if (values)
      {
        node.Value = std::max(node.Value, (*values)[item]);
      }
    }
    if (t.End - t.Begin <= leafSize)
    {
      node.Begin = t.Begin;
      node.Count = t.End - t.Begin;
      this->Nodes[t.Node] = node;
      continue;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
    {
      if (centreBox.Hi[k] - centreBox.Lo[k] > centreBox.Hi[axis] - centreBox.Lo[axis])
      {
        axis = k;
      }
    }
    const std::uint32_t mid = t.Begin + (t.End - t.Begin) / 2;
    // Ties broken by item id: the same input always gives the same tree.
    std::nth_element(this->Items.begin() + t.Begin, this->Items.begin() + mid,
      this->Items.begin() + t.End,
      [&](std::uint32_t a, std::uint32_t b) {
        return centres[a][axis] < centres[b][axis] ||
          (centres[a][axis] == centres[b][axis] && a < b);
      });
    node.Begin = static_cast<std::uint32_t>(this->Nodes.size());
    node.Count = 0;
    this->Nodes[t.Node] = node;
    this->Nodes.emplace_back();
    this->Nodes.emplace_back();
    tasks.push_back({ node.Begin + 1, mid, t.End });
    tasks.push_back({ node.Begin, t.Begin, mid });
  }
}
}
