// The engine-independent half of the drop samples: the command line, and where each asset goes.
// Terrain assets (name containing "terrain" or "ground", or given with --terrain) are laid side
// by side as static bodies with their origin on y = 0; every other asset is dropped from above
// them, spaced along x. A flat floor below everything catches what falls off.
#pragma once

#include "hullcook/runtime.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace hullcook::samples {

struct Options {
  const char* bundle_path = nullptr;
  std::vector<std::string> terrain;  // exact names; empty: by name pattern
  float scale = 1.0f;                // [game units per output unit]
  float seconds = 8.0f;
  float tau = 0.0f;  // requested level of detail [output units]
};

// Prints usage and returns false on a bad command line.
inline bool parse(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--terrain") && has_value)
      options.terrain.push_back(argv[++i]);
    else if (!std::strcmp(argv[i], "--scale") && has_value)
      options.scale = std::strtof(argv[++i], nullptr);
    else if (!std::strcmp(argv[i], "--seconds") && has_value)
      options.seconds = std::strtof(argv[++i], nullptr);
    else if (!std::strcmp(argv[i], "--tau") && has_value)
      options.tau = std::strtof(argv[++i], nullptr);
    else if (argv[i][0] != '-' && !options.bundle_path)
      options.bundle_path = argv[i];
    else
      options.bundle_path = nullptr, i = argc;
  }
  if (!options.bundle_path || !(options.scale > 0) || !(options.seconds > 0)) {
    std::fprintf(stderr,
                 "usage: %s BUNDLE.hcb [--terrain NAME]... [--scale UNITS_PER_OUTPUT_UNIT] "
                 "[--seconds S] [--tau T]\n",
                 argv[0]);
    return false;
  }
  return true;
}

struct Box {
  float min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

inline Box bounds(const runtime::Level& level, float scale) {
  Box box{1e30f, 1e30f, -1e30f, -1e30f};
  for (std::size_t h = 0; h < level.hull_count(); ++h) {
    const runtime::Hull hull = level.hull(h);
    for (std::size_t v = 0; v < hull.vertex_count(); ++v) {
      const runtime::Vec2 p = hull.vertex(v);
      box.min_x = std::min(box.min_x, p.x * scale), box.max_x = std::max(box.max_x, p.x * scale);
      box.min_y = std::min(box.min_y, p.y * scale), box.max_y = std::max(box.max_y, p.y * scale);
    }
  }
  if (box.min_x > box.max_x) box = {};
  return box;
}

struct Placed {
  runtime::Asset asset;
  runtime::Level level;
  bool terrain = false;
  float x = 0, y = 0;  // [game units] the body's origin
};

inline bool is_terrain(const Options& options, const runtime::Asset& asset) {
  const std::string name(asset.name());
  if (!options.terrain.empty())
    return std::find(options.terrain.begin(), options.terrain.end(), name) != options.terrain.end();
  return name.find("terrain") != std::string::npos || name.find("ground") != std::string::npos;
}

// Maps and validates the bundle named on the command line; prints its status and returns false
// when it cannot be used.
inline bool open_bundle(const Options& options, runtime::MappedFile& file,
                        runtime::Bundle& bundle) {
  runtime::Status status = file.open(options.bundle_path);
  if (status == runtime::Status::ok) status = bundle.open(file.data(), file.size());
  if (status != runtime::Status::ok) {
    std::fprintf(stderr, "%s: %s\n", options.bundle_path, runtime::status_string(status));
    return false;
  }
  return true;
}

// Lays the bundle's assets out; returns the floor height [game units] below everything.
inline float lay_out(const runtime::Bundle& bundle, const Options& options,
                     std::vector<Placed>& placed) {
  // Terrain first, side by side; then the sprites in rows above it, wrapping at its width.
  float terrain_x = 0, top = 0, bottom = -1.0f;
  float sprite_x = 0, row_y = 0, row_height = 0;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) row_y = top + 1.0f;
    for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
      const runtime::Asset asset = bundle.asset(a);
      const bool terrain = is_terrain(options, asset);
      if (terrain != (pass == 0)) continue;
      const runtime::Level level = asset.select_level(options.tau);
      if (level.hull_count() == 0) continue;
      const Box box = bounds(level, options.scale);
      Placed p{asset, level, terrain};
      const float width = box.max_x - box.min_x, height = box.max_y - box.min_y;
      if (terrain) {
        p.x = terrain_x - box.min_x;
        terrain_x += width;
        top = std::max(top, box.max_y);
        bottom = std::min(bottom, box.min_y);
      } else {
        const float margin = 0.25f * std::max(width, 0.1f);
        if (sprite_x > 0 && sprite_x + width + 2 * margin > terrain_x) {
          sprite_x = 0;
          row_y += row_height + 1.0f;
          row_height = 0;
        }
        p.x = sprite_x - box.min_x + margin;
        p.y = row_y - box.min_y;
        sprite_x += width + 2 * margin;
        row_height = std::max(row_height, height);
      }
      placed.push_back(p);
    }
  }
  return bottom - 1.0f;
}

inline void print_rest(const Placed& p, float x, float y, float angle, bool asleep) {
  std::printf("%s: dropped at (%.3f, %.3f), rest at (%.3f, %.3f), angle %.3f rad, %s\n",
              std::string(p.asset.name()).c_str(), p.x, p.y, x, y, angle,
              asleep ? "asleep" : "moving");
}

}  // namespace hullcook::samples
