// Internal to hullcook_cook: the preview's small raster canvas (anti-aliased polygon fills and
// strokes) and its PNG encoding, so that drawing needs no image library beyond libpng.
#pragma once

#include "hullcook/core/polygon.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hullcook::preview_detail {

using Colour = std::array<std::uint8_t, 3>;  // R, G, B

class Canvas {
 public:
  Canvas(int width, int height, Colour background);

  int width() const { return width_; }
  int height() const { return height_; }
  std::uint8_t* pixel(int x, int y) {
    return rgb_.data() + (static_cast<std::size_t>(y) * width_ + x) * 3;
  }
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }

  // Fills the rings (even-odd: a ring inside another is a hole) with colour at the given opacity,
  // anti-aliased. Coordinates in canvas pixels, (0, 0) the top-left corner of the first pixel.
  void fill(const std::vector<Ring>& rings, Colour colour, double opacity = 1.0);

  // Draws the closed outline of ring, width pixels wide, anti-aliased.
  void stroke(const Ring& ring, Colour colour, double width);

 private:
  // Adds the coverage of the rings (even-odd) to mask_ within the box, with max() so that
  // overlapping shapes of one stroke do not darken.
  void cover(const std::vector<Ring>& rings);
  void blend_mask(Colour colour, double opacity);

  int width_, height_;
  std::vector<std::uint8_t> rgb_;
  std::vector<float> mask_;     // coverage of the shape being drawn, 0..1
  std::vector<float> scratch_;  // one shape's coverage before max() into mask_
  int low_x_ = 0, low_y_ = 0, high_x_ = -1, high_y_ = -1;  // mask_'s dirty box
};

// PNG bytes of 8-bit pixels: channels 3 (RGB) or 4 (RGBA), rows top to bottom.
std::string encode_png(const std::uint8_t* pixels, int width, int height, int channels);

}  // namespace hullcook::preview_detail
