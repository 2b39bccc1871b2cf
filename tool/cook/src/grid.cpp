#include "grid.h"

#include "hullcook/core/error.h"

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
