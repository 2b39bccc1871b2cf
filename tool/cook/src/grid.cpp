#include "grid.h"

#include "hullcook/core/error.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace hullcook {

std::vector<GridCell> grid_cells(int width, int height, const Grid& grid) {
  std::vector<GridCell> cells;
  std::size_t index = 0;
  for (long long y = grid.margin; y + grid.cell_height <= height;
       y += grid.cell_height + grid.spacing) {
    for (long long x = grid.margin; x + grid.cell_width <= width;
         x += grid.cell_width + grid.spacing) {
      cells.push_back(
          {static_cast<int>(x), static_cast<int>(y), grid.cell_width, grid.cell_height, index++});
    }
  }
  return cells;
}

UncoveredPixels uncovered_pixels(const AlphaImage& image, const Grid& grid, int alpha) {
  UncoveredPixels uncovered;
  uncovered.from_x = image.width, uncovered.from_y = image.height;
  // The same steps as grid_cells, in 64 bits: a margin and spacing near the int range.
  auto whole = [&](int size, int cell, long long& next) {
    int count = 0;
    next = grid.margin;
    for (; next + cell <= size; next += cell + grid.spacing) ++count;
    return count;
  };
  long long next_x = 0, next_y = 0;
  uncovered.columns = whole(image.width, grid.cell_width, next_x);
  uncovered.rows = whole(image.height, grid.cell_height, next_y);
  if (uncovered.columns == 0 || uncovered.rows == 0) return uncovered;
  // Up to the far margin: Tiled's margin runs round the whole sheet.
  if (next_x < static_cast<long long>(image.width) - grid.margin) {
    uncovered.from_x = static_cast<int>(next_x);
  }
  if (next_y < static_cast<long long>(image.height) - grid.margin) {
    uncovered.from_y = static_cast<int>(next_y);
  }
  const int to_x = std::max(uncovered.from_x, image.width - grid.margin);
  const int to_y = std::max(uncovered.from_y, image.height - grid.margin);
  // Inside the margin on every side: a sheet's frame or guides there belong to no cell either.
  const int margin = std::min({grid.margin, image.width, image.height});
  for (int y = margin; y < to_y; ++y) {
    const std::uint8_t* row = image.alpha.data() + static_cast<std::size_t>(y) * image.width;
    // A row of the bottom strip counts across the width; the others only in the right strip.
    for (int x = y >= uncovered.from_y ? margin : uncovered.from_x; x < to_x; ++x) {
      if (row[x] >= alpha) ++uncovered.opaque;
    }
  }
  return uncovered;
}

std::string describe_uncovered(const UncoveredPixels& uncovered, const AlphaImage& image,
                               const Grid& grid) {
  std::string where;
  if (uncovered.from_x < image.width) where = "x >= " + std::to_string(uncovered.from_x);
  if (uncovered.from_y < image.height) {
    where +=
        (where.empty() ? "" : " or ") + std::string("y >= ") + std::to_string(uncovered.from_y);
  }
  auto count = [](int n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  return std::to_string(uncovered.opaque) + " opaque pixel" + (uncovered.opaque == 1 ? "" : "s") +
         " lie beyond the last whole cell (" + where + " of a " + std::to_string(image.width) +
         "x" + std::to_string(image.height) + " image), where --grid " +
         std::to_string(grid.cell_width) + "x" + std::to_string(grid.cell_height) + " --margin " +
         std::to_string(grid.margin) + " --spacing " + std::to_string(grid.spacing) + " fits " +
         count(uncovered.columns, "column") + " and " + count(uncovered.rows, "row");
}

AlphaImage crop(const AlphaImage& image, const GridCell& cell) {
  AlphaImage out;
  out.width = cell.width;
  out.height = cell.height;
  out.alpha.resize(static_cast<std::size_t>(cell.width) * cell.height);
  for (int row = 0; row < cell.height; ++row) {
    const auto from =
        image.alpha.begin() + static_cast<std::ptrdiff_t>(cell.y + row) * image.width + cell.x;
    std::copy(from, from + cell.width,
              out.alpha.begin() + static_cast<std::ptrdiff_t>(row) * cell.width);
  }
  return out;
}

Grid Grid::parse(const std::string& text) {
  auto side = [&text](const std::string& part) {
    char* end = nullptr;
    const long value = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || end != part.c_str() + part.size() || value < 1 || value > 65535) {
      throw UsageError("--grid: '" + text + "' is not a cell size such as 64x64 (1 to 65535 px)");
    }
    return static_cast<int>(value);
  };
  const std::size_t x = text.find('x');
  Grid grid;
  grid.cell_width = side(text.substr(0, x));
  grid.cell_height = x == std::string::npos ? grid.cell_width : side(text.substr(x + 1));
  return grid;
}

}  // namespace hullcook
