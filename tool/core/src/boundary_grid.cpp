#include "boundary_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcook::detail {

BoundaryGrid::BoundaryGrid(const Ring& ring) : ring_(ring) {
  if (ring.empty() || ring.size() > std::numeric_limits<std::uint32_t>::max()) return;
  double max_x = ring[0].x, max_y = ring[0].y;
  min_x_ = max_x, min_y_ = max_y;
  for (Vec2 p : ring) {
    min_x_ = std::min(min_x_, p.x), max_x = std::max(max_x, p.x);
    min_y_ = std::min(min_y_, p.y), max_y = std::max(max_y, p.y);
  }
  // About one vertex per cell if they were spread evenly over the box.
  const double width = max_x - min_x_, height = max_y - min_y_;
  cell_size_ = std::sqrt(width * height / static_cast<double>(ring.size()));
  if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) cell_size_ = std::max(width, height);
  if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) return;  // no grid: scans only
  columns_ = static_cast<int>(std::clamp(width / cell_size_, 0.0, 1023.0)) + 1;
  rows_ = static_cast<int>(std::clamp(height / cell_size_, 0.0, 1023.0)) + 1;
  scale_ = 1.0 / cell_size_;
  if (!std::isfinite(scale_)) return;
  cells_.build(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_),
               [&](auto&& add) {
                 for (std::size_t i = 0; i < ring.size(); ++i) {
                   add(static_cast<std::size_t>(row_of(ring[i].y)) * columns_ +
                           static_cast<std::size_t>(column_of(ring[i].x)),
                       static_cast<std::uint32_t>(i));
                 }
               });
}

int BoundaryGrid::column_of(double x) const {
  return static_cast<int>(std::clamp((x - min_x_) * scale_, 0.0, columns_ - 1.0));
}

int BoundaryGrid::row_of(double y) const {
  return static_cast<int>(std::clamp((y - min_y_) * scale_, 0.0, rows_ - 1.0));
}

}  // namespace hullcook::detail
