// Scanline coverage: each pixel row is sampled on kSubRows sub-scanlines, and along a
// sub-scanline the covered length of each pixel is exact, which is smooth enough for lines two
// pixels wide and translucent fills.
#include "canvas.h"

#include "hullcook/core/error.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>

namespace hullcook::preview_detail {
namespace {

constexpr int kSubRows = 4;

}  // namespace

Canvas::Canvas(int width, int height, Colour background)
    : width_(std::max(width, 1)),
      height_(std::max(height, 1)),
      rgb_(static_cast<std::size_t>(width_) * height_ * 3),
      mask_(static_cast<std::size_t>(width_) * height_, 0.0f),
      scratch_(static_cast<std::size_t>(width_) + 2, 0.0f) {
  for (std::size_t i = 0; i < rgb_.size(); i += 3) {
    rgb_[i] = background[0], rgb_[i + 1] = background[1], rgb_[i + 2] = background[2];
  }
}

void Canvas::cover(const std::vector<Ring>& rings) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Ring& ring : rings) {
    for (Vec2 p : ring) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x),
      y1 = std::max(y1, p.y);
    }
  }
  if (x0 > x1) return;
  const int row_first = std::max(0, static_cast<int>(std::floor(y0)));
  const int row_last = std::min(height_ - 1, static_cast<int>(std::floor(y1)));
  const int column_first = std::max(0, static_cast<int>(std::floor(x0)));
  const int column_last = std::min(width_ - 1, static_cast<int>(std::floor(x1)));
  if (row_first > row_last || column_first > column_last) return;
  low_x_ = std::min(low_x_, column_first), high_x_ = std::max(high_x_, column_last);
  low_y_ = std::min(low_y_, row_first), high_y_ = std::max(high_y_, row_last);
  std::vector<double> crossings;
  const double weight = 1.0 / kSubRows;
  for (int row = row_first; row <= row_last; ++row) {
    bool touched = false;
    for (int sub = 0; sub < kSubRows; ++sub) {
      const double y = row + (sub + 0.5) / kSubRows;
      crossings.clear();
      for (const Ring& ring : rings) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
          Vec2 a = ring[i], b = ring[(i + 1) % n];
          if ((a.y <= y) == (b.y <= y)) continue;
          crossings.push_back(a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y));
        }
      }
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const double a = std::clamp(crossings[k], double(column_first), column_last + 1.0);
        const double b = std::clamp(crossings[k + 1], double(column_first), column_last + 1.0);
        if (b <= a) continue;
        touched = true;
        const int ia = static_cast<int>(a), ib = static_cast<int>(b);
        float* cell = scratch_.data() - column_first;
        if (ia == ib) {
          cell[ia] += static_cast<float>(weight * (b - a));
          continue;
        }
        cell[ia] += static_cast<float>(weight * (ia + 1 - a));
        for (int i = ia + 1; i < ib; ++i) cell[i] += static_cast<float>(weight);
        if (ib <= column_last) cell[ib] += static_cast<float>(weight * (b - ib));
      }
    }
    if (!touched) continue;
    float* mask = mask_.data() + static_cast<std::size_t>(row) * width_;
    for (int x = column_first; x <= column_last; ++x) {
      float& c = scratch_[x - column_first];
      mask[x] = std::max(mask[x], std::min(c, 1.0f));
      c = 0.0f;
    }
  }
}

void Canvas::blend_mask(Colour colour, double opacity) {
  for (int y = low_y_; y <= high_y_; ++y) {
    float* mask = mask_.data() + static_cast<std::size_t>(y) * width_;
    for (int x = low_x_; x <= high_x_; ++x) {
      if (mask[x] <= 0) continue;
      const double m = mask[x] * opacity;
      std::uint8_t* p = pixel(x, y);
      for (int k = 0; k < 3; ++k) {
        p[k] = static_cast<std::uint8_t>(std::lround(p[k] + (colour[k] - p[k]) * m));
      }
      mask[x] = 0;
    }
  }
  low_x_ = width_, low_y_ = height_, high_x_ = -1, high_y_ = -1;
}

void Canvas::fill(const std::vector<Ring>& rings, Colour colour, double opacity) {
  low_x_ = width_, low_y_ = height_, high_x_ = -1, high_y_ = -1;
  cover(rings);
  blend_mask(colour, opacity);
}

void Canvas::stroke(const Ring& ring, Colour colour, double width) {
  low_x_ = width_, low_y_ = height_, high_x_ = -1, high_y_ = -1;
  const double half = width / 2;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % n];
    // An octagon at each vertex joins the segments.
    Ring join;
    for (int k = 0; k < 8; ++k) {
      const double angle = (k + 0.5) * 3.14159265358979 / 4;
      join.push_back(a + Vec2{std::cos(angle), std::sin(angle)} * half);
    }
    cover({join});
    const Vec2 along = b - a;
    const double length = std::hypot(along.x, along.y);
    if (!(length > 0)) continue;
    const Vec2 normal = Vec2{-along.y, along.x} * (half / length);
    cover({{a + normal, b + normal, b - normal, a - normal}});
  }
  blend_mask(colour, 1.0);
}

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), size);
}
void flush_nothing(png_structp) {}
void on_warning(png_structp, png_const_charp) {}

// Writes the PNG; false on a libpng error (only body's plain calls run after setjmp).
bool write_png(png_structp png, png_infop info, std::string& out, const std::uint8_t* pixels,
               int width, int height, int channels) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, &out, append_bytes, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const std::size_t stride = static_cast<std::size_t>(width) * channels;
  for (int y = 0; y < height; ++y) png_write_row(png, pixels + stride * y);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string encode_png(const std::uint8_t* pixels, int width, int height, int channels) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::string out;
  const bool written = info && write_png(png, info, out, pixels, width, height, channels);
  png_destroy_write_struct(&png, &info);
  if (!written) throw OutputError("preview: PNG encoding failed");
  return out;
}

}  // namespace hullcook::preview_detail
