// Pictures of a drop scene, so that a person can see what happened: the final frame as SVG (every
// body's hulls over the terrain, in world units, y up) and frames as PNG images (libpng).
#pragma once

#include "hullcook/runtime.h"

#include <string>
#include <vector>

namespace hullcook::samples {

struct Bounds {
  float min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

// One convex polygon of the scene in world coordinates [game units], counter-clockwise.
struct Shape {
  enum class Kind { wall, terrain, body };
  Kind kind = Kind::body;
  int body = 0;  // the index of the body it belongs to (walls: -1)
  std::vector<runtime::Vec2> points;
};

struct Frame {
  Bounds scene;  // the inside of the walls: bodies must stay in it
  std::vector<Shape> shapes;
  std::vector<std::string> body_names;  // by body index
};

// Writes frame as an SVG document: one <polygon> per shape, with data-kind and data-body
// attributes, the scene's inside in the root's data-scene ("min_x min_y max_x max_y"), and
// coordinates in world units. False when the file cannot be written.
bool write_svg(const std::string& path, const Frame& frame);

// Renders frame into an RGB PNG `width` pixels wide. False when the file cannot be written.
bool write_png(const std::string& path, const Frame& frame, int width = 960);

}  // namespace hullcook::samples
