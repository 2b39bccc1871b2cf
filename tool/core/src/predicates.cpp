#include "hullcook/core/predicates.h"

#include "predicates_inline.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hullcook {
namespace {

// Knuth's two-sum: s + e == a + b exactly.
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  double b_virtual = s - a;
  double a_virtual = s - b_virtual;
  e = (a - a_virtual) + (b - b_virtual);
}

// p + e == a * b exactly (fused multiply-add recovers the rounding error).
inline void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

// The determinant expanded into six exact products, summed as a non-overlapping expansion
// (Shewchuk's grow-expansion); its largest non-zero component carries the exact sign.
double orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  const std::array<std::array<double, 2>, 6> factors{
      {{a.x, b.y}, {-a.x, c.y}, {-c.x, b.y}, {-a.y, b.x}, {a.y, c.x}, {c.y, b.x}}};
  std::array<double, 13> expansion{};
  int length = 0;
  auto grow = [&](double value) {
    double carry = value;
    for (int i = 0; i < length; ++i) {
      double sum, error;
      two_sum(carry, expansion[i], sum, error);
      expansion[i] = error;
      carry = sum;
    }
    expansion[length++] = carry;
  };
  for (const auto& factor : factors) {
    double product, error;
    two_product(factor[0], factor[1], product, error);
    grow(error);
    grow(product);
  }
  for (int i = length - 1; i >= 0; --i) {
    if (expansion[i] != 0.0) return expansion[i];
  }
  return 0.0;
}

}  // namespace

namespace {

// A sum of terms with the errors of its additions carried, and the errors of those additions
// carried too (a compensated sum of the second order): the first order's own rounding, eps² times
// the terms' size, was 4.9e-9 of a frame 1e-3 wide at (-1e6, -1e6) (stop 57's review).
class CompensatedSum {
 public:
  void add(double x) {
    double error, second;
    two_sum(sum_, x, sum_, error);
    two_sum(carried_, error, carried_, second);
    carried_twice_ += second;
  }
  // The shoelace's terms of ring, times sign (+1 or -1, exact), each product with its error.
  void add_twice_area(const Ring& ring, double sign) {
    for (std::size_t i = 0, n = ring.size(); i < n && n >= 3; ++i) {
      const Vec2 a = ring[i], b = ring[i + 1 == n ? 0 : i + 1];
      double product, error;
      two_product(sign * a.x, b.y, product, error);
      add(product);
      add(error);
      two_product(-sign * a.y, b.x, product, error);
      add(product);
      add(error);
    }
  }
  double value() const { return sum_ + (carried_ + carried_twice_); }

 private:
  double sum_ = 0.0, carried_ = 0.0, carried_twice_ = 0.0;
};

}  // namespace

double accurate_twice_area(const Ring& ring) {
  CompensatedSum sum;
  sum.add_twice_area(ring, 1.0);
  return sum.value();
}

double accurate_twice_area(const Region& region) {
  // One sum for every ring: a frame's area is a small difference of its rings' large ones, which
  // rounding each ring's apart lost (stop 57: a unit square less a hole 1e-8 inside it, 4e-8
  // summed 5.5e-17 off, more than a billionth of it).
  CompensatedSum sum;
  sum.add_twice_area(region.outer, accurate_twice_area(region.outer) < 0.0 ? -1.0 : 1.0);
  for (const Ring& hole : region.holes) {
    sum.add_twice_area(hole, accurate_twice_area(hole) < 0.0 ? 1.0 : -1.0);
  }
  return sum.value();
}

namespace {

// Whether x - y rounded to difference is exact: two-sum's error is zero.
inline bool difference_is_exact(double x, double y, double difference) {
  double sum, error;
  two_sum(x, -y, sum, error);
  return sum == difference && error == 0.0;
}

// Whether x * y rounded to product is exact: two-product's error is zero, with the product far
// above the subnormals where that error could round away (unless a factor is zero).
inline bool product_is_exact(double x, double y, double product) {
  if (x == 0.0 || y == 0.0) return true;
  double rounded, error;
  two_product(x, y, rounded, error);
  return rounded == product && std::abs(product) > 1e-280 && error == 0.0;
}

// Where orient2d_exact is exact: its six products and their errors stay clear of overflow and
// of the subnormals.
inline bool within_exact_range(double v) {
  const double magnitude = std::abs(v);
  return magnitude == 0.0 || (magnitude >= 1e-140 && magnitude <= 1e140);
}

// Exactly collinear points whose determinant was computed without a rounding (lattice points,
// as traced outlines are, are most of the exact calls of a cook): the expansion's sum is then 0
// too, and orient2d_exact returns 0.0 for it. This returns the same, at a tenth of the cost.
// Out of line: the filtered path of orient2d stays as short as it was.
[[gnu::noinline]] bool is_exact_zero(Vec2 a, Vec2 b, Vec2 c) {
  const double ac_x = a.x - c.x, bc_y = b.y - c.y, ac_y = a.y - c.y, bc_x = b.x - c.x;
  const double left = ac_x * bc_y, right = ac_y * bc_x;
  return left == right && within_exact_range(a.x) && within_exact_range(a.y) &&
         within_exact_range(b.x) && within_exact_range(b.y) && within_exact_range(c.x) &&
         within_exact_range(c.y) && difference_is_exact(a.x, c.x, ac_x) &&
         difference_is_exact(b.y, c.y, bc_y) && difference_is_exact(a.y, c.y, ac_y) &&
         difference_is_exact(b.x, c.x, bc_x) && product_is_exact(ac_x, bc_y, left) &&
         product_is_exact(ac_y, bc_x, right);
}

}  // namespace

double orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double determinant = left - right;
  const double magnitude = std::abs(left) + std::abs(right);
  if (std::abs(determinant) > detail::kOrientErrorBound * magnitude) return determinant;
  if (determinant == 0.0 && is_exact_zero(a, b, c)) return 0.0;
  return orient2d_exact(a, b, c);
}

int orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double value = orient2d(a, b, c);
  return (value > 0.0) - (value < 0.0);
}

bool turns_left_somewhere(const Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; n >= 3 && i < n; ++i) {
    if (orientation(ring[i], ring[(i + 1) % n], ring[(i + 2) % n]) > 0) return true;
  }
  return false;
}

bool is_weakly_convex(const Ring& ring) {
  thread_local Ring distinct;
  distinct.clear();
  for (const Vec2& p : ring) {
    if (distinct.empty() || p != distinct.back()) distinct.push_back(p);
  }
  while (distinct.size() > 1 && distinct.back() == distinct.front()) distinct.pop_back();
  const std::size_t n = distinct.size();
  if (n < 3) return false;
  bool turns_left = false;
  // Edge directions in the upper half-turn [0, pi): a walk that turns by less than a half-turn
  // at each vertex winds once when it enters that half-turn once.
  auto upper = [](Vec2 e) { return e.y > 0.0 || (e.y == 0.0 && e.x > 0.0); };
  std::size_t windings = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = distinct[i], b = distinct[(i + 1) % n], c = distinct[(i + 2) % n];
    const int turn = orientation(a, b, c);
    if (turn < 0) return false;
    const Vec2 in = b - a, out = c - b;
    if (turn == 0 && in.x * out.x + in.y * out.y < 0.0) return false;  // back along itself
    turns_left = turns_left || turn > 0;
    windings += !upper(in) && upper(out);
  }
  return turns_left && windings == 1;
}

bool on_segment(Vec2 a, Vec2 b, Vec2 p) {
  // The box first: it is exact too, and it rules out nearly every edge of a ring walked for one
  // point without the orientation's error analysis.
  if (!(std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
        p.y <= std::max(a.y, b.y))) {
    return false;
  }
  // An end is on the segment, and its orientation, exactly zero, would take the exact arithmetic
  // (the pieces of a fan all meet at its apex: boundary_points_shared met it 2 million times on a
  // star of 8,000 vertices).
  return p == a || p == b || detail::fast_orient2d(a, b, p) == 0.0;
}

bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  // The orientations' values have exact signs; their products could underflow.
  auto same_side = [](double u, double v) { return (u > 0.0 && v > 0.0) || (u < 0.0 && v < 0.0); };
  const double o1 = detail::fast_orient2d(a, b, c);
  const double o2 = detail::fast_orient2d(a, b, d);
  // c and d strictly on one side of ab's line: no common point (the usual answer, decided early).
  if (same_side(o1, o2)) return false;
  const double o3 = detail::fast_orient2d(c, d, a);
  const double o4 = detail::fast_orient2d(c, d, b);
  if (same_side(o3, o4)) return false;
  if (o1 != 0.0 && o2 != 0.0 && o3 != 0.0 && o4 != 0.0) return true;
  auto within_box = [](Vec2 p, Vec2 q, Vec2 r) {
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  if (o1 == 0.0 && within_box(a, b, c)) return true;
  if (o2 == 0.0 && within_box(a, b, d)) return true;
  if (o3 == 0.0 && within_box(c, d, a)) return true;
  if (o4 == 0.0 && within_box(c, d, b)) return true;
  return false;
}

bool segments_cross_properly(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return detail::fast_orientation(a, b, c) * detail::fast_orientation(a, b, d) < 0 &&
         detail::fast_orientation(c, d, a) * detail::fast_orientation(c, d, b) < 0;
}

}  // namespace hullcook
