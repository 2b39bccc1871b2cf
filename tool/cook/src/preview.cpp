// The preview: drawn on our own small canvas (canvas.cpp) and encoded with libpng, so that the
// hullcook executable links no image-processing library.
#include "hullcook/cook/preview.h"

#include "canvas.h"
#include "hullcook/cook/cook.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"
#include "markup.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hullcook {
namespace {

constexpr int kMargin = 16;  // [canvas px] around the sprite, so outlines on its border show

using preview_detail::Canvas;
using preview_detail::Colour;
using preview_detail::encode_png;

// Where a point in output units lands on the canvas.
struct CanvasMapping {
  Transform transform;
  Vec2 frame_origin{0, 0};  // [px] the input point at the canvas's margin corner
  double factor = 1;        // canvas px per input px

  Vec2 operator()(Vec2 out) const {
    Vec2 in = out;
    if (transform.flip_y) in.y = -in.y;
    in = in / transform.scale + transform.origin;
    return (in - frame_origin) * factor + Vec2{kMargin, kMargin};
  }
};

std::vector<Ring> rings_of(const Region& region) {
  std::vector<Ring> rings{region.outer};
  rings.insert(rings.end(), region.holes.begin(), region.holes.end());
  return rings;
}

// A distinct, reproducible colour per piece (golden-ratio hues), as R, G, B.
Colour piece_colour(std::size_t index, double shade = 1.0) {
  double hue = std::fmod(0.13 + 0.6180339887 * static_cast<double>(index), 1.0) * 6.0;
  double f = hue - std::floor(hue), v = 220, p = v * 0.2, q = v * (1 - 0.8 * f),
         t = v * (1 - 0.8 * (1 - f));
  std::array<std::array<double, 3>, 6> rgb{
      {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}}};
  const auto& c = rgb[static_cast<int>(hue) % 6];
  auto channel = [&](double value) {
    return static_cast<std::uint8_t>(std::lround(value * shade));
  };
  return {channel(c[0]), channel(c[1]), channel(c[2])};
}

const Colour kOutlineColour{225, 30, 30};     // red
const Colour kComponentColour{235, 200, 20};  // yellow

class Preview {
 public:
  // sprite_uri: the sprite as svg() embeds it, when given (then sprite holds no pixels and the
  // image is the asset's image_width x image_height).
  Preview(RgbaImage sprite, const CookedAsset& asset, std::string sprite_uri = {})
      : asset_(asset), sprite_(std::move(sprite)), sprite_uri_(std::move(sprite_uri)) {
    mapping_.transform = asset.transform;
    if (!(mapping_.transform.scale > 0)) mapping_.transform.scale = 1;
    if (!sprite_uri_.empty()) {
      sprite_.width = asset.image_width;
      sprite_.height = asset.image_height;
    }
    if (has_sprite()) {
      width_ = sprite_.width;
      height_ = sprite_.height;
      int long_side = std::max({sprite_.width, sprite_.height, 1});
      mapping_.factor = std::max(1, (kPreviewMinSize + long_side - 1) / long_side);
    } else {
      // No sprite: frame the geometry, scaled so its long side is kPreviewMinSize.
      Vec2 low{std::numeric_limits<double>::max()}, high{std::numeric_limits<double>::lowest()};
      CanvasMapping pixels = mapping_;  // factor 1, no offset yet
      for (const Region& region : asset.regions) {
        for (Vec2 p : region.outer) {
          Vec2 q = pixels(p) - Vec2{kMargin, kMargin};
          low = glm::min(low, q), high = glm::max(high, q);
        }
      }
      if (low.x > high.x) low = high = Vec2{0, 0};
      Vec2 extent = high - low;
      double long_side = std::max({extent.x, extent.y, 1e-9});
      mapping_.frame_origin = low;
      mapping_.factor = kPreviewMinSize / long_side;
      width_ = extent.x;
      height_ = extent.y;
    }
    canvas_width_ = static_cast<int>(std::ceil(width_ * mapping_.factor)) + 2 * kMargin;
    canvas_height_ = static_cast<int>(std::ceil(height_ * mapping_.factor)) + 2 * kMargin;
  }

  std::string png() const {
    Canvas canvas(canvas_width_, canvas_height_, {255, 255, 255});
    if (!sprite_.rgba.empty()) draw_sprite(canvas);
    for (std::size_t i = 0; i < asset_.pieces.size(); ++i) {
      canvas.fill({points(asset_.pieces[i].hull)}, piece_colour(i), 0.35);
    }
    for (std::size_t i = 0; i < asset_.pieces.size(); ++i) {
      canvas.stroke(points(asset_.pieces[i].hull), piece_colour(i, 0.7), 2);
    }
    for (const CookedPiece& piece : asset_.pieces) {
      for (const Ring& ring : rings_of(piece.component))
        canvas.stroke(points(ring), kComponentColour, 2);
    }
    for (const Region& region : asset_.regions) {
      for (const Ring& ring : rings_of(region)) canvas.stroke(points(ring), kOutlineColour, 2);
    }
    return encode_png(canvas.rgb().data(), canvas.width(), canvas.height(), 3);
  }

  std::string svg() const {
    std::ostringstream out;
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << canvas_width_ << "\" height=\""
        << canvas_height_ << "\" viewBox=\"0 0 " << canvas_width_ << ' ' << canvas_height_
        << "\">\n"
        << "<title>" << markup_escaped(asset_.name.empty() ? asset_.source : asset_.name)
        << "</title>\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    if (has_sprite()) {
      out << "<image x=\"" << kMargin << "\" y=\"" << kMargin << "\" width=\""
          << width_ * mapping_.factor << "\" height=\"" << height_ * mapping_.factor
          << "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" opacity=\"0.6\" "
             "href=\""
          << (sprite_uri_.empty() ? png_uri(sprite_) : sprite_uri_) << "\"/>\n";
    }
    out << "<g class=\"hulls\" fill-opacity=\"0.35\" stroke-width=\"2\">\n";
    for (std::size_t i = 0; i < asset_.pieces.size(); ++i) {
      std::string colour = color_text(piece_colour(i));
      out << "<path fill=\"" << colour << "\" stroke=\"" << colour << "\" d=\""
          << path({asset_.pieces[i].hull}) << "\"/>\n";
    }
    out << "</g>\n<g class=\"components\" fill=\"none\" stroke=\"" << color_text(kComponentColour)
        << "\" stroke-width=\"1\">\n";
    for (const CookedPiece& piece : asset_.pieces) {
      out << "<path d=\"" << path(rings_of(piece.component)) << "\"/>\n";
    }
    out << "</g>\n<g class=\"outline\" fill=\"none\" stroke=\"" << color_text(kOutlineColour)
        << "\" stroke-width=\"2\">\n";
    for (const Region& region : asset_.regions)
      out << "<path d=\"" << path(rings_of(region)) << "\"/>\n";
    out << "</g>\n</svg>\n";
    return std::move(out).str();  // C++20: the buffer, not a copy of it
  }

 private:
  bool has_sprite() const { return !sprite_.rgba.empty() || !sprite_uri_.empty(); }

  static std::string png_uri(const RgbaImage& image) {
    return "data:image/png;base64," +
           base64(encode_png(image.rgba.data(), image.width, image.height, 4));
  }

  Ring points(const Ring& ring) const {
    Ring result;
    result.reserve(ring.size());
    for (Vec2 p : ring) result.push_back(mapping_(p));
    return result;
  }

  std::string path(const std::vector<Ring>& rings) const {
    std::string d;
    // As printf's "%.2f" (the standard defines to_chars so), at a fraction of its cost: an HTML
    // report of thousands of outlines spent most of its time here. Room for any double.
    char number[512];
    const auto append = [&](double value) {
      d.append(
          number,
          std::to_chars(number, number + sizeof number, value, std::chars_format::fixed, 2).ptr);
    };
    for (const Ring& ring : rings) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        Vec2 c = mapping_(ring[i]);
        d += i == 0 ? 'M' : 'L';
        append(c.x);
        d += ' ';
        append(c.y);
        d += ' ';
      }
      if (!ring.empty()) d += "Z ";
    }
    if (!d.empty()) d.pop_back();
    return d;
  }

  // The sprite scaled by an integer factor (nearest neighbour) over a checkerboard, washed out so
  // that the drawing stands out.
  void draw_sprite(Canvas& canvas) const {
    const int factor = static_cast<int>(mapping_.factor);
    const int columns = std::min(sprite_.width * factor, canvas.width() - kMargin);
    const int rows = std::min(sprite_.height * factor, canvas.height() - kMargin);
    for (int y = 0; y < rows; ++y) {
      const std::uint8_t* source_row =
          sprite_.rgba.data() + static_cast<std::size_t>(y / factor) * sprite_.width * 4;
      for (int x = 0; x < columns; ++x) {
        const std::uint8_t* s = source_row + static_cast<std::size_t>(x / factor) * 4;
        const double checker = ((x / 8 + y / 8) % 2) ? 205 : 240;
        const double alpha = s[3] / 255.0;
        std::uint8_t* c = canvas.pixel(x + kMargin, y + kMargin);
        for (int k = 0; k < 3; ++k) {
          const double blended = alpha * s[k] + (1 - alpha) * checker;
          c[k] = static_cast<std::uint8_t>(
              std::clamp(std::lround(0.6 * blended + 0.4 * 255), 0L, 255L));
        }
      }
    }
  }

  const CookedAsset& asset_;
  RgbaImage sprite_;
  std::string sprite_uri_;
  CanvasMapping mapping_;
  double width_ = 0, height_ = 0;  // [px] of the frame
  int canvas_width_ = 0, canvas_height_ = 0;
};

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

void render_preview(const std::filesystem::path& image, const CookedAsset& asset,
                    const std::filesystem::path& out) {
  const std::string extension = lower_extension(out);
  if (extension != ".png" && extension != ".svg") {
    throw UsageError(out.string() + ": a preview is written as .png or .svg");
  }
  RgbaImage sprite;
  if (!image.empty()) sprite = load_rgba(image, std::numeric_limits<std::uint64_t>::max());
  Preview preview(std::move(sprite), asset);
  write_file_atomically(out, extension == ".png" ? preview.png() : preview.svg());
}

std::string preview_svg(RgbaImage sprite, const CookedAsset& asset) {
  return Preview(std::move(sprite), asset).svg();
}

std::string preview_svg_embedding(std::string sprite_uri, const CookedAsset& asset) {
  return Preview(RgbaImage{}, asset, std::move(sprite_uri)).svg();
}

}  // namespace hullcook
