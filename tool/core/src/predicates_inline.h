// Internal: the floating-point filter of orient2d inlined into hot loops. The values are those of
// orient2d (same expression); within a CoordinateBound the filter is a single comparison, and
// only the uncertain case pays for the call.
#pragma once

#include "hullcook/core/predicates.h"

#include <cmath>
#include <limits>

namespace hullcook::detail {

constexpr double kOrientErrorBound =
    (3.0 + 16.0 * std::numeric_limits<double>::epsilon() / 2) *
    (std::numeric_limits<double>::epsilon() / 2);  // Shewchuk's ccwerrboundA

// A bound on orient2d's rounding error that holds for every point of a region, when one is in
// force on this thread (see CoordinateBound); otherwise infinity. A determinant beyond it has its
// sign, and fast_orient2d returns it without the per-call bound.
inline thread_local double static_orient_error_bound = std::numeric_limits<double>::infinity();

// Puts in force, for its lifetime, the error bound of orientations of points whose coordinates are
// at most max_abs in absolute value; the caller orients no other point. Then |a.x - c.x| <= 2
// max_abs, each product is at most 4 max_abs^2, and orient2d's per-call bound at most
// kOrientErrorBound * 8 max_abs^2, up to a few roundings that the margin covers. A determinant
// beyond it passes the per-call bound too: fast_orient2d returns the same values as without it.
class CoordinateBound {
 public:
  explicit CoordinateBound(double max_abs) : saved_(static_orient_error_bound) {
    // Outside this range squares overflow or lose precision: no static bound.
    static_orient_error_bound = max_abs > 1e-100 && max_abs < 1e100
                                    ? kOrientErrorBound * 8.0 * max_abs * max_abs * (1.0 + 1e-9)
                                    : std::numeric_limits<double>::infinity();
  }
  ~CoordinateBound() { static_orient_error_bound = saved_; }
  CoordinateBound(const CoordinateBound&) = delete;
  CoordinateBound& operator=(const CoordinateBound&) = delete;

 private:
  double saved_;
};

// The largest absolute finite coordinate of the ring's (or region's) points: the argument of
// CoordinateBound.
inline double max_abs_coordinate(const Ring& ring, double max_abs = 0.0) {
  for (Vec2 p : ring) {
    if (std::abs(p.x) > max_abs && std::isfinite(p.x)) max_abs = std::abs(p.x);
    if (std::abs(p.y) > max_abs && std::isfinite(p.y)) max_abs = std::abs(p.y);
  }
  return max_abs;
}
inline double max_abs_coordinate(const Region& region) {
  double max_abs = max_abs_coordinate(region.outer);
  for (const Ring& hole : region.holes) max_abs = max_abs_coordinate(hole, max_abs);
  return max_abs;
}

// orient2d's determinant as rounded, before any filter: its sign is orient2d's when its magnitude
// exceeds the static bound in force. Loops that must not call orient2d (see melkman_steps) filter
// it themselves, with the same expression as fast_orient2d.
inline double rounded_orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  return left - right;
}

inline double fast_orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double determinant = rounded_orient2d(a, b, c);
  if (std::abs(determinant) > static_orient_error_bound) return determinant;
  return orient2d(a, b, c);
}

inline int fast_orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double value = fast_orient2d(a, b, c);
  return (value > 0.0) - (value < 0.0);
}

}  // namespace hullcook::detail
