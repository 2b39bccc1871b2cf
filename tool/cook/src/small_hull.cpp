#include "small_hull.h"

#include "hullcook/core/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcook {
namespace {

// Candidates are made this much wider than the weld, so that rounding keeps them welded.
constexpr double kWeldMargin = 1 + 1e-6;

double area_of(const Ring& ring) { return std::abs(signed_area(ring)); }

}  // namespace

std::vector<Ring> small_hulls(const Ring& ring, const EngineLimits& limits, double reach) {
  if (ring.empty()) return {};
  // Coordinates relative to a vertex keep a tiny piece's precision far from the origin.
  const Vec2 origin = ring.front();
  Ring local;
  local.reserve(ring.size());
  for (Vec2 p : ring) local.push_back(p - origin);
  Ring hull = convex_hull(local);

  std::vector<Vec2> directions{{1, 0}};
  for (std::size_t i = 0, n = hull.size(); n >= 2 && i < n; ++i) {
    Vec2 edge = hull[(i + 1) % n] - hull[i];
    double length = glm::length(edge);
    if (length > 0) directions.push_back(edge / length);
  }
  const double extent = largest_coordinate(local);
  double size = limits.weld > 0 ? limits.weld_distance() * kWeldMargin
                                : std::max(1e-9 * extent, std::numeric_limits<double>::min());
  const double turn =
      limits.weld > 0 ? limits.least_turn() * kWeldMargin : kCollinearFractionOfWeld * size;

  std::vector<Ring> candidates, flat;
  for (Vec2 u : directions) {
    Vec2 v{-u.y, u.x};
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    for (Vec2 p : local) {
      u0 = std::min(u0, glm::dot(p, u)), u1 = std::max(u1, glm::dot(p, u));
      v0 = std::min(v0, glm::dot(p, v)), v1 = std::max(v1, glm::dot(p, v));
    }
    auto at = [&](double a, double b) { return origin + u * a + v * b; };
    // Rectangles at least the weld distance a side: centred on the ring, or flush with either
    // side of it (the one that stays inside the outline, where the other would stick out).
    double width = std::max(u1 - u0, size), height = std::max(v1 - v0, size);
    for (double a : {0.5 * (u0 + u1 - width), u0, u1 - width}) {
      for (double b : {0.5 * (v0 + v1 - height), v0, v1 - height}) {
        candidates.push_back(
            {at(a, b), at(a + width, b), at(a + width, b + height), at(a, b + height)});
      }
    }
    // Triangles on either side: a base twice the ring's length (at least the weld) and twice
    // its thickness high hold the ring; a tenth of the weld high keeps the turns strict.
    double half_base = std::max(u1 - u0, size);
    double rise = std::max(2 * (v1 - v0), 1.5 * turn);
    double middle = 0.5 * (u0 + u1);
    candidates.push_back(
        {at(middle - half_base, v0), at(middle + half_base, v0), at(middle, v0 + rise)});
    candidates.push_back(
        {at(middle + half_base, v1), at(middle - half_base, v1), at(middle, v1 - rise)});
    // Flat triangles whose base reaches a fraction of reach past each end, not half the ring's
    // length: for a sliver much longer than τ, the triangles above reach past τ. The sides
    // pass over the ring's ends at its thickness when the apex rises (thickness) x (half the
    // length + the reach past) / (the reach past); half again more keeps them clear.
    for (double fraction : {0.5, 0.9}) {
      const double past = fraction * reach;
      if (!(past > 0) || past >= 0.5 * (u1 - u0)) continue;
      const double over =
          std::max({1.5 * (v1 - v0) * (0.5 * (u1 - u0) + past) / past, 1.5 * size, 1.5 * turn});
      const double low = u0 - past, high = u1 + past;
      flat.push_back({at(low, v0), at(high, v0), at(middle, v0 + over)});
      flat.push_back({at(high, v1), at(low, v1), at(middle, v1 - over)});
    }
  }
  auto by_area = [](const Ring& a, const Ring& b) { return area_of(a) < area_of(b); };
  std::stable_sort(candidates.begin(), candidates.end(), by_area);
  // After the others: they are tried only where none of those holds the ring within τ.
  std::stable_sort(flat.begin(), flat.end(), by_area);
  candidates.insert(candidates.end(), flat.begin(), flat.end());
  return candidates;
}

}  // namespace hullcook
