// Internal: the cells of a grid in square layers round a cell, for the nearest-vertex searches
// (Eq. 5's closest vertex, and the best vertices of ∂P0 for a hole's cuts).
#pragma once

#include <algorithm>

namespace hullcook::detail {

// Calls visit(x, y) for each cell of the grid (columns x rows) exactly `layer` cells away from
// cell (column, row) in x or y (the cell itself for layer 0). False, visiting nothing, when that
// layer lies wholly outside the grid: every cell has been visited by the layers before.
template <typename Visit>
bool visit_square_layer(int column, int row, int layer, int columns, int rows, Visit&& visit) {
  const int x0 = column - layer, x1 = column + layer, y0 = row - layer, y1 = row + layer;
  if (x0 < 0 && y0 < 0 && x1 >= columns && y1 >= rows) return false;
  const int clipped_x0 = std::max(x0, 0), clipped_x1 = std::min(x1, columns - 1);
  if (y0 >= 0) {
    for (int x = clipped_x0; x <= clipped_x1; ++x) visit(x, y0);
  }
  if (y1 < rows && y1 != y0) {
    for (int x = clipped_x0; x <= clipped_x1; ++x) visit(x, y1);
  }
  for (int y = std::max(y0 + 1, 0); y <= std::min(y1 - 1, rows - 1); ++y) {
    if (x0 >= 0) visit(x0, y);
    if (x1 < columns && x1 != x0) visit(x1, y);
  }
  return true;
}

}  // namespace hullcook::detail
