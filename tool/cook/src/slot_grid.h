// A grid of the boxes of a region's slots, to find the slots whose boxes may touch a box.
#pragma once

#include "hullcook/core/polygon.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <vector>

namespace hullcook {

struct SlotBox {
  Vec2 low{std::numeric_limits<double>::infinity()};
  Vec2 high{-std::numeric_limits<double>::infinity()};
  SlotBox() = default;
  explicit SlotBox(const Ring& ring) {
    for (Vec2 p : ring) low = glm::min(low, p), high = glm::max(high, p);
  }
  bool touches(const SlotBox& other) const {
    return low.x <= other.high.x && other.low.x <= high.x && low.y <= other.high.y &&
           other.low.y <= high.y;
  }
};

// Slots listed by the cells of a uniform grid that their boxes overlap, about two cells a slot. A
// slot whose box grows is listed in the cells its box newly overlaps (listing it again in all
// of them made a comb's base, which every tooth merges into, fill every cell with copies: 39 s
// for a comb of 4,096 teeth that took 2.8 s before the grid).
class SlotGrid {
 public:
  SlotGrid(const SlotBox& bounds, std::size_t slots) : low_(bounds.low) {
    const Vec2 extent = glm::max(bounds.high - bounds.low, Vec2{0, 0});
    const double area = std::max(extent.x * extent.y, 1e-300);
    cell_ = std::max({std::sqrt(2 * area / double(slots)), extent.x / 1024, extent.y / 1024});
    if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = std::max({extent.x, extent.y, 1.0});
    columns_ = static_cast<std::size_t>(extent.x / cell_) + 1;
    rows_ = static_cast<std::size_t>(extent.y / cell_) + 1;
    cells_.resize(columns_ * rows_);
  }
  void add(std::size_t slot, const SlotBox& box) {
    const Cells now = cells_of(box);
    const auto [listed, added] = listed_.try_emplace(slot, now);
    const Cells before = added ? Cells{1, 0, 1, 0} : listed->second;  // empty when new
    for (std::size_t r = now.r0; r <= now.r1; ++r) {
      for (std::size_t c = now.c0; c <= now.c1; ++c) {
        if (!(before.r0 <= r && r <= before.r1 && before.c0 <= c && c <= before.c1)) {
          cells_[r * columns_ + c].push_back(slot);
        }
      }
    }
    listed->second = now;
  }
  // Appends the slots listed in the cells box overlaps (some more than once); false when that is
  // a quarter of the cells or more, or more than most listings (then out is left with some of
  // them): a scan of every slot costs less than sorting them (a comb's wide pieces each collected
  // tens of thousands).
  bool collect(const SlotBox& box, std::vector<std::size_t>& out, std::size_t most) const {
    const Cells cells = cells_of(box);
    if (4 * (cells.r1 - cells.r0 + 1) * (cells.c1 - cells.c0 + 1) >= cells_.size()) return false;
    for (std::size_t r = cells.r0; r <= cells.r1; ++r) {
      for (std::size_t c = cells.c0; c <= cells.c1; ++c) {
        const std::vector<std::size_t>& cell = cells_[r * columns_ + c];
        out.insert(out.end(), cell.begin(), cell.end());
        if (out.size() > most) return false;
      }
    }
    return true;
  }

 private:
  struct Cells {
    std::size_t c0, c1, r0, r1;  // inclusive
  };
  std::size_t index(double v, double low, std::size_t count) const {
    const double at = (v - low) / cell_;
    if (!(at > 0)) return 0;
    return std::min(count - 1, static_cast<std::size_t>(std::min(at, 1e18)));
  }
  Cells cells_of(const SlotBox& box) const {
    return {index(box.low.x, low_.x, columns_), index(box.high.x, low_.x, columns_),
            index(box.low.y, low_.y, rows_), index(box.high.y, low_.y, rows_)};
  }

  Vec2 low_;
  double cell_ = 1;
  std::size_t columns_ = 1, rows_ = 1;
  std::vector<std::vector<std::size_t>> cells_;
  std::unordered_map<std::size_t, Cells> listed_;  // per slot listed: the cells it is listed in
};

}  // namespace hullcook
