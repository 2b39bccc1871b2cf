#include "sheet.h"

#include "strict_json.h"

#include "hullcook/cook/cook.h"
#include "hullcook/core/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

namespace hullcook {
namespace {

// Ordered: an Aseprite hash's frames are numbered in the file's order, which slices refer to.
using Json = nlohmann::ordered_json;

// Far beyond any atlas, and small enough that sums of two stay within an int.
constexpr long long kLargestCoordinate = 1 << 29;

// Reads the sheet's fields, each error naming the file and where in it.
class SheetReader {
 public:
  explicit SheetReader(const std::filesystem::path& path) : path_(path.string()) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw InputError(path_ + ": " + where + (where.empty() ? "" : ": ") + problem);
  }

  const Json& member(const Json& object, const char* key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key)) fail(where, std::string("no '") + key + "'");
    return object.at(key);
  }

  int whole(const Json& object, const char* key, const std::string& where, long long least) const {
    const Json& value = member(object, key, where);
    const std::optional<long long> whole = whole_number(value);
    if (!whole) fail(where, std::string("'") + key + "' must be a whole number");
    const long long number = *whole;
    if (number < least || number > kLargestCoordinate) {
      fail(where, std::string("'") + key + "' is " + value.dump() + ", out of range (" +
                      std::to_string(least) + " to " + std::to_string(kLargestCoordinate) + ")");
    }
    return static_cast<int>(number);
  }

  double real(const Json& object, const char* key, const std::string& where) const {
    const Json& value = member(object, key, where);
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      fail(where, std::string("'") + key + "' must be a finite number");
    }
    return value.get<double>();
  }

  // pivot: normalised.
  void check_pivot(Vec2 pivot, const std::string& where) const {
    if (std::abs(pivot.x) > kLargestPivot || std::abs(pivot.y) > kLargestPivot) {
      fail(where, "the pivot lies more than 1e6 sprite sizes from the sprite");
    }
  }

  bool flag(const Json& object, const char* key, const std::string& where) const {
    if (!object.contains(key)) return false;
    if (!object.at(key).is_boolean())
      fail(where, std::string("'") + key + "' must be true or false");
    return object.at(key).get<bool>();
  }

  SheetFrame frame(const std::string& name, const Json& entry, std::uint64_t max_pixels) const {
    const std::string where = "frame '" + name + "'";
    if (name.empty()) fail(where, "a frame needs a name");
    if (!entry.is_object()) fail(where, "not an object");
    SheetFrame frame;
    frame.name = name;
    const Json& rect = member(entry, "frame", where);
    frame.trimmed_width = whole(rect, "w", where + ": frame", 1);
    frame.trimmed_height = whole(rect, "h", where + ": frame", 1);
    frame.rotated = flag(entry, "rotated", where);
    frame.atlas = {whole(rect, "x", where + ": frame", 0), whole(rect, "y", where + ": frame", 0),
                   frame.rotated ? frame.trimmed_height : frame.trimmed_width,
                   frame.rotated ? frame.trimmed_width : frame.trimmed_height, 0};
    frame.width = frame.trimmed_width;
    frame.height = frame.trimmed_height;
    if (entry.contains("sourceSize")) {
      frame.width = whole(entry["sourceSize"], "w", where + ": sourceSize", 1);
      frame.height = whole(entry["sourceSize"], "h", where + ": sourceSize", 1);
    }
    if (static_cast<std::uint64_t>(frame.width) * static_cast<std::uint64_t>(frame.height) >
        max_pixels) {
      fail(where, "a " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                      " frame is too large (at most " + std::to_string(max_pixels) +
                      " pixels; --max-pixels)");
    }
    if (entry.contains("spriteSourceSize")) {
      const Json& placed = entry["spriteSourceSize"];
      const std::string at = where + ": spriteSourceSize";
      frame.offset_x = whole(placed, "x", at, 0);
      frame.offset_y = whole(placed, "y", at, 0);
      if (whole(placed, "w", at, 1) != frame.trimmed_width ||
          whole(placed, "h", at, 1) != frame.trimmed_height) {
        fail(at, "its size is not the frame's (the sprite's size, unrotated)");
      }
    }
    if (frame.offset_x + frame.trimmed_width > frame.width ||
        frame.offset_y + frame.trimmed_height > frame.height) {
      fail(where, "the trimmed sprite does not lie inside sourceSize");
    }
    if (entry.contains("pivot")) {
      frame.pivot = Vec2{real(entry["pivot"], "x", where + ": pivot"),
                         real(entry["pivot"], "y", where + ": pivot")};
      check_pivot(*frame.pivot, where);
    }
    return frame;
  }

  // Aseprite: a slice's key holds from its frame until the slice's next key; a key's pivot is in
  // pixels from the key's bounds' top left, and becomes that frame's pivot.
  void apply_slice_pivots(const Json& slices, std::vector<SheetFrame>& frames) const {
    if (!slices.is_array()) fail("meta.slices", "not an array");
    std::vector<std::string> pivot_from(frames.size());
    for (const Json& slice : slices) {
      if (!slice.is_object() || !slice.contains("name") || !slice["name"].is_string()) {
        fail("meta.slices", "a slice needs a name");
      }
      const std::string name = slice["name"].get<std::string>();
      const std::string where = "slice '" + name + "'";
      const Json& keys = member(slice, "keys", where);
      if (!keys.is_array()) fail(where, "'keys' is not an array");
      for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::size_t first = static_cast<std::size_t>(whole(keys[k], "frame", where, 0));
        const std::size_t end =
            k + 1 < keys.size() ? static_cast<std::size_t>(whole(keys[k + 1], "frame", where, 0))
                                : frames.size();
        if (first >= frames.size() || end <= first) {
          fail(where, "a key's frame " + std::to_string(first) +
                          " is not one of the sheet's frames in order (0 to " +
                          std::to_string(frames.size() - 1) + ")");
        }
        const Json& bounds = member(keys[k], "bounds", where);
        const int x = whole(bounds, "x", where + ": bounds", -kLargestCoordinate);
        const int y = whole(bounds, "y", where + ": bounds", -kLargestCoordinate);
        if (!keys[k].contains("pivot")) continue;
        const double px = x + real(keys[k]["pivot"], "x", where + ": pivot");
        const double py = y + real(keys[k]["pivot"], "y", where + ": pivot");
        for (std::size_t f = first; f < std::min(end, frames.size()); ++f) {
          SheetFrame& frame = frames[f];
          if (frame.pivot) {
            fail(where, "frame '" + frame.name + "' has a pivot already" +
                            (pivot_from[f].empty() ? "" : " from slice '" + pivot_from[f] + "'"));
          }
          frame.pivot = Vec2{px / frame.width, py / frame.height};
          check_pivot(*frame.pivot, where);
          pivot_from[f] = name;
        }
      }
    }
  }

 private:
  std::string path_;
};

// Names stay clean of the packed files' extensions: "walk/01.png" is the asset sheet/walk/01.
std::string without_image_extension(const std::string& name) {
  static const std::array<const char*, 10> extensions = {
      ".png", ".tga", ".bmp", ".webp", ".jpg", ".jpeg", ".gif", ".psd", ".aseprite", ".ase"};
  const std::size_t dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0 || name[dot - 1] == '/') return name;
  std::string extension = name.substr(dot);
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* known : extensions) {
    if (extension == known) return name.substr(0, dot);
  }
  return name;
}

}  // namespace

bool is_sheet_file(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  auto ends_with = [&name](const std::string& end) {
    return name.size() >= end.size() &&
           name.compare(name.size() - end.size(), end.size(), end) == 0;
  };
  if (ends_with(".physics.json") || ends_with(".hullcook.json") || name == "hullcook.json") {
    return false;
  }
  return path.extension() == ".json";
}

Sheet read_sheet(const std::filesystem::path& path, std::uint64_t max_pixels) {
  refuse_unless_regular_file(path);
  std::ifstream stream(path, std::ios::binary);
  if (!stream) SheetReader(path).fail("", "cannot read");
  const std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (stream.bad()) SheetReader(path).fail("", "cannot read");
  return parse_sheet(text, path, max_pixels);
}

Sheet parse_sheet(std::string_view text, const std::filesystem::path& path,
                  std::uint64_t max_pixels) {
  const SheetReader reader(path);
  std::string refusal;
  const Json json = parse_strict<Json>(text, refusal);
  if (!refusal.empty()) reader.fail("", refusal);
  if (json.is_discarded() || !json.is_object()) reader.fail("", "not a JSON object");
  if (!json.contains("frames") || !json.contains("meta")) {
    reader.fail("", "not a sprite sheet (TexturePacker or Aseprite JSON: 'frames' and 'meta')");
  }
  const Json& meta = json["meta"];
  const Json& image = reader.member(meta, "image", "meta");
  if (!image.is_string() || image.get<std::string>().empty()) {
    reader.fail("meta", "'image' must name the atlas image");
  }
  Sheet sheet;
  sheet.image = (path.parent_path() / image.get<std::string>()).lexically_normal();
  const Json& frames = json["frames"];
  if (frames.is_object()) {
    for (const auto& [name, entry] : frames.items()) {
      sheet.frames.push_back(reader.frame(without_image_extension(name), entry, max_pixels));
    }
  } else if (frames.is_array()) {
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const Json& entry = frames[i];
      const Json& filename = reader.member(entry, "filename", "frame " + std::to_string(i));
      if (!filename.is_string()) {
        reader.fail("frame " + std::to_string(i), "'filename' must be a string");
      }
      sheet.frames.push_back(reader.frame(
          without_image_extension(entry["filename"].get<std::string>()), entry, max_pixels));
    }
  } else {
    reader.fail("", "'frames' must be an object or an array");
  }
  if (sheet.frames.empty()) reader.fail("", "no frames");
  std::set<std::string> names;
  for (const SheetFrame& frame : sheet.frames) {
    if (!names.insert(frame.name).second) {
      reader.fail("frame '" + frame.name + "'", "two frames have this name");
    }
  }
  if (meta.contains("slices")) reader.apply_slice_pivots(meta["slices"], sheet.frames);
  return sheet;
}

void check_frames_inside(const Sheet& sheet, const std::filesystem::path& path, int width,
                         int height) {
  for (const SheetFrame& frame : sheet.frames) {
    const GridCell& r = frame.atlas;
    if (r.x + r.width > width || r.y + r.height > height) {
      throw InputError(path.string() + ": frame '" + frame.name + "': " + std::to_string(r.width) +
                       "x" + std::to_string(r.height) + " at (" + std::to_string(r.x) + ", " +
                       std::to_string(r.y) + ") lies outside the " + std::to_string(width) + "x" +
                       std::to_string(height) + " atlas " + sheet.image.string());
    }
  }
}

AlphaImage frame_image(const AlphaImage& atlas, const SheetFrame& frame) {
  AlphaImage out;
  out.width = frame.width;
  out.height = frame.height;
  out.alpha.assign(static_cast<std::size_t>(frame.width) * frame.height, 0);
  const GridCell& r = frame.atlas;
  for (int y = 0; y < frame.trimmed_height; ++y) {
    for (int x = 0; x < frame.trimmed_width; ++x) {
      // Turned 90° clockwise in the atlas: the sprite's (x, y) is stored at (h - 1 - y, x).
      const int atlas_x = r.x + (frame.rotated ? frame.trimmed_height - 1 - y : x);
      const int atlas_y = r.y + (frame.rotated ? x : y);
      out.alpha[static_cast<std::size_t>(frame.offset_y + y) * frame.width + frame.offset_x + x] =
          atlas.alpha[static_cast<std::size_t>(atlas_y) * atlas.width + atlas_x];
    }
  }
  return out;
}

}  // namespace hullcook
