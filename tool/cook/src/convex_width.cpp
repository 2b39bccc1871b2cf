#include "convex_width.h"

#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace hullcook {

double width_of_by_scan(const Ring& hull) {
  double width = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = hull.size(); i < n; ++i) {
    Vec2 edge = hull[(i + 1) % n] - hull[i];
    double length = glm::length(edge);
    if (length == 0) continue;
    double farthest = 0;
    for (Vec2 v : hull) farthest = std::max(farthest, cross(edge, v - hull[i]) / length);
    width = std::min(width, farthest);
  }
  return width;
}

double width_of(const Ring& hull) {
  const std::size_t n = hull.size();
  if (n < kCalipersFrom) return width_of_by_scan(hull);
  // The calipers take the heights to rise and then fall along the ring: true of a strictly
  // convex ring, unless its heights tie within rounding over more vertices than the look-ahead
  // below (a lens thinner than 1e-12 of its length). Other rings take the scan.
  for (std::size_t i = 0; i < n; ++i) {
    if (orientation(hull[i == 0 ? n - 1 : i - 1], hull[i], hull[(i + 1) % n]) <= 0) {
      return width_of_by_scan(hull);
    }
  }
  // As the edge turns counter-clockwise, its farthest vertex moves forward: each edge starts
  // from the last one's and steps on while the next lies no nearer. A step back by rounding on a
  // nearly straight run would stop it short, so a few vertices past where it stops are looked at
  // too (the scan's maximum is taken over the same quotients).
  constexpr std::size_t kLookAhead = 4;
  double width = std::numeric_limits<double>::infinity();
  std::size_t far = 0;
  bool started = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = hull[i], edge = hull[(i + 1) % n] - a;
    const double length = glm::length(edge);
    if (length == 0) continue;
    auto height = [&](std::size_t k) { return cross(edge, hull[k] - a) / length; };
    double farthest = 0;
    if (!started) {
      for (std::size_t k = 0; k < n; ++k) {
        if (height(k) > height(far)) far = k;
      }
      started = true;
    } else {
      for (std::size_t steps = 0; steps < n;) {
        std::size_t best = far;
        for (std::size_t ahead = 1; ahead <= kLookAhead && steps + ahead < n; ++ahead) {
          const std::size_t k = (far + ahead) % n;
          if (height(k) >= height(best)) best = k;
        }
        if (best == far) break;
        steps += (best + n - far) % n;
        far = best;
      }
    }
    farthest = std::max(farthest, height(far));
    width = std::min(width, farthest);
  }
  Vec2 low = hull[0], high = hull[0];
  for (Vec2 p : hull) low = glm::min(low, p), high = glm::max(high, p);
  if (!(width > 1e-9 * glm::length(high - low))) return width_of_by_scan(hull);
  return width;
}

}  // namespace hullcook
