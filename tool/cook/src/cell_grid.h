// A uniform grid of square cells, in which the output contract's partition check (contract.cpp)
// files items (edges or points) in the cells they meet (see Buckets).
#pragma once

#include "hullcook/core/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace hullcook::detail {

class CellGrid {
 public:
  CellGrid() = default;

  // About one cell per item over the box [low, high], square cells, at most 1024 a side.
  CellGrid(Vec2 low, Vec2 high, std::size_t items) : low_(low) {
    const double width = std::max(high.x - low.x, 0.0), height = std::max(high.y - low.y, 0.0);
    const double extent = std::max(width, height);
    const double area_per_item =
        std::max(width * height, extent * extent * 1e-6) / double(std::max<std::size_t>(items, 1));
    size_ = std::max({std::sqrt(area_per_item), extent / 1024, 1e-300});
    if (!std::isfinite(size_)) size_ = extent / 1024;
    columns_ = std::clamp(static_cast<int>(std::ceil(width / size_)), 1, 1024);
    rows_ = std::clamp(static_cast<int>(std::ceil(height / size_)), 1, 1024);
  }

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  std::size_t cells() const { return std::size_t(columns_) * std::size_t(rows_); }
  double cell_size() const { return size_; }
  Vec2 low() const { return low_; }

  // The cell holding x (or y), clamped to the grid.
  int column(double x) const { return clamp_index((x - low_.x) / size_, columns_); }
  int row(double y) const { return clamp_index((y - low_.y) / size_, rows_); }
  std::size_t cell(int column, int row) const {
    return std::size_t(row) * std::size_t(columns_) + std::size_t(column);
  }

  // Calls visit(cell) for every cell that the segment ab comes within margin of (and perhaps a few
  // more): per row, the span of x the segment takes in that row's band, widened by margin.
  template <typename Visit>
  void for_each_cell(Vec2 a, Vec2 b, double margin, Visit&& visit) const {
    if (a.y > b.y) std::swap(a, b);
    const int first_row = row(a.y - margin), last_row = row(b.y + margin);
    for (int r = first_row; r <= last_row; ++r) {
      double low = std::min(a.x, b.x), high = std::max(a.x, b.x);
      if (b.y > a.y && first_row != last_row) {
        auto x_at = [&](double y) {
          return a.x + std::clamp((y - a.y) / (b.y - a.y), 0.0, 1.0) * (b.x - a.x);
        };
        const double band_low = low_.y + r * size_ - margin;
        const double band_high = low_.y + (r + 1) * size_ + margin;
        const double u = x_at(band_low), w = x_at(band_high);
        low = std::min(u, w), high = std::max(u, w);
      }
      const int last_column = column(high + margin);
      for (int c = column(low - margin); c <= last_column; ++c) visit(cell(c, r));
    }
  }

 private:
  static int clamp_index(double cells, int count) {
    if (!(cells > 0.0)) return 0;
    if (cells >= count - 1.0) return count - 1;
    return static_cast<int>(cells);
  }

  Vec2 low_{0.0, 0.0};
  double size_ = 1.0;
  int columns_ = 1, rows_ = 1;
};

}  // namespace hullcook::detail
