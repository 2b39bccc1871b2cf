// Uniform grids (`--grid WxH --margin M --spacing S`): a sheet or tileset cut into cells, each
// cell one asset.
#pragma once

#include "hullcook/cook/cook.h"
#include "hullcook/trace/trace.h"

#include <string>
#include <vector>

namespace hullcook {

struct GridCell {
  int x = 0, y = 0;           // [px] top left corner in the sheet
  int width = 0, height = 0;  // [px]
  std::size_t index = 0;      // row-major, as Tiled numbers tiles: row * columns + column
};

// The whole cells of grid in a width x height image: the first at (margin, margin), each next
// one a cell and the spacing further, as long as it lies inside the image. Row-major.
std::vector<GridCell> grid_cells(int width, int height, const Grid& grid);

// The pixels of cell (inside image) as an image of their own.
AlphaImage crop(const AlphaImage& image, const GridCell& cell);

}  // namespace hullcook
