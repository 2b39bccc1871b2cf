// Rings the stress generators and image painters are built from, in their own units. Every ring
// is counter-clockwise; reversed() turns one into a hole.
#pragma once

#include "hullcook/core/polygon.h"

#include <vector>

namespace hullcook::stress {

struct Box {
  double x0, y0, x1, y1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  Vec2 center() const { return {(x0 + x1) / 2, (y0 + y1) / 2}; }
};

Ring rectangle(const Box& box);

// Each corner replaced by a quarter circle of radius (at most half the shorter side) drawn with
// segments_per_corner edges.
Ring rounded_rectangle(const Box& box, double radius, int segments_per_corner);

// Each corner cut at 45 degrees, chamfer along each side (at most half the shorter side).
Ring octagon(const Box& box, double chamfer);

// The rhombus through the midpoints of the box's sides.
Ring diamond(const Box& box);

// n vertices on a circle; the first at angle phase [radians].
Ring regular_polygon(Vec2 center, double radius, int sides, double phase);

// Vertices at the given angles (ascending, within one turn) and radii around center.
Ring star(Vec2 center, const std::vector<double>& angles, const std::vector<double>& radii);

// The box with a rectangular bite of the given depth and height taken out of the middle of its
// right side.
Ring notched_rectangle(const Box& box, double notch_depth, double notch_height);

Ring reversed(Ring ring);

}  // namespace hullcook::stress
