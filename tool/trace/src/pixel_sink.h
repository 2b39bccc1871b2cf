// Internal to hullcook_trace: where the image decoders put their rows.
//
// Every decoder gives the samples OpenCV's imdecode(IMREAD_UNCHANGED) gave before hullcook read
// images itself (the outputs must not change): 8 bits, 1 channel (grey), 3 (B, G, R) or 4
// (B, G, R, A). The sink keeps only what its caller asked for: the alpha plane after the colour
// key (all the tracer reads) or 8-bit RGBA (for drawing).
#pragma once

#include "hullcook/trace/trace.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hullcook::image_detail {

[[noreturn]] void fail(const std::string& name, const std::string& problem);

struct Layout {
  int channels = 4;  // 1, 3 or 4
  bool has_alpha = true;
};

class PixelSink {
 public:
  enum class Keep { alpha, rgba };

  PixelSink(Keep keep, std::optional<std::array<std::uint8_t, 3>> colour_key,
            const std::string& name)
      : keep_(keep), colour_key_(colour_key), name_(name) {}

  // Once, before the rows. Throws InputError if alpha is wanted from an image without an alpha
  // channel and no colour key was given.
  void start(int width, int height, Layout layout);

  // Row y (0 = top) in the layout given to start().
  void put_row(int y, const std::uint8_t* samples);

  // True when only the alpha plane is kept and no colour key applies: a decoder may then write
  // the alpha straight into alpha_row(y) instead of calling put_row.
  bool alpha_only() const { return keep_ == Keep::alpha && !colour_key_; }
  std::uint8_t* alpha_row(int y) {
    return pixels_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
  }

  int width() const { return width_; }
  int height() const { return height_; }
  const Layout& layout() const { return layout_; }
  const std::string& name() const { return name_; }

  AlphaImage take_alpha();
  RgbaImage take_rgba();

 private:
  Keep keep_;
  std::optional<std::array<std::uint8_t, 3>> colour_key_;
  const std::string& name_;
  int width_ = 0, height_ = 0;
  Layout layout_;
  std::vector<std::uint8_t> pixels_;  // alpha plane or RGBA
};

// The decoders. bytes is the whole file; the header was checked by read_header (load.cpp), so
// width and height are the file's own and within --max-pixels.
void decode_png(const std::string& bytes, PixelSink& sink);
void decode_webp(const std::string& bytes, int width, int height, PixelSink& sink);
void decode_bmp(const std::string& bytes, PixelSink& sink);
void decode_tga(const std::string& bytes, int width, int height, PixelSink& sink);

// Little-endian and big-endian readers of the file's bytes (at + size must be in range).
inline std::uint32_t u16_le(const std::string& bytes, std::size_t at) {
  return static_cast<std::uint32_t>(std::uint8_t(bytes[at])) |
         static_cast<std::uint32_t>(std::uint8_t(bytes[at + 1])) << 8;
}
inline std::uint32_t u32_le(const std::string& bytes, std::size_t at) {
  return u16_le(bytes, at) | u16_le(bytes, at + 2) << 16;
}
inline std::uint32_t u32_be(const std::string& bytes, std::size_t at) {
  auto byte = [&](std::size_t i) {
    return static_cast<std::uint32_t>(std::uint8_t(bytes[at + i]));
  };
  return byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
}

}  // namespace hullcook::image_detail
