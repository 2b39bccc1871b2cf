#include "scene_picture.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>

namespace hullcook::samples {
namespace {

struct Color {
  std::uint8_t r, g, b;
};

constexpr Color kBackground{246, 244, 238};
constexpr Color kWall{96, 96, 104};
constexpr Color kTerrain{150, 118, 84};

// A distinct, stable colour per body: hues spaced by the golden angle.
Color body_color(int body) {
  const float hue = std::fmod(static_cast<float>(body) * 137.508f, 360.0f) / 60.0f;
  const float x = 1.0f - std::fabs(std::fmod(hue, 2.0f) - 1.0f);
  float r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0:
      r = 1, g = x;
      break;
    case 1:
      r = x, g = 1;
      break;
    case 2:
      g = 1, b = x;
      break;
    case 3:
      g = x, b = 1;
      break;
    case 4:
      r = x, b = 1;
      break;
    default:
      r = 1, b = x;
  }
  auto channel = [](float v) { return static_cast<std::uint8_t>(60 + 150 * v); };
  return {channel(r), channel(g), channel(b)};
}

Color shape_color(const Shape& shape) {
  switch (shape.kind) {
    case Shape::Kind::wall:
      return kWall;
    case Shape::Kind::terrain:
      return kTerrain;
    case Shape::Kind::body:
      break;
  }
  return body_color(shape.body);
}

const char* kind_name(Shape::Kind kind) {
  switch (kind) {
    case Shape::Kind::wall:
      return "wall";
    case Shape::Kind::terrain:
      return "terrain";
    case Shape::Kind::body:
      break;
  }
  return "body";
}

// The picture shows the scene with a margin that includes the walls.
Bounds view_of(const Frame& frame) {
  Bounds view = frame.scene;
  for (const Shape& shape : frame.shapes)
    for (const runtime::Vec2& p : shape.points) {
      view.min_x = std::min(view.min_x, p.x), view.max_x = std::max(view.max_x, p.x);
      view.min_y = std::min(view.min_y, p.y), view.max_y = std::max(view.max_y, p.y);
    }
  return view;
}

}  // namespace

bool write_svg(const std::string& path, const Frame& frame) {
  const Bounds view = view_of(frame);
  const float width = view.max_x - view.min_x, height = view.max_y - view.min_y;
  std::ofstream out(path);
  char buffer[256];
  // y up: the document's y is the negated world y, so viewBox starts at -max_y.
  std::snprintf(buffer, sizeof buffer,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"%.4f %.4f %.4f %.4f\" "
                "width=\"%d\" height=\"%d\" data-scene=\"%.6f %.6f %.6f %.6f\">\n",
                view.min_x, -view.max_y, width, height, 960,
                static_cast<int>(std::ceil(960.0f * height / width)), frame.scene.min_x,
                frame.scene.min_y, frame.scene.max_x, frame.scene.max_y);
  out << buffer;
  std::snprintf(
      buffer, sizeof buffer,
      "<rect x=\"%.4f\" y=\"%.4f\" width=\"%.4f\" height=\"%.4f\" fill=\"#%02x%02x%02x\"/>\n",
      view.min_x, -view.max_y, width, height, kBackground.r, kBackground.g, kBackground.b);
  out << buffer << "<g transform=\"scale(1,-1)\" stroke=\"#202020\" stroke-width=\""
      << 0.0015f * width << "\" stroke-linejoin=\"round\">\n";
  for (const Shape& shape : frame.shapes) {
    const Color color = shape_color(shape);
    std::snprintf(buffer, sizeof buffer,
                  "<polygon data-kind=\"%s\" data-body=\"%d\" fill=\"#%02x%02x%02x\" points=\"",
                  kind_name(shape.kind), shape.body, color.r, color.g, color.b);
    out << buffer;
    for (std::size_t i = 0; i < shape.points.size(); ++i) {
      std::snprintf(buffer, sizeof buffer, "%s%.6f,%.6f", i ? " " : "", shape.points[i].x,
                    shape.points[i].y);
      out << buffer;
    }
    out << "\"/>\n";
  }
  out << "</g>\n</svg>\n";
  out.close();
  return static_cast<bool>(out);
}

bool write_png(const std::string& path, const Frame& frame, int width) {
  const Bounds view = view_of(frame);
  const float scale = static_cast<float>(width) / (view.max_x - view.min_x);  // [px / unit]
  const int height =
      std::clamp(static_cast<int>(std::ceil((view.max_y - view.min_y) * scale)), 1, 4 * width);
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < pixels.size(); i += 3)
    pixels[i] = kBackground.r, pixels[i + 1] = kBackground.g, pixels[i + 2] = kBackground.b;
  for (const Shape& shape : frame.shapes) {
    const Color color = shape_color(shape);
    const std::size_t n = shape.points.size();
    if (n < 3) continue;
    // Pixel rows through the polygon: each row's span between its edge crossings at the row's
    // centre (a convex polygon crosses a row at most twice).
    float top = -1e30f, bottom = 1e30f;
    for (const runtime::Vec2& p : shape.points)
      top = std::max(top, p.y), bottom = std::min(bottom, p.y);
    const int first_row = std::max(0, static_cast<int>(std::floor((view.max_y - top) * scale)));
    const int last_row =
        std::min(height - 1, static_cast<int>(std::ceil((view.max_y - bottom) * scale)));
    for (int row = first_row; row <= last_row; ++row) {
      const float y = view.max_y - (static_cast<float>(row) + 0.5f) / scale;
      float left = 1e30f, right = -1e30f;
      for (std::size_t i = 0; i < n; ++i) {
        const runtime::Vec2 a = shape.points[i], b = shape.points[(i + 1) % n];
        if ((a.y <= y) == (b.y <= y)) continue;
        const float x = a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x);
        left = std::min(left, x), right = std::max(right, x);
      }
      if (left > right) continue;
      const int from = std::max(0, static_cast<int>(std::lround((left - view.min_x) * scale)));
      const int to = std::min(width, static_cast<int>(std::lround((right - view.min_x) * scale)));
      for (int column = from; column < to; ++column) {
        std::uint8_t* pixel = &pixels[(static_cast<std::size_t>(row) * width + column) * 3];
        pixel[0] = color.r, pixel[1] = color.g, pixel[2] = color.b;
      }
    }
  }
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_RGB;
  const bool ok = png_image_write_to_file(&image, path.c_str(), 0, pixels.data(), 0, nullptr) != 0;
  png_image_free(&image);
  return ok;
}

}  // namespace hullcook::samples
