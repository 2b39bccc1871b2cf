// The engine-independent half of the drop samples: the command line, where each asset goes, the
// walls, and the pictures. Terrain assets (name containing "terrain" or "ground", or given with
// --terrain) are laid side by side as static bodies with their origin on y = 0; every other asset
// is dropped from above them, spaced along x. Walls left and right of the terrain and a floor
// below everything keep every body in the scene.
#pragma once

#include "scene_picture.h"

#include "hullcook/runtime.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace hullcook::samples {

struct Options {
  const char* bundle_path = nullptr;
  std::vector<std::string> terrain;  // exact names; empty: by name pattern
  float scale = 1.0f;                // [game units per output unit]
  float seconds = 8.0f;
  float tau = 0.0f;        // requested level of detail [output units]
  std::string svg_path;    // --svg: the final frame
  std::string frames_dir;  // --frames: a PNG every `every` steps
  int every = 10;
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
    else if (!std::strcmp(argv[i], "--svg") && has_value)
      options.svg_path = argv[++i];
    else if (!std::strcmp(argv[i], "--frames") && has_value)
      options.frames_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--every") && has_value)
      options.every = std::atoi(argv[++i]);
    else if (argv[i][0] != '-' && !options.bundle_path)
      options.bundle_path = argv[i];
    else
      options.bundle_path = nullptr, i = argc;
  }
  if (!options.bundle_path || !(options.scale > 0) || !(options.seconds > 0) || options.every < 1) {
    std::fprintf(stderr,
                 "usage: %s BUNDLE.hcb [--terrain NAME]... [--scale UNITS_PER_OUTPUT_UNIT] "
                 "[--seconds S] [--tau T] [--svg FINAL.svg] [--frames DIR [--every STEPS]]\n",
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

// The density [kg per game unit²] that gives the body of a placed asset a mass of 1 kg (its
// hulls' areas summed; they overlap by little). Box2D's solver handles mass ratios up to about
// 10:1: a sprite sheet of hundreds of hulls weighs thousands of times a small sprite, and a pile
// of such sheets on small sprites kept creeping, or pressed a sprite into its neighbour, by as
// much as the hulls' shapes happened to allow.
inline float unit_mass_density(const Placed& p, float scale) {
  double area = 0;
  for (std::size_t h = 0; h < p.level.hull_count(); ++h) area += p.level.hull(h).area();
  area *= static_cast<double>(scale) * scale;
  return area > 0 ? static_cast<float>(1.0 / area) : 1.0f;
}

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

// Lays the bundle's assets out; returns the inside of the walls [game units]: from the floor
// below everything to above the highest body, as wide as the terrain (at least 10 units).
inline Bounds lay_out(const runtime::Bundle& bundle, const Options& options,
                      std::vector<Placed>& placed) {
  // Terrain first, side by side; then the sprites in rows above it, wrapping at its width.
  float terrain_x = 0, top = 0, bottom = -1.0f, highest = 0;
  float sprite_x = 0, row_y = 0, row_height = 0;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      row_y = top + 1.0f;
      terrain_x = std::max(terrain_x, 10.0f);
    }
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
        highest = std::max(highest, row_y + height);
      }
      placed.push_back(p);
    }
  }
  return {0.0f, bottom - 1.0f, terrain_x, std::max(highest, top) + 2.0f};
}

// The static boxes around the scene's inside: the left and right walls and the floor, 1 unit
// thick.
inline std::vector<Bounds> walls(const Bounds& scene) {
  return {{scene.min_x - 1, scene.min_y - 1, scene.min_x, scene.max_y},
          {scene.max_x, scene.min_y - 1, scene.max_x + 1, scene.max_y},
          {scene.min_x, scene.min_y - 1, scene.max_x, scene.min_y}};
}

// The scene as it is now: walls, then every body's hulls placed by to_world(body index, local
// point) -> world point [game units].
template <typename ToWorld>
Frame frame_of(const Bounds& scene, const std::vector<Placed>& placed, float scale,
               ToWorld&& to_world) {
  Frame frame;
  frame.scene = scene;
  for (const Bounds& wall : walls(scene))
    frame.shapes.push_back({Shape::Kind::wall,
                            -1,
                            {{wall.min_x, wall.min_y},
                             {wall.max_x, wall.min_y},
                             {wall.max_x, wall.max_y},
                             {wall.min_x, wall.max_y}}});
  for (std::size_t b = 0; b < placed.size(); ++b) {
    frame.body_names.emplace_back(placed[b].asset.name());
    for (std::size_t h = 0; h < placed[b].level.hull_count(); ++h) {
      const runtime::Hull hull = placed[b].level.hull(h);
      Shape shape{
          placed[b].terrain ? Shape::Kind::terrain : Shape::Kind::body, static_cast<int>(b), {}};
      for (std::size_t v = 0; v < hull.vertex_count(); ++v)
        shape.points.push_back(to_world(b, hull.placed_vertex(v, {scale, false})));
      frame.shapes.push_back(std::move(shape));
    }
  }
  return frame;
}

// Creates the --frames directory when it is missing; prints the problem and returns false when
// it cannot.
inline bool prepare_frames(const Options& options) {
  if (options.frames_dir.empty()) return true;
  std::error_code error;
  std::filesystem::create_directories(options.frames_dir, error);
  if (!error) return true;
  std::fprintf(stderr, "%s: %s\n", options.frames_dir.c_str(), error.message().c_str());
  return false;
}

// Writes frame `index` as DIR/frame_NNNN.png; prints the problem and returns false on failure.
inline bool write_frame(const Options& options, int index, const Frame& frame) {
  char name[32];
  std::snprintf(name, sizeof name, "/frame_%04d.png", index);
  const std::string path = options.frames_dir + name;
  if (write_png(path, frame)) return true;
  std::fprintf(stderr, "%s: cannot write the frame\n", path.c_str());
  return false;
}

inline bool write_final_svg(const Options& options, const Frame& frame) {
  if (options.svg_path.empty() || write_svg(options.svg_path, frame)) return true;
  std::fprintf(stderr, "%s: cannot write the SVG\n", options.svg_path.c_str());
  return false;
}

// How far each body's hulls moved between two frames of the same scene: the largest distance
// any of its vertices travelled [game units], by body index.
inline std::vector<float> displacements(const Frame& before, const Frame& after) {
  std::vector<float> moved(after.body_names.size(), 0.0f);
  for (std::size_t s = 0; s < after.shapes.size() && s < before.shapes.size(); ++s) {
    const Shape& shape = after.shapes[s];
    if (shape.body < 0) continue;
    for (std::size_t v = 0; v < shape.points.size(); ++v) {
      const runtime::Vec2 a = before.shapes[s].points[v], b = shape.points[v];
      moved[shape.body] = std::max(moved[shape.body], std::hypot(b.x - a.x, b.y - a.y));
    }
  }
  return moved;
}

// The step from which the samples measure whether bodies still move: 2 s before the end.
inline int rest_check_step(int steps) { return std::max(0, steps - 120); }

inline void print_rest(const Placed& p, float x, float y, float angle, bool asleep, float moved) {
  std::printf(
      "%s: dropped at (%.4f, %.4f), rest at (%.4f, %.4f), angle %.5f rad, %s, moved %.5f "
      "in the last 2 s\n",
      std::string(p.asset.name()).c_str(), p.x, p.y, x, y, angle, asleep ? "asleep" : "moving",
      moved);
}

}  // namespace hullcook::samples
