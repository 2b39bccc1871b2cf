// Internal: the floating-point filter of orient2d inlined into hot loops. The values are those of
// orient2d (same expression and bound); only the rare uncertain case pays for the call.
#pragma once

#include "hullcook/core/predicates.h"

#include <cmath>
#include <limits>

namespace hullcook::detail {

inline double fast_orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double determinant = left - right;
  constexpr double epsilon = std::numeric_limits<double>::epsilon() / 2;
  constexpr double error_bound = (3.0 + 16.0 * epsilon) * epsilon;
  if (std::abs(determinant) > error_bound * (std::abs(left) + std::abs(right))) return determinant;
  return orient2d(a, b, c);
}

inline int fast_orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double value = fast_orient2d(a, b, c);
  return (value > 0.0) - (value < 0.0);
}

}  // namespace hullcook::detail
