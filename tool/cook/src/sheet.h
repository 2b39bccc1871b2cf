// Sprite sheets: a TexturePacker (hash or array) or Aseprite JSON file and its atlas image, each
// frame one asset in its own untrimmed, unrotated coordinates.
#pragma once

#include "grid.h"
#include "hullcook/core/polygon.h"
#include "hullcook/trace/trace.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

struct SheetFrame {
  std::string name;  // the frame's key or filename, without an image extension
  // [px] the frame's pixels in the atlas; a rotated frame is stored turned 90° clockwise, so
  // its rectangle there is height wide and width tall of the trimmed sprite.
  GridCell atlas;
  bool rotated = false;
  int trimmed_width = 0, trimmed_height = 0;  // [px] the sprite as drawn, unrotated
  int offset_x = 0, offset_y = 0;             // [px] its top left in the untrimmed frame
  int width = 0, height = 0;                  // [px] the untrimmed frame (sourceSize)
  std::optional<Vec2> pivot;                  // normalised frame coordinates, y down
};

struct Sheet {
  std::filesystem::path image;     // the atlas: meta.image, relative to the JSON file
  std::vector<SheetFrame> frames;  // in the file's order
};

// A JSON file named as an input is a sheet; a sidecar (NAME.physics.json, NAME.hullcook.json) or
// a project file (hullcook.json) is not.
bool is_sheet_file(const std::filesystem::path& path);

// Reads and checks a sheet's JSON (not its atlas): throws InputError naming path and the problem.
// A frame's untrimmed size may hold at most max_pixels pixels.
Sheet read_sheet(const std::filesystem::path& path, std::uint64_t max_pixels);

// Same as read_sheet() on the JSON text already in memory; path names the file in errors and
// meta.image is relative to it.
Sheet parse_sheet(std::string_view text, const std::filesystem::path& path,
                  std::uint64_t max_pixels);

// Throws InputError naming path unless every frame lies inside a width x height atlas.
void check_frames_inside(const Sheet& sheet, const std::filesystem::path& path, int width,
                         int height);

// The frame as an image of its own: its untrimmed size, transparent but for the sprite, which is
// turned back upright and placed at its offset.
AlphaImage frame_image(const AlphaImage& atlas, const SheetFrame& frame);

}  // namespace hullcook
