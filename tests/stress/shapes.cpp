#include "shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hullcook::stress {

Ring rectangle(const Box& box) {
  return {{box.x0, box.y0}, {box.x1, box.y0}, {box.x1, box.y1}, {box.x0, box.y1}};
}

Ring rounded_rectangle(const Box& box, double radius, int segments_per_corner) {
  const double r = std::min(radius, std::min(box.width(), box.height()) / 2);
  const Vec2 centers[4] = {{box.x1 - r, box.y0 + r},
                           {box.x1 - r, box.y1 - r},
                           {box.x0 + r, box.y1 - r},
                           {box.x0 + r, box.y0 + r}};
  Ring ring;
  for (int corner = 0; corner < 4; ++corner) {
    const double start = (corner - 1) * std::numbers::pi / 2;
    for (int s = 0; s <= segments_per_corner; ++s) {
      const double angle = start + s * (std::numbers::pi / 2) / segments_per_corner;
      ring.push_back(centers[corner] + r * Vec2{std::cos(angle), std::sin(angle)});
    }
  }
  return ring;
}

Ring octagon(const Box& box, double chamfer) {
  const double c = std::min(chamfer, std::min(box.width(), box.height()) / 2);
  return {{box.x0 + c, box.y0}, {box.x1 - c, box.y0}, {box.x1, box.y0 + c}, {box.x1, box.y1 - c},
          {box.x1 - c, box.y1}, {box.x0 + c, box.y1}, {box.x0, box.y1 - c}, {box.x0, box.y0 + c}};
}

Ring diamond(const Box& box) {
  const Vec2 c = box.center();
  return {{c.x, box.y0}, {box.x1, c.y}, {c.x, box.y1}, {box.x0, c.y}};
}

Ring regular_polygon(Vec2 center, double radius, int sides, double phase) {
  Ring ring;
  for (int i = 0; i < sides; ++i) {
    const double angle = phase + 2 * std::numbers::pi * i / sides;
    ring.push_back(center + radius * Vec2{std::cos(angle), std::sin(angle)});
  }
  return ring;
}

Ring star(Vec2 center, const std::vector<double>& angles, const std::vector<double>& radii) {
  Ring ring;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    ring.push_back(center + radii[i] * Vec2{std::cos(angles[i]), std::sin(angles[i])});
  }
  return ring;
}

Ring notched_rectangle(const Box& box, double notch_depth, double notch_height) {
  const double y = box.center().y;
  const double h = notch_height / 2;
  const double x = box.x1 - notch_depth;
  return {{box.x0, box.y0}, {box.x1, box.y0}, {box.x1, y - h},  {x, y - h},
          {x, y + h},       {box.x1, y + h},  {box.x1, box.y1}, {box.x0, box.y1}};
}

Ring reversed(Ring ring) {
  std::reverse(ring.begin(), ring.end());
  return ring;
}

}  // namespace hullcook::stress
