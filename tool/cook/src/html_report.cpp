#include "hullcook/cook/html_report.h"

#include "hullcook/cook/fragment.h"
#include "hullcook/cook/preview.h"
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"
#include "markup.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

namespace hullcook {
namespace {

// The page's look and its sorting. Cards carry their sort keys as data- attributes; the script
// reads the key from the address's hash so that a link (or a test) can ask for an order.
constexpr const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 0; background: #f3f3f1; color: #222; }
header { padding: 12px 20px; background: #fff; border-bottom: 1px solid #ddd; }
h1 { font-size: 18px; margin: 0 0 4px; }
nav a { margin-right: 8px; padding: 2px 8px; border: 1px solid #bbb; border-radius: 4px;
        color: #222; text-decoration: none; }
nav a.current { background: #333; color: #fff; border-color: #333; }
#cards { display: grid; grid-template-columns: repeat(auto-fill, minmax(260px, 1fr));
         gap: 14px; padding: 16px 20px; }
.card { background: #fff; border: 1px solid #ddd; border-radius: 6px; padding: 10px; }
.card h2 { font-size: 13px; margin: 0 0 6px; overflow-wrap: anywhere; }
.card svg { display: block; width: 100%; height: auto; max-height: 320px; }
.card dl { display: grid; grid-template-columns: auto auto; gap: 0 10px; margin: 8px 0 0; }
.card dt { color: #666; }
.card dd { margin: 0; text-align: right; font-variant-numeric: tabular-nums; }
.source { color: #888; font-size: 12px; margin: 6px 0 0; overflow-wrap: anywhere; }
.warnings { color: #a40; font-size: 12px; margin: 6px 0 0; padding-left: 18px; }
)";

constexpr const char* kScript = R"(
(function () {
  var keys = { name: 'index', pieces: 'pieces', time: 'time' };
  function sortCards() {
    var match = /^#sort=(name|pieces|time)$/.exec(location.hash);
    var key = match ? match[1] : 'name';
    var field = keys[key];
    var box = document.getElementById('cards');
    var cards = Array.prototype.slice.call(box.querySelectorAll('.card'));
    cards.sort(function (a, b) {
      var index = Number(a.dataset.index) - Number(b.dataset.index);
      if (field === 'index') return index;
      return Number(b.dataset[field]) - Number(a.dataset[field]) || index;
    });
    cards.forEach(function (card) { box.appendChild(card); });
    document.body.setAttribute('data-sorted-by', key);
    Array.prototype.forEach.call(document.querySelectorAll('nav a'), function (link) {
      link.classList.toggle('current', link.getAttribute('href') === '#sort=' + key);
    });
  }
  window.addEventListener('hashchange', sortCards);
  sortCards();
})();
)";

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// The sprite's pixels as the cook traced them: its frame, transparent but for the cutout, turned
// back upright, its colour key transparent. The images are read again, so one changed since the
// cook is refused.
class SpriteReader {
 public:
  // The asset's preview SVG: a whole PNG image embedded as its own bytes (neither decoded nor
  // encoded again: a browser draws PNG as libpng does), any other sprite cut out and encoded.
  std::string svg(const CookedAsset& asset) {
    if (std::optional<std::string> uri = own_png(asset)) {
      return preview_svg_embedding(std::move(*uri), asset);
    }
    return preview_svg(sprite(asset), asset);
  }

 private:
  // The data: URI of the asset's image file when it is a PNG that is the whole sprite, as it was
  // when cooked (same size) and without a colour key to apply.
  static std::optional<std::string> own_png(const CookedAsset& asset) {
    const SpriteCutout& cutout = asset.cutout;
    const bool whole = !cutout.image.empty() && !cutout.color_key && !cutout.rotated &&
                       cutout.x == 0 && cutout.y == 0 && cutout.offset_x == 0 &&
                       cutout.offset_y == 0 && cutout.width == asset.image_width &&
                       cutout.height == asset.image_height;
    if (!whole) return std::nullopt;
    std::ifstream stream(cutout.image, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(stream),
                            std::istreambuf_iterator<char>()};
    // The signature, then IHDR's length, type, width and height (big-endian).
    static constexpr std::string_view kSignature{"\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16};
    if (bytes.size() < 24 || std::string_view(bytes).substr(0, 16) != kSignature) {
      return std::nullopt;
    }
    auto big_endian = [&](std::size_t at) {
      std::uint32_t value = 0;
      for (std::size_t i = 0; i < 4; ++i) value = value << 8 | std::uint8_t(bytes[at + i]);
      return value;
    };
    if (big_endian(16) != static_cast<std::uint32_t>(asset.image_width) ||
        big_endian(20) != static_cast<std::uint32_t>(asset.image_height)) {
      return std::nullopt;  // changed since the cook: sprite() says so
    }
    return "data:image/png;base64," + base64(bytes);
  }

  RgbaImage sprite(const CookedAsset& asset) {
    const SpriteCutout& cutout = asset.cutout;
    if (cutout.image.empty()) return {};
    if (cutout.image != path_) {
      path_.clear();  // a throwing load must not leave the previous image under a new name
      image_ = load_rgba(cutout.image, std::numeric_limits<std::uint64_t>::max());
      path_ = cutout.image;
    }
    const int stored_width = cutout.rotated ? cutout.height : cutout.width;
    const int stored_height = cutout.rotated ? cutout.width : cutout.height;
    const bool inside = cutout.x >= 0 && cutout.y >= 0 && cutout.x + stored_width <= image_.width &&
                        cutout.y + stored_height <= image_.height && cutout.offset_x >= 0 &&
                        cutout.offset_y >= 0 &&
                        cutout.offset_x + cutout.width <= asset.image_width &&
                        cutout.offset_y + cutout.height <= asset.image_height;
    if (!inside) {
      throw InputError(cutout.image + ": changed since it was cooked: " + asset.name +
                       " no longer lies inside it");
    }
    RgbaImage frame;
    frame.width = asset.image_width;
    frame.height = asset.image_height;
    frame.has_alpha = true;
    frame.rgba.assign(static_cast<std::size_t>(frame.width) * frame.height * 4, 0);
    for (int y = 0; y < cutout.height; ++y) {
      for (int x = 0; x < cutout.width; ++x) {
        // Turned 90° clockwise when stored: the sprite's (x, y) is at (height - 1 - y, x).
        const int image_x = cutout.x + (cutout.rotated ? cutout.height - 1 - y : x);
        const int image_y = cutout.y + (cutout.rotated ? x : y);
        std::memcpy(&frame.rgba[(static_cast<std::size_t>(cutout.offset_y + y) * frame.width +
                                 cutout.offset_x + x) *
                                4],
                    &image_.rgba[(static_cast<std::size_t>(image_y) * image_.width + image_x) * 4],
                    4);
      }
    }
    if (cutout.color_key) {
      const std::array<std::uint8_t, 3>& key = *cutout.color_key;
      for (std::size_t i = 0; i < frame.rgba.size(); i += 4) {
        if (std::equal(key.begin(), key.end(), frame.rgba.begin() + i)) frame.rgba[i + 3] = 0;
      }
    }
    return frame;
  }

  std::string path_;  // the image in image_: assets of one sheet or grid come one after another
  RgbaImage image_;
};

std::size_t hull_vertices(const CookedAsset& asset) {
  std::size_t count = 0;
  if (!asset.levels.empty()) {
    for (const Ring& hull : asset.levels.front().hulls) count += hull.size();
  }
  return count;
}

void write_card(std::ostream& out, std::size_t index, const CookedAsset& asset,
                SpriteReader& sprites) {
  const std::string name = markup_escaped(asset.name);
  const std::size_t hulls = asset.levels.empty() ? 0 : asset.levels.front().hulls.size();
  out << "<article class=\"card\" id=\"asset-" << index << "\" data-index=\"" << index
      << "\" data-name=\"" << name << "\" data-pieces=\"" << asset.stats.pieces << "\" data-time=\""
      << formatted("%.3f", asset.stats.total_ms) << "\">\n"
      << "<h2>" << name << "</h2>\n"
      << sprites.svg(asset) << "<dl>\n"
      << "<dt>vertices traced</dt><dd class=\"vertices-traced\">" << asset.stats.traced_vertices
      << "</dd>\n"
      << "<dt>pieces</dt><dd class=\"pieces\">" << asset.stats.pieces << "</dd>\n"
      << "<dt>hulls</dt><dd class=\"hulls\">" << hulls << "</dd>\n"
      << "<dt>hull vertices</dt><dd class=\"hull-vertices\">" << hull_vertices(asset) << "</dd>\n"
      << "<dt>τ</dt><dd class=\"tau\">" << formatted("%.6g", asset.tau) << "</dd>\n"
      << "<dt>max concavity</dt><dd class=\"max-concavity\">"
      << formatted("%.6g", asset.stats.max_concavity) << "</dd>\n"
      << "<dt>time</dt><dd class=\"time\">" << formatted("%.2f", asset.stats.total_ms)
      << " ms</dd>\n</dl>\n"
      << "<p class=\"source\">" << markup_escaped(asset.source);
  if (asset.image_width > 0) {
    out << " · " << asset.image_width << "×" << asset.image_height << " px";
  }
  // τ and the concavity are in output units.
  out << " · 1 unit = " << formatted("%.6g", asset.pixels_per_unit) << " px</p>\n";
  if (!asset.warnings.empty()) {
    out << "<ul class=\"warnings\">\n";
    for (const std::string& warning : asset.warnings) {
      out << "<li>" << markup_escaped(warning) << "</li>\n";
    }
    out << "</ul>\n";
  }
  out << "</article>\n";
}

}  // namespace

std::string html_report(const CookResult& result) {
  std::size_t pieces = 0, hull_count = 0;
  double milliseconds = 0;
  for (const CookedAsset& asset : result.assets) {
    pieces += asset.stats.pieces;
    hull_count += asset.levels.empty() ? 0 : asset.levels.front().hulls.size();
    milliseconds += asset.stats.total_ms;
  }
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>hullcook report</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
      << "<header>\n<h1>hullcook report</h1>\n<p>hullcook " << markup_escaped(tool_version())
      << ": " << result.assets.size() << " assets, " << pieces << " pieces, " << hull_count
      << " hulls, " << formatted("%.1f", milliseconds)
      << " ms. Outline red, cuts yellow, hulls coloured.</p>\n"
      << "<nav>Sort by <a href=\"#sort=name\">name</a><a href=\"#sort=pieces\">pieces</a>"
      << "<a href=\"#sort=time\">time</a></nav>\n</header>\n<main id=\"cards\">\n";
  SpriteReader sprites;
  for (std::size_t i = 0; i < result.assets.size(); ++i) {
    write_card(out, i, result.assets[i], sprites);
  }
  out << "</main>\n<script>" << kScript << "</script>\n</body>\n</html>\n";
  return std::move(out).str();  // C++20: the buffer, not a copy of it
}

}  // namespace hullcook
