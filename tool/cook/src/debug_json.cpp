#include "hullcook/cook/debug_json.h"

#include "utf8_names.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace hullcook {
namespace {

class JsonWriter {
 public:
  std::string& out() { return out_; }

  void number(double value) {
    if (!std::isfinite(value)) {
      out_ += "null";  // JSON has no infinities; never produced by valid cooking
      return;
    }
    // As printf's "%.17g" (the standard defines to_chars so), at a tenth of its cost: a debug
    // JSON of a large cook holds millions of numbers, and printing them doubled its time.
    char buffer[32];
    const std::to_chars_result printed =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 17);
    out_.append(buffer, printed.ptr);
  }

  void integer(std::size_t value) { out_ += std::to_string(value); }

  // Names come from file names, which need not be UTF-8; JSON must be (see utf8_names.h).
  void string(const std::string& raw) {
    const std::string text = valid_utf8(raw);
    out_ += '"';
    for (unsigned char c : text) {
      switch (c) {
        case '"':
          out_ += "\\\"";
          break;
        case '\\':
          out_ += "\\\\";
          break;
        case '\n':
          out_ += "\\n";
          break;
        case '\r':
          out_ += "\\r";
          break;
        case '\t':
          out_ += "\\t";
          break;
        default:
          if (c < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
            out_ += buffer;
          } else {
            out_ += static_cast<char>(c);
          }
      }
    }
    out_ += '"';
  }

  void point(Vec2 p) {
    out_ += '[';
    number(p.x);
    out_ += ", ";
    number(p.y);
    out_ += ']';
  }

  void ring(const Ring& ring) {
    out_ += '[';
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (i) out_ += ", ";
      point(ring[i]);
    }
    out_ += ']';
  }

  void region(const Region& region) {
    out_ += "{\"outer\": ";
    ring(region.outer);
    out_ += ", \"holes\": [";
    for (std::size_t i = 0; i < region.holes.size(); ++i) {
      if (i) out_ += ", ";
      ring(region.holes[i]);
    }
    out_ += "]}";
  }

 private:
  std::string out_;
};

}  // namespace

std::string debug_json(const std::vector<CookedAsset>& assets) {
  JsonWriter json;
  std::string& out = json.out();
  // A point prints as about 45 bytes: reserved at once, the text is not copied as it grows
  // (a large cook's debug JSON is tens of megabytes).
  std::size_t points = 0;
  const auto count = [&](const Region& region) {
    points += region.outer.size();
    for (const Ring& hole : region.holes) points += hole.size();
  };
  for (const CookedAsset& asset : assets) {
    for (const Region& region : asset.regions) count(region);
    for (const CookedPiece& piece : asset.pieces)
      count(piece.component), points += piece.hull.size();
    for (const CookedLevel& level : asset.levels) {
      for (const Ring& hull : level.hulls) points += hull.size();
    }
  }
  out.reserve(48 * points + 1024 * (assets.size() + 1));
  out += "{\"hullcook\": 1,\n \"assets\": [";
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const CookedAsset& asset = assets[a];
    out += a ? ",\n  {" : "\n  {";
    out += "\"name\": ";
    json.string(asset.name);
    out += ", \"source\": ";
    json.string(asset.source);
    out += ",\n   \"transform\": {\"scale\": ";
    json.number(asset.transform.scale);
    out += ", \"origin\": ";
    json.point(asset.transform.origin);
    out += ", \"flip_y\": ";
    out += asset.transform.flip_y ? "true" : "false";
    out += "},\n   \"tau\": ";
    json.number(asset.tau);
    out += ", \"measure\": ";
    json.string(asset.measure);
    out += ",\n   \"regions\": [";
    for (std::size_t i = 0; i < asset.regions.size(); ++i) {
      out += i ? ",\n    " : "\n    ";
      json.region(asset.regions[i]);
    }
    out += "],\n   \"pieces\": [";
    for (std::size_t i = 0; i < asset.pieces.size(); ++i) {
      const CookedPiece& piece = asset.pieces[i];
      out += i ? ",\n    " : "\n    ";
      out += "{\"component\": ";
      json.region(piece.component);
      out += ", \"hull\": ";
      json.ring(piece.hull);
      out += ", \"concavity\": ";
      json.number(piece.concavity);
      out += '}';
    }
    out += "],\n   \"levels\": [";
    for (std::size_t l = 0; l < asset.levels.size(); ++l) {
      const CookedLevel& level = asset.levels[l];
      out += l ? ",\n    {\"tau\": " : "\n    {\"tau\": ";
      json.number(level.tau);
      out += ", \"hulls\": [";
      for (std::size_t h = 0; h < level.hulls.size(); ++h) {
        if (h) out += ", ";
        json.ring(level.hulls[h]);
      }
      out += "]}";
    }
    out += "]";
    out += ",\n   \"pixels_per_unit\": ";
    json.number(asset.pixels_per_unit);
    out += ", \"pivot\": ";
    json.point(asset.pivot);
    if (asset.image_width > 0) {
      out += ", \"image\": {\"width\": ";
      json.integer(static_cast<std::size_t>(asset.image_width));
      out += ", \"height\": ";
      json.integer(static_cast<std::size_t>(asset.image_height));
      out += "}";
    }
    if (asset.quantization_error) {
      out += ", \"quantization_error\": ";
      json.number(*asset.quantization_error);
    }
    if (asset.physics) {
      const PhysicsProperties& physics = *asset.physics;
      out += ",\n   \"physics\": {\"density\": ";
      json.number(physics.density);
      out += ", \"friction\": ";
      json.number(physics.friction);
      out += ", \"restitution\": ";
      json.number(physics.restitution);
      out += ", \"sensor\": ";
      out += physics.sensor ? "true" : "false";
      out += ", \"category_bits\": ";
      json.integer(physics.category_bits);
      out += ", \"mask_bits\": ";
      json.integer(physics.mask_bits);
      out += "}";
    }
    if (!asset.warnings.empty()) {
      out += ",\n   \"warnings\": [";
      for (std::size_t w = 0; w < asset.warnings.size(); ++w) {
        if (w) out += ", ";
        json.string(asset.warnings[w]);
      }
      out += "]";
    }
    out += ",\n   \"stats\": {\"pieces\": ";
    json.integer(asset.stats.pieces);
    out += ", \"max_concavity\": ";
    json.number(asset.stats.max_concavity);
    out += ", \"convexity\": ";
    json.number(asset.stats.convexity);
    // No timings: they differ from run to run, and the same inputs and settings give the same
    // bytes (--report has them).
    out += ", \"traced_vertices\": ";
    json.integer(asset.stats.traced_vertices);
    out += "}}";
  }
  out += "\n ]}\n";
  return std::move(out);
}

}  // namespace hullcook
