// A k-d tree of points that finds those near a segment: where points crowd a few cells of a
// uniform grid (a star's core, every spike passing by it), the grid's cells test them all.
#pragma once

#include "hullcook/core/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace hullcook::detail {

class PointTree {
 public:
  // points must outlive the tree.
  explicit PointTree(const std::vector<Vec2>& points) : points_(points), order_(points.size()) {
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    if (points.empty()) return;
    nodes_.resize(1);
    build(0, 0, points.size());
  }

  // Calls visit(index) for every point within margin of the segment ab, and perhaps a few more
  // (boxes are widened by slack for the rounding of the test); each once, in no set order.
  template <typename Visit>
  void for_each_near(Vec2 a, Vec2 b, double margin, double slack, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::size_t stack[128];
    std::size_t depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
      const Node& node = nodes_[stack[--depth]];
      if (!segment_meets_box(a, b, node.low - (margin + slack), node.high + (margin + slack))) {
        continue;
      }
      if (node.first_child == 0) {
        for (std::size_t k = node.begin; k < node.end; ++k) visit(order_[k]);
        continue;
      }
      stack[depth++] = node.first_child;
      stack[depth++] = node.first_child + 1;
    }
  }

 private:
  static constexpr std::size_t kLeafSize = 8;

  struct Node {
    Vec2 low, high;  // the box of its points
    std::size_t begin, end;
    std::size_t first_child;  // 0: a leaf (the root is no one's child)
  };

  // Fills the node in slot with the points order_[begin, end), split at the median of their box's
  // longer side: depth at most log2(n / kLeafSize) + 1.
  void build(std::size_t slot, std::size_t begin, std::size_t end) {
    Vec2 low = points_[order_[begin]], high = low;
    for (std::size_t k = begin; k < end; ++k) {
      const Vec2 p = points_[order_[k]];
      low = {std::min(low.x, p.x), std::min(low.y, p.y)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    nodes_[slot] = {low, high, begin, end, 0};
    if (end - begin <= kLeafSize) return;
    const bool by_x = high.x - low.x >= high.y - low.y;
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + std::ptrdiff_t(begin),
                     order_.begin() + std::ptrdiff_t(middle), order_.begin() + std::ptrdiff_t(end),
                     [&](std::size_t i, std::size_t j) {
                       const double p = by_x ? points_[i].x : points_[i].y;
                       const double q = by_x ? points_[j].x : points_[j].y;
                       return p != q ? p < q : i < j;
                     });
    // The children are consecutive, so that a node needs one link.
    const std::size_t children = nodes_.size();
    nodes_.resize(children + 2);
    nodes_[slot].first_child = children;
    build(children, begin, middle);
    build(children + 1, middle, end);
  }

  // Whether the segment ab meets the box [low, high] (closed), by clipping its parameter range.
  static bool segment_meets_box(Vec2 a, Vec2 b, Vec2 low, Vec2 high) {
    double t0 = 0.0, t1 = 1.0;
    const double d[2] = {b.x - a.x, b.y - a.y}, start[2] = {a.x, a.y};
    const double lows[2] = {low.x, low.y}, highs[2] = {high.x, high.y};
    for (int axis = 0; axis < 2; ++axis) {
      if (d[axis] == 0.0) {
        if (start[axis] < lows[axis] || start[axis] > highs[axis]) return false;
        continue;
      }
      double u = (lows[axis] - start[axis]) / d[axis], w = (highs[axis] - start[axis]) / d[axis];
      if (u > w) std::swap(u, w);
      t0 = std::max(t0, u), t1 = std::min(t1, w);
      if (t0 > t1) return false;
    }
    return true;
  }

  const std::vector<Vec2>& points_;
  std::vector<std::size_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace hullcook::detail
