#include "images.h"

#include "random.h"

#include "../cli/png_writer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace hullcook::stress {
namespace {

constexpr std::uint8_t kOpaque = 255, kClear = 0;
constexpr double kPi = std::numbers::pi;

// An alpha canvas; every shape covers the pixels whose centres it contains.
class Canvas {
 public:
  Canvas(int width, int height) : width_(width), height_(height), alpha_(width * height, kClear) {}

  void set(int x, int y, std::uint8_t value) {
    if (x >= 0 && y >= 0 && x < width_ && y < height_) alpha_[y * width_ + x] = value;
  }

  // Pixels x0 <= x < x1, y0 <= y < y1.
  void rectangle(int x0, int y0, int x1, int y1, std::uint8_t value) {
    for (int y = std::max(y0, 0); y < std::min(y1, height_); ++y) {
      for (int x = std::max(x0, 0); x < std::min(x1, width_); ++x) alpha_[y * width_ + x] = value;
    }
  }

  // The rectangle with corners rounded to radius (pixel centres inside).
  void rounded(int x0, int y0, int x1, int y1, double radius, std::uint8_t value) {
    radius = std::min({radius, (x1 - x0) / 2.0, (y1 - y0) / 2.0});
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double cx = std::clamp(px, x0 + radius, x1 - radius);
        const double cy = std::clamp(py, y0 + radius, y1 - radius);
        if (std::hypot(px - cx, py - cy) <= radius) set(x, y, value);
      }
    }
  }

  void disc(double cx, double cy, double radius, std::uint8_t value) {
    for (int y = static_cast<int>(cy - radius) - 1; y <= static_cast<int>(cy + radius) + 1; ++y) {
      for (int x = static_cast<int>(cx - radius) - 1; x <= static_cast<int>(cx + radius) + 1; ++x) {
        if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) <= radius) set(x, y, value);
      }
    }
  }

  // A one-pixel line from (x0, y0) to (x1, y1), 8-connected (Bresenham).
  void line(int x0, int y0, int x1, int y1, std::uint8_t value) {
    const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
    const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int error = dx + dy;
    while (true) {
      set(x0, y0, value);
      if (x0 == x1 && y0 == y1) break;
      const int twice = 2 * error;
      if (twice >= dy) error += dy, x0 += sx;
      if (twice <= dx) error += dx, y0 += sy;
    }
  }

  DrawnImage image(ImageFamily family, std::uint64_t seed, std::string description) && {
    return {family, seed, std::move(description), width_, height_, std::move(alpha_)};
  }

 private:
  int width_, height_;
  std::vector<std::uint8_t> alpha_;
};

// Columns (or rows) of cells between lines: the offsets of each cell's first pixel.
std::vector<int> cell_starts(int border, const std::vector<int>& sizes, int line) {
  std::vector<int> starts;
  int at = border;
  for (int size : sizes) {
    starts.push_back(at);
    at += size + line;
  }
  return starts;
}

DrawnImage tileset(Random& random, std::uint64_t seed) {
  int columns = random.integer(2, 10), rows = random.integer(2, 8);
  if (columns * rows < 6) columns = 3, rows = 2;
  const int line = random.integer(1, 3);
  const int border = line + random.integer(0, 3);
  const int pad = random.integer(0, 3);  // transparent margin around the sheet
  const bool irregular = random.chance(0.3);
  const int cell_w = random.integer(6, 40), cell_h = random.integer(6, 40);
  std::vector<int> widths(columns, cell_w), heights(rows, cell_h);
  if (irregular) {
    for (int& w : widths) w = random.integer(6, 40);
    for (int& h : heights) h = random.integer(6, 40);
  }
  int width = 2 * (pad + border) - line, height = 2 * (pad + border) - line;
  for (int w : widths) width += w + line;
  for (int h : heights) height += h + line;
  Canvas canvas(width, height);
  canvas.rectangle(pad, pad, width - pad, height - pad, kOpaque);
  const std::vector<int> xs = cell_starts(pad + border, widths, line);
  const std::vector<int> ys = cell_starts(pad + border, heights, line);
  const double filled = random.chance(0.3) ? random.uniform(0, 0.3) : 0.0;
  const double dotted = random.chance(0.3) ? random.uniform(0, 0.5) : 0.0;
  int holes = 0, islands = 0;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      if (random.chance(filled)) continue;  // an opaque tile: no hole
      ++holes;
      canvas.rectangle(xs[i], ys[j], xs[i] + widths[i], ys[j] + heights[j], kClear);
      if (random.chance(dotted) && std::min(widths[i], heights[j]) >= 8) {
        ++islands;  // a sprite in the cell: its own region inside the hole
        canvas.disc(xs[i] + widths[i] / 2.0, ys[j] + heights[j] / 2.0,
                    random.uniform(2, std::min(widths[i], heights[j]) / 2.0 - 2), kOpaque);
      }
    }
  }
  std::ostringstream description;
  description << width << "x" << height << " tileset, " << columns << "x" << rows << " cells"
              << (irregular ? " (irregular)" : "") << ", line " << line << ", border " << border
              << ", " << holes << " holes, " << islands << " islands";
  return std::move(canvas).image(ImageFamily::tileset, seed, description.str());
}

DrawnImage grid_sheet(std::uint64_t seed) {
  constexpr int kCells = 20, kCell = 48, kLine = 2, kBorder = 1;
  constexpr int kSide = 2 * kBorder + kCells * kCell + (kCells - 1) * kLine;  // 1000
  Canvas canvas(kSide, kSide);
  canvas.rectangle(0, 0, kSide, kSide, kOpaque);
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const int x = kBorder + i * (kCell + kLine), y = kBorder + j * (kCell + kLine);
      canvas.rectangle(x, y, x + kCell, y + kCell, kClear);
    }
  }
  return std::move(canvas).image(ImageFamily::grid_sheet, seed,
                                 "1000x1000 grid sheet, 20x20 cells of 48 px, lines 2 px");
}

DrawnImage frame(Random& random, std::uint64_t seed) {
  std::ostringstream description;
  if (random.chance(0.25)) {  // a porthole: a ring, maybe with a cross inside
    const double radius = random.uniform(10, 90);
    const double thickness = random.uniform(1, std::max(1.0, radius / 3));
    const int side = static_cast<int>(2 * radius) + 4;
    Canvas canvas(side, side);
    canvas.disc(side / 2.0, side / 2.0, radius, kOpaque);
    canvas.disc(side / 2.0, side / 2.0, radius - thickness, kClear);
    const bool cross = random.chance(0.5);
    if (cross) {
      const int bar = random.integer(1, 4);
      canvas.rectangle(side / 2 - bar / 2, 2, side / 2 - bar / 2 + bar, side - 2, kOpaque);
      canvas.rectangle(2, side / 2 - bar / 2, side - 2, side / 2 - bar / 2 + bar, kOpaque);
    }
    description << "porthole radius " << radius << ", ring " << thickness
                << (cross ? ", cross" : "");
    return std::move(canvas).image(ImageFamily::frame, seed, description.str());
  }
  const int width = random.integer(24, 200), height = random.integer(24, 200);
  const int border = random.integer(1, 12);
  const int panes_x = random.integer(1, 3), panes_y = random.integer(1, 3);
  const int mullion = random.integer(1, 4);
  const double corner = random.chance(0.5) ? random.uniform(0, std::min(width, height) / 4.0) : 0;
  Canvas canvas(width + 4, height + 4);
  canvas.rounded(2, 2, width + 2, height + 2, corner, kOpaque);
  const int inner_w = width - 2 * border - (panes_x - 1) * mullion;
  const int inner_h = height - 2 * border - (panes_y - 1) * mullion;
  const double inner_corner = random.chance(0.5) ? random.uniform(0, 6) : 0;
  for (int j = 0; j < panes_y; ++j) {
    for (int i = 0; i < panes_x; ++i) {
      const int x0 = 2 + border + i * (inner_w / panes_x + mullion);
      const int y0 = 2 + border + j * (inner_h / panes_y + mullion);
      canvas.rounded(x0, y0, x0 + inner_w / panes_x, y0 + inner_h / panes_y, inner_corner, kClear);
    }
  }
  description << width << "x" << height << " frame, border " << border << ", " << panes_x << "x"
              << panes_y << " panes, mullion " << mullion << ", corner " << corner;
  return std::move(canvas).image(ImageFamily::frame, seed, description.str());
}

DrawnImage button(Random& random, std::uint64_t seed) {
  const int width = random.integer(32, 96), height = random.integer(12, 32);
  const double corner = random.uniform(0, height / 2.0);
  const int wall = random.integer(1, 2);
  const int holes = random.integer(1, 3);
  const int bar = random.integer(1, 4);
  Canvas canvas(width + 2, height + 2);
  canvas.rounded(1, 1, width + 1, height + 1, corner, kOpaque);
  // The holes keep wall pixels from the rounded outline: inset by the wall plus what the corner
  // takes away near the ends.
  const int inset = wall + static_cast<int>(std::ceil(corner * (1 - std::sqrt(0.5))));
  const int hole_w = (width - 2 * inset - (holes - 1) * bar) / holes;
  int notches = 0;
  for (int i = 0; i < holes && hole_w >= 3; ++i) {
    const int x0 = 1 + inset + i * (hole_w + bar);
    const int y0 = 1 + inset, y1 = height + 1 - inset;
    if (y1 - y0 < 3) break;
    canvas.rounded(x0, y0, x0 + hole_w, y1, random.uniform(0, 3), kClear);
    if (random.chance(0.5) && hole_w >= 6 && y1 - y0 >= 6) {
      ++notches;  // material reaching into the hole, like a letter's bar
      const int depth = random.integer(2, hole_w / 2), tall = random.integer(1, (y1 - y0) / 3);
      const int y = (y0 + y1) / 2 - tall / 2;
      canvas.rectangle(x0 + hole_w - depth, y, x0 + hole_w, y + tall, kOpaque);
    }
  }
  std::ostringstream description;
  description << width << "x" << height << " button, corner " << corner << ", wall " << wall << ", "
              << holes << " holes, bar " << bar << ", " << notches << " notched";
  return std::move(canvas).image(ImageFamily::button, seed, description.str());
}

DrawnImage one_pixel_walls(Random& random, std::uint64_t seed) {
  std::ostringstream description;
  const int kind = random.integer(0, 2);
  if (kind == 0) {  // a maze: a 1 px grid with some inner walls knocked out
    const int cell = random.integer(2, 10), columns = random.integer(3, 24),
              rows = random.integer(3, 24);
    const int width = columns * (cell + 1) + 1, height = rows * (cell + 1) + 1;
    Canvas canvas(width + 2, height + 2);
    canvas.rectangle(1, 1, width + 1, height + 1, kOpaque);
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < columns; ++i) {
        const int x = 2 + i * (cell + 1), y = 2 + j * (cell + 1);
        canvas.rectangle(x, y, x + cell, y + cell, kClear);
        if (i + 1 < columns && random.chance(0.3))
          canvas.rectangle(x + cell, y, x + cell + 1, y + cell, kClear);
        if (j + 1 < rows && random.chance(0.3))
          canvas.rectangle(x, y + cell, x + cell, y + cell + 1, kClear);
      }
    }
    description << "maze of " << columns << "x" << rows << " cells of " << cell << " px";
    return std::move(canvas).image(ImageFamily::one_pixel_walls, seed, description.str());
  }
  if (kind == 1) {  // diagonal 1 px lines both ways: a lattice of diamond holes
    // About 2 (side / spacing)^2 holes: at most 14 spacings a side keeps them near 400, within
    // what cook() takes (holes x vertices at most 5e7).
    const int spacing = random.integer(4, 16);
    const int side = random.integer(24, std::max(24, std::min(160, 14 * spacing)));
    Canvas canvas(side + 2, side + 2);
    for (int x = 1; x <= side; ++x) {
      canvas.set(x, 1, kOpaque);
      canvas.set(x, side, kOpaque);
      canvas.set(1, x, kOpaque);
      canvas.set(side, x, kOpaque);
    }
    for (int start = -side; start <= side; start += spacing) {
      for (int t = 0; t < side; ++t) {
        const int a = start + t;
        if (a >= 0 && a < side) {
          canvas.set(1 + a, 1 + t, kOpaque);
          canvas.set(side - a, 1 + t, kOpaque);
        }
      }
    }
    description << side << " px diamond lattice, spacing " << spacing;
    return std::move(canvas).image(ImageFamily::one_pixel_walls, seed, description.str());
  }
  // Concentric 1 px square rings joined by 1 px spokes, and a comb along the bottom.
  const int rings = random.integer(2, 10), gap = random.integer(1, 6);
  const int side = 2 * rings * (gap + 1) + 1;
  Canvas canvas(side + 2, side + 2 + 12);
  for (int r = 0; r < rings; ++r) {
    const int o = 1 + r * (gap + 1), e = side - r * (gap + 1);
    canvas.line(o, o, e, o, kOpaque);
    canvas.line(e, o, e, e, kOpaque);
    canvas.line(e, e, o, e, kOpaque);
    canvas.line(o, e, o, o, kOpaque);
  }
  const int spokes = random.integer(1, 4);
  const int middle = 1 + side / 2;
  canvas.line(middle, 1, middle, side, kOpaque);
  if (spokes > 1) canvas.line(1, middle, side, middle, kOpaque);
  if (spokes > 2) canvas.line(1, 1, side, side, kOpaque);
  if (spokes > 3) canvas.line(side, 1, 1, side, kOpaque);
  for (int x = 1; x <= side; x += 2) canvas.line(x, side + 1, x, side + 10, kOpaque);
  canvas.line(1, side + 10, side, side + 10, kOpaque);
  description << rings << " concentric 1 px squares " << gap << " px apart, " << spokes
              << " spokes, comb";
  return std::move(canvas).image(ImageFamily::one_pixel_walls, seed, description.str());
}

// Sprites of the small families, a few pixels apart, in rows until the image is at least
// kSide px each way.
DrawnImage mosaic(Random& random, std::uint64_t seed) {
  constexpr int kSide = 640, kGap = 3;
  constexpr ImageFamily kParts[] = {ImageFamily::tileset, ImageFamily::frame, ImageFamily::button,
                                    ImageFamily::one_pixel_walls};
  struct Placed {
    DrawnImage image;
    int x, y;
  };
  std::vector<Placed> placed;
  int x = 0, y = 0, row_height = 0, width = 0;
  while (y < kSide) {
    const ImageFamily family = kParts[random.integer(0, 3)];
    DrawnImage part = draw_image(family, mix_seed(seed, placed.size()));
    if (x > 0 && x + part.width > kSide + 200) x = 0, y += row_height + kGap, row_height = 0;
    if (x == 0 && y >= kSide) break;
    row_height = std::max(row_height, part.height);
    width = std::max(width, x + part.width);
    placed.push_back({std::move(part), x, y});
    x += placed.back().image.width + kGap;
    if (x >= kSide) x = 0, y += row_height + kGap, row_height = 0;
  }
  int height = 0;
  for (const Placed& p : placed) height = std::max(height, p.y + p.image.height);
  Canvas canvas(width, height);
  for (const Placed& p : placed) {
    for (int py = 0; py < p.image.height; ++py) {
      for (int px = 0; px < p.image.width; ++px) {
        canvas.set(p.x + px, p.y + py, p.image.alpha[py * p.image.width + px]);
      }
    }
  }
  std::ostringstream description;
  description << placed.size() << " sprites of the other families, " << width << "x" << height
              << " px";
  return std::move(canvas).image(ImageFamily::mosaic, seed, description.str());
}

// One to three radial falloffs of alpha with a ripple along x, their centres anywhere from a
// fifth of the image outside it to inside: the opaque part is often cut by the image's border.
DrawnImage soft_edges(Random& random, std::uint64_t seed) {
  const int width = random.integer(16, 200), height = random.integer(16, 200);
  Canvas canvas(width, height);
  std::vector<std::uint8_t> alpha(static_cast<std::size_t>(width) * height, kClear);
  const int blobs = random.integer(1, 3);
  std::ostringstream description;
  description << width << "x" << height << " px, " << blobs << " falloffs (slope, ripple):";
  for (int b = 0; b < blobs; ++b) {
    const double cx = random.uniform(-0.2, 1.2) * width, cy = random.uniform(-0.2, 1.2) * height;
    const double slope = random.uniform(0.5, 8), ripple = random.uniform(0, 60);
    const double frequency = random.uniform(0.2, 1.2);
    description << " (" << slope << ", " << ripple << ")";
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const double value =
            255 - slope * std::hypot(x - cx, y - cy) + ripple * std::sin(frequency * x);
        std::uint8_t& a = alpha[static_cast<std::size_t>(y) * width + x];
        a = std::max(a, static_cast<std::uint8_t>(std::clamp(static_cast<int>(value), 0, 255)));
      }
    }
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      canvas.set(x, y, alpha[static_cast<std::size_t>(y) * width + x]);
  }
  return std::move(canvas).image(ImageFamily::soft_edges, seed, description.str());
}

// Value noise on a lattice of `cell` px (bilinear between random lattice values): a disc whose
// rim sinks where the noise is high, with holes inside where it is below the density.
DrawnImage noise_disc(Random& random, std::uint64_t seed) {
  const int width = random.integer(60, 220), height = random.integer(60, 220);
  const int cell = random.integer(2, 6);
  const double density = random.uniform(0.3, 0.5);
  const int columns = width / cell + 2, rows = height / cell + 2;
  std::vector<double> lattice(static_cast<std::size_t>(columns) * rows);
  for (double& value : lattice) value = random.uniform();
  auto noise = [&](int x, int y) {
    const double gx = double(x) / cell, gy = double(y) / cell;
    const int i = static_cast<int>(gx), j = static_cast<int>(gy);
    const double fx = gx - i, fy = gy - j;
    auto at = [&](int a, int b) { return lattice[static_cast<std::size_t>(b) * columns + a]; };
    return at(i, j) * (1 - fx) * (1 - fy) + at(i + 1, j) * fx * (1 - fy) +
           at(i, j + 1) * (1 - fx) * fy + at(i + 1, j + 1) * fx * fy;
  };
  Canvas canvas(width, height);
  const double cx = width / 2.0, cy = height / 2.0, radius = std::min(width, height) / 2.0 - 2;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double value = noise(x, y), r = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      if (r > radius - 6 * value) continue;
      canvas.set(x, y, value < density && r < radius - 8 ? kClear : kOpaque);
    }
  }
  std::ostringstream description;
  description << width << "x" << height << " px, noise cells of " << cell << " px, holes below "
              << density;
  return std::move(canvas).image(ImageFamily::noise_disc, seed, description.str());
}

// Outlines of thousands of traced vertices, which the simplifier searches by a tree of blocks
// (rings of 4,096 or more): a comb of 200-600 teeth 1-2 px wide and 1-3 px apart, some shorter,
// on a spine 3-6 px tall; or an arm 3-8 px wide wound 4-12 turns round a spiral (enough for its
// sides to run 4,400 px), 2-6 px between turns.
DrawnImage long_outline(Random& random, std::uint64_t seed) {
  std::ostringstream description;
  if (random.chance(0.5)) {
    const int teeth = random.integer(200, 600), width = random.integer(1, 2);
    const int gap = random.integer(1, 3), length = random.integer(8, 48);
    const int spine = random.integer(3, 6);
    Canvas canvas(teeth * (width + gap) + 2, length + spine + 2);
    canvas.rectangle(1, 1 + length, teeth * (width + gap) + 1, 1 + length + spine, kOpaque);
    for (int t = 0; t < teeth; ++t) {
      const int x = 1 + t * (width + gap);
      const int tooth = random.chance(0.2) ? random.integer(1, length) : length;
      canvas.rectangle(x, 1 + length - tooth, x + width, 1 + length, kOpaque);
    }
    description << "comb of " << teeth << " teeth " << width << " px wide, " << gap
                << " px apart, up to " << length << " px long, spine " << spine << " px";
    return std::move(canvas).image(ImageFamily::long_outline, seed, description.str());
  }
  const int arm = random.integer(3, 8), gap = random.integer(2, 6);
  const double pitch = arm + gap;
  // Its sides run about 2π pitch turns² px: at least 4,400 px, so that they trace to thousands.
  const int turns =
      std::max(random.integer(4, 12), static_cast<int>(std::ceil(std::sqrt(700 / pitch))));
  const int side = static_cast<int>(2 * pitch * (turns + 1)) + 6;
  Canvas canvas(side, side);
  const double centre = side / 2.0;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const double dx = x + 0.5 - centre, dy = y + 0.5 - centre;
      const double angle = std::atan2(dy, dx) + kPi;  // [0, 2π]
      // The arm's outer side is at radius pitch (1 + turn + angle / 2π) on turn 0, 1, ...
      const double v = std::hypot(dx, dy) / pitch - 1 - angle / (2 * kPi);
      const double turn = std::ceil(v);
      if (turn >= 0 && turn < turns && v >= turn - arm / pitch) canvas.set(x, y, kOpaque);
    }
  }
  description << "spiral of " << turns << " turns, arm " << arm << " px, " << gap
              << " px between turns";
  return std::move(canvas).image(ImageFamily::long_outline, seed, description.str());
}

}  // namespace

std::size_t images_to_draw(ImageFamily family, std::size_t wanted) {
  if (wanted == 0) return 0;
  if (family == ImageFamily::grid_sheet) return 1;
  if (family == ImageFamily::mosaic) return std::max<std::size_t>(1, wanted / 10);
  return wanted;
}

const std::vector<ImageFamily>& all_image_families() {
  static const std::vector<ImageFamily> families{
      ImageFamily::tileset,         ImageFamily::frame,      ImageFamily::button,
      ImageFamily::one_pixel_walls, ImageFamily::grid_sheet, ImageFamily::mosaic,
      ImageFamily::soft_edges,      ImageFamily::noise_disc, ImageFamily::long_outline};
  return families;
}

const char* image_family_name(ImageFamily family) {
  switch (family) {
    case ImageFamily::tileset:
      return "tileset";
    case ImageFamily::frame:
      return "frame";
    case ImageFamily::button:
      return "ui_button";
    case ImageFamily::one_pixel_walls:
      return "one_pixel_walls";
    case ImageFamily::grid_sheet:
      return "grid_sheet";
    case ImageFamily::mosaic:
      return "mosaic";
    case ImageFamily::soft_edges:
      return "soft_edges";
    case ImageFamily::noise_disc:
      return "noise_disc";
    case ImageFamily::long_outline:
      return "long_outline";
  }
  return "?";
}

std::optional<ImageFamily> parse_image_family(std::string_view name) {
  for (ImageFamily family : all_image_families()) {
    if (name == image_family_name(family)) return family;
  }
  return std::nullopt;
}

DrawnImage draw_image(ImageFamily family, std::uint64_t seed) {
  Random random(mix_seed(seed, 100 + static_cast<std::uint64_t>(family)));
  switch (family) {
    case ImageFamily::tileset:
      return tileset(random, seed);
    case ImageFamily::frame:
      return frame(random, seed);
    case ImageFamily::button:
      return button(random, seed);
    case ImageFamily::one_pixel_walls:
      return one_pixel_walls(random, seed);
    case ImageFamily::grid_sheet:
      return grid_sheet(seed);
    case ImageFamily::mosaic:
      return mosaic(random, seed);
    case ImageFamily::soft_edges:
      return soft_edges(random, seed);
    case ImageFamily::noise_disc:
      return noise_disc(random, seed);
    case ImageFamily::long_outline:
      return long_outline(random, seed);
  }
  return grid_sheet(seed);
}

std::string encode_png(const DrawnImage& image) {
  std::vector<std::uint8_t> rgba;
  rgba.reserve(image.alpha.size() * 4);
  for (std::uint8_t a : image.alpha) {
    rgba.insert(rgba.end(), {200, 120, 40, a});
  }
  return test::make_png(static_cast<std::uint32_t>(image.width),
                        static_cast<std::uint32_t>(image.height), 6, rgba);
}

}  // namespace hullcook::stress
