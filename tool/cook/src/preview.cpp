#include "hullcook/cook/preview.h"

#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"

#include <glm/common.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace hullcook {
namespace {

constexpr int kMargin = 16;  // [canvas px] around the sprite, so outlines on its border show

// The sprite as 8-bit BGRA. OpenCV decodes PNG, BMP and WebP; the tracer's reader covers the
// rest (TGA) as a white silhouette with its alpha.
cv::Mat load_sprite(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  cv::Mat decoded;
  if (!bytes.empty()) {
    try {
      decoded = cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8U, bytes.data()),
                             cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception&) {
      decoded.release();
    }
  }
  if (decoded.empty()) {
    TraceSettings settings;
    settings.max_pixels = std::numeric_limits<std::uint64_t>::max();
    AlphaImage alpha = load_alpha(path, settings);  // throws InputError naming the file
    cv::Mat channel(alpha.height, alpha.width, CV_8U, alpha.alpha.data());
    cv::Mat white(alpha.height, alpha.width, CV_8U, cv::Scalar(255));
    cv::merge(std::vector<cv::Mat>{white, white, white, channel}, decoded);
    return decoded;
  }
  if (decoded.depth() == CV_16U) decoded.convertTo(decoded, CV_8U, 1.0 / 257.0);
  cv::Mat bgra;
  switch (decoded.channels()) {
    case 1:
      cv::cvtColor(decoded, bgra, cv::COLOR_GRAY2BGRA);
      break;
    case 3:
      cv::cvtColor(decoded, bgra, cv::COLOR_BGR2BGRA);
      break;
    default:
      bgra = decoded;
  }
  return bgra;
}

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

// A distinct, reproducible colour per piece (golden-ratio hues), as B, G, R.
cv::Scalar piece_colour(std::size_t index) {
  double hue = std::fmod(0.13 + 0.6180339887 * static_cast<double>(index), 1.0) * 6.0;
  double f = hue - std::floor(hue), v = 220, p = v * 0.2, q = v * (1 - 0.8 * f),
         t = v * (1 - 0.8 * (1 - f));
  std::array<std::array<double, 3>, 6> rgb{
      {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}}};
  const auto& c = rgb[static_cast<int>(hue) % 6];
  return {c[2], c[1], c[0]};
}

const cv::Scalar kOutlineColour{30, 30, 225};     // red
const cv::Scalar kComponentColour{20, 200, 235};  // yellow

std::string hex(const cv::Scalar& bgr) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", static_cast<int>(bgr[2]),
                static_cast<int>(bgr[1]), static_cast<int>(bgr[0]));
  return text;
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = static_cast<std::uint32_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) chunk |= static_cast<std::uint32_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) chunk |= bytes[i + 2];
    text += alphabet[(chunk >> 18) & 63];
    text += alphabet[(chunk >> 12) & 63];
    text += i + 1 < bytes.size() ? alphabet[(chunk >> 6) & 63] : '=';
    text += i + 2 < bytes.size() ? alphabet[chunk & 63] : '=';
  }
  return text;
}

std::vector<std::uint8_t> png_bytes(const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  if (!cv::imencode(".png", image, bytes)) throw OutputError("preview: PNG encoding failed");
  return bytes;
}

class Preview {
 public:
  Preview(const std::filesystem::path& image, const CookedAsset& asset) : asset_(asset) {
    mapping_.transform = asset.transform;
    if (!(mapping_.transform.scale > 0)) mapping_.transform.scale = 1;
    if (!image.empty()) {
      sprite_ = load_sprite(image);
      width_ = sprite_.cols;
      height_ = sprite_.rows;
      int long_side = std::max({sprite_.cols, sprite_.rows, 1});
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
    cv::Mat canvas(canvas_height_, canvas_width_, CV_8UC3, cv::Scalar(255, 255, 255));
    if (!sprite_.empty()) draw_sprite(canvas);
    cv::Mat fills = canvas.clone();
    for (std::size_t i = 0; i < asset_.pieces.size(); ++i) {
      std::vector<std::vector<cv::Point>> hull{points(asset_.pieces[i].hull)};
      cv::fillPoly(fills, hull, piece_colour(i), cv::LINE_AA, kShift);
    }
    cv::addWeighted(fills, 0.35, canvas, 0.65, 0, canvas);
    for (std::size_t i = 0; i < asset_.pieces.size(); ++i) {
      std::vector<std::vector<cv::Point>> hull{points(asset_.pieces[i].hull)};
      cv::polylines(canvas, hull, true, piece_colour(i) * 0.7, 2, cv::LINE_AA, kShift);
    }
    for (const CookedPiece& piece : asset_.pieces) {
      for (const Ring& ring : rings_of(piece.component)) {
        std::vector<std::vector<cv::Point>> line{points(ring)};
        cv::polylines(canvas, line, true, kComponentColour, 2, cv::LINE_AA, kShift);
      }
    }
    for (const Region& region : asset_.regions) {
      for (const Ring& ring : rings_of(region)) {
        std::vector<std::vector<cv::Point>> line{points(ring)};
        cv::polylines(canvas, line, true, kOutlineColour, 2, cv::LINE_AA, kShift);
      }
    }
    std::vector<std::uint8_t> bytes = png_bytes(canvas);
    return {bytes.begin(), bytes.end()};
  }

  std::string svg() const {
    std::ostringstream out;
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << canvas_width_ << "\" height=\""
        << canvas_height_ << "\" viewBox=\"0 0 " << canvas_width_ << ' ' << canvas_height_
        << "\">\n"
        << "<title>" << escaped(asset_.name.empty() ? asset_.source : asset_.name) << "</title>\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    if (!sprite_.empty()) {
      out << "<image x=\"" << kMargin << "\" y=\"" << kMargin << "\" width=\""
          << width_ * mapping_.factor << "\" height=\"" << height_ * mapping_.factor
          << "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" opacity=\"0.6\" "
             "href=\"data:image/png;base64,"
          << base64(png_bytes(sprite_)) << "\"/>\n";
    }
    out << "<g id=\"hulls\" fill-opacity=\"0.35\" stroke-width=\"2\">\n";
    for (std::size_t i = 0; i < asset_.pieces.size(); ++i) {
      std::string colour = hex(piece_colour(i));
      out << "<path fill=\"" << colour << "\" stroke=\"" << colour << "\" d=\""
          << path({asset_.pieces[i].hull}) << "\"/>\n";
    }
    out << "</g>\n<g id=\"components\" fill=\"none\" stroke=\"" << hex(kComponentColour)
        << "\" stroke-width=\"1\">\n";
    for (const CookedPiece& piece : asset_.pieces) {
      out << "<path d=\"" << path(rings_of(piece.component)) << "\"/>\n";
    }
    out << "</g>\n<g id=\"outline\" fill=\"none\" stroke=\"" << hex(kOutlineColour)
        << "\" stroke-width=\"2\">\n";
    for (const Region& region : asset_.regions)
      out << "<path d=\"" << path(rings_of(region)) << "\"/>\n";
    out << "</g>\n</svg>\n";
    return out.str();
  }

 private:
  static constexpr int kShift = 4;  // sub-pixel bits of OpenCV's drawing

  std::vector<cv::Point> points(const Ring& ring) const {
    std::vector<cv::Point> result;
    for (Vec2 p : ring) {
      Vec2 c = mapping_(p) * double(1 << kShift);
      result.emplace_back(static_cast<int>(std::lround(c.x)), static_cast<int>(std::lround(c.y)));
    }
    return result;
  }

  std::string path(const std::vector<Ring>& rings) const {
    std::string d;
    char number[64];
    for (const Ring& ring : rings) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        Vec2 c = mapping_(ring[i]);
        std::snprintf(number, sizeof number, "%s%.2f %.2f ", i == 0 ? "M" : "L", c.x, c.y);
        d += number;
      }
      if (!ring.empty()) d += "Z ";
    }
    if (!d.empty()) d.pop_back();
    return d;
  }

  static std::string escaped(const std::string& text) {
    std::string result;
    for (char c : text) {
      if (c == '<')
        result += "&lt;";
      else if (c == '>')
        result += "&gt;";
      else if (c == '&')
        result += "&amp;";
      else
        result += c;
    }
    return result;
  }

  // The scaled sprite over a checkerboard, washed out so that the drawing stands out.
  void draw_sprite(cv::Mat& canvas) const {
    cv::Mat scaled;
    cv::resize(sprite_, scaled, {}, mapping_.factor, mapping_.factor, cv::INTER_NEAREST);
    for (int y = 0; y < scaled.rows; ++y) {
      for (int x = 0; x < scaled.cols; ++x) {
        const cv::Vec4b& s = scaled.at<cv::Vec4b>(y, x);
        double checker = ((x / 8 + y / 8) % 2) ? 205 : 240;
        double alpha = s[3] / 255.0;
        cv::Vec3b& c = canvas.at<cv::Vec3b>(y + kMargin, x + kMargin);
        for (int k = 0; k < 3; ++k) {
          double blended = alpha * s[k] + (1 - alpha) * checker;
          c[k] = cv::saturate_cast<std::uint8_t>(0.6 * blended + 0.4 * 255);
        }
      }
    }
  }

  const CookedAsset& asset_;
  CanvasMapping mapping_;
  cv::Mat sprite_;
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
  Preview preview(image, asset);
  write_file_atomically(out, extension == ".png" ? preview.png() : preview.svg());
}

}  // namespace hullcook
