// A uniform grid of axis-aligned boxes, for the referee's "which items may touch this box"
// queries (a region's holes and edges, the pieces of a decomposition): near-linear on the
// thousands of holes and pieces of a 20x20 grid, where pairwise tests would be quadratic.
#pragma once

#include "hullcook/core/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hullcook::stress {

struct Bounds {
  Vec2 low{INFINITY, INFINITY};
  Vec2 high{-INFINITY, -INFINITY};

  void add(Vec2 p) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  }
  void add(const Ring& ring) {
    for (Vec2 p : ring) add(p);
  }
  bool overlaps(const Bounds& other) const {
    return low.x <= other.high.x && other.low.x <= high.x && low.y <= other.high.y &&
           other.low.y <= high.y;
  }
  bool contains(Vec2 p) const {
    return low.x <= p.x && p.x <= high.x && low.y <= p.y && p.y <= high.y;
  }
};

inline Bounds bounds_of(const Ring& ring) {
  Bounds bounds;
  bounds.add(ring);
  return bounds;
}

inline Bounds bounds_of(Vec2 a, Vec2 b) {
  Bounds bounds;
  bounds.add(a);
  bounds.add(b);
  return bounds;
}

class BoxGrid {
 public:
  explicit BoxGrid(std::vector<Bounds> items) : items_(std::move(items)), seen_(items_.size(), 0) {
    for (const Bounds& item : items_) {
      extent_.add(item.low);
      extent_.add(item.high);
    }
    // About sqrt(n) cells a side: as many cells as items.
    const double cells = std::max(1.0, std::sqrt(static_cast<double>(items_.size())));
    const Vec2 size = extent_.high - extent_.low;
    if (!items_.empty() && std::isfinite(size.x) && std::isfinite(size.y)) {
      side_ = std::max(std::max(size.x, size.y) / cells, 1e-300);
      columns_ = std::clamp<std::size_t>(static_cast<std::size_t>(size.x / side_) + 1, 1, 4096);
      rows_ = std::clamp<std::size_t>(static_cast<std::size_t>(size.y / side_) + 1, 1, 4096);
    }
    cells_.resize(columns_ * rows_);
    for (std::size_t i = 0; i < items_.size(); ++i) {
      visit_cells(items_[i], [&](std::size_t cell) { cells_[cell].push_back(i); });
    }
  }

  // Every item whose box overlaps query (each once), in ascending order.
  std::vector<std::size_t> query(const Bounds& query) {
    std::vector<std::size_t> found;
    if (!query.overlaps(extent_)) return found;
    ++stamp_;
    visit_cells(query, [&](std::size_t cell) {
      for (std::size_t i : cells_[cell]) {
        if (seen_[i] != stamp_ && items_[i].overlaps(query)) {
          seen_[i] = stamp_;
          found.push_back(i);
        }
      }
    });
    std::sort(found.begin(), found.end());
    return found;
  }

  const Bounds& item(std::size_t i) const { return items_[i]; }
  std::size_t size() const { return items_.size(); }

 private:
  std::size_t clamp_index(double offset, std::size_t count) const {
    if (!(offset > 0)) return 0;
    return std::min(static_cast<std::size_t>(offset / side_), count - 1);
  }

  template <typename Visit>
  void visit_cells(const Bounds& box, Visit visit) const {
    const std::size_t x0 = clamp_index(box.low.x - extent_.low.x, columns_);
    const std::size_t x1 = clamp_index(box.high.x - extent_.low.x, columns_);
    const std::size_t y0 = clamp_index(box.low.y - extent_.low.y, rows_);
    const std::size_t y1 = clamp_index(box.high.y - extent_.low.y, rows_);
    for (std::size_t y = y0; y <= y1; ++y) {
      for (std::size_t x = x0; x <= x1; ++x) visit(y * columns_ + x);
    }
  }

  std::vector<Bounds> items_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
  Bounds extent_;
  double side_ = 1.0;
  std::size_t columns_ = 1, rows_ = 1;
  std::vector<std::vector<std::size_t>> cells_;
};

}  // namespace hullcook::stress
