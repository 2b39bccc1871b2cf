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

// Where the whole cells stop short of the image: the opaque pixels (alpha at least the tracer's
// threshold) of the strips where a next column or row of cells would start, inside the image's
// margin on every side. A sheet sized for other cells, or one cell too narrow, loses those pixels
// silently otherwise.
struct UncoveredPixels {
  std::size_t opaque = 0;
  int from_x = 0, from_y = 0;  // [px] the strips: x >= from_x, or y >= from_y (the image's size:
                               // no strip that way)
  int columns = 0, rows = 0;   // whole cells across and down
};
UncoveredPixels uncovered_pixels(const AlphaImage& image, const Grid& grid, int alpha);

// What an UncoveredPixels with opaque pixels says: "N opaque pixels lie beyond the last whole
// cell (x >= 96 of a 100x80 image), where --grid 32x32 fits 3 columns and 2 rows".
std::string describe_uncovered(const UncoveredPixels& uncovered, const AlphaImage& image,
                               const Grid& grid);

// The pixels of cell (inside image) as an image of their own.
AlphaImage crop(const AlphaImage& image, const GridCell& cell);

}  // namespace hullcook
