// The predicates' signs against exact 128-bit integer arithmetic, on near-degenerate input.
#include "hullcook/core/predicates.h"

#include "predicates_inline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <tuple>

namespace hullcook {
namespace {

int exact_sign(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx,
               std::int64_t cy) {
  const __int128 det =
      static_cast<__int128>(ax - cx) * (by - cy) - static_cast<__int128>(ay - cy) * (bx - cx);
  return (det > 0) - (det < 0);
}

// Calls check(trial, a, b, c, exact sign) on 20000 triples of integer points with c within 2 units
// of a + k (b - a), |k| <= max_step: coordinates below 2^bits are exact doubles, their differences
// and products are not. Returns how many triples were exactly collinear.
template <typename Check>
int check_nearly_collinear_triples(std::uint64_t seed, int bits, int max_step, Check&& check) {
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<std::int64_t> coordinate(-(std::int64_t{1} << bits),
                                                         std::int64_t{1} << bits);
  std::uniform_int_distribution<std::int64_t> offset(-2, 2);
  std::uniform_int_distribution<int> step(-max_step, max_step);
  // Direction vectors shorter than the coordinates, so that c stays in range.
  const std::int64_t shrink = std::int64_t{4} * max_step;
  int degenerate = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::int64_t ax = coordinate(random), ay = coordinate(random);
    const std::int64_t dx = coordinate(random) / shrink, dy = coordinate(random) / shrink;
    const int k = step(random);
    const std::int64_t bx = ax + dx, by = ay + dy;
    const std::int64_t cx = ax + k * dx + offset(random), cy = ay + k * dy + offset(random);
    const int expected = exact_sign(ax, ay, bx, by, cx, cy);
    degenerate += expected == 0;
    check(trial, Vec2{double(ax), double(ay)}, Vec2{double(bx), double(by)},
          Vec2{double(cx), double(cy)}, expected);
  }
  return degenerate;
}

TEST(Predicates, ExactOnNearlyCollinearIntegerPoints) {
  const int degenerate = check_nearly_collinear_triples(
      12345, 50, 1000, [](int trial, Vec2 a, Vec2 b, Vec2 c, int expected) {
        ASSERT_EQ(orientation(a, b, c), expected) << trial;
        ASSERT_EQ(orientation(b, c, a), expected) << trial;
        ASSERT_EQ(orientation(b, a, c), -expected) << trial;
      });
  EXPECT_GT(degenerate, 100);  // the test does exercise exact collinearity
}

TEST(Predicates, Issue17_CollinearLatticePointsTakeTheShortcutToAnExactZero) {
  // Traced outlines are lattice points: most exact calls of a cook are exactly collinear points
  // whose rounded determinant is exact, and orient2d returns 0 for them without the expansion.
  // The lattices below are scaled by powers of two from 2^-400 to 2^300 (products exact or not,
  // far from the subnormals where no exact predicate holds), with coordinates of 12 to 50
  // bits (differences and products exact or not).
  for (const int scale : {-400, -200, -60, -1, 0, 30, 300}) {
    for (const int bits : {12, 26, 40, 50}) {
      int degenerate = 0;
      check_nearly_collinear_triples(
          std::uint64_t(scale * 100 + bits + 1000), bits, 64,
          [&](int trial, Vec2 a, Vec2 b, Vec2 c, int expected) {
            a = {std::ldexp(a.x, scale), std::ldexp(a.y, scale)};
            b = {std::ldexp(b.x, scale), std::ldexp(b.y, scale)};
            c = {std::ldexp(c.x, scale), std::ldexp(c.y, scale)};
            for (const auto& [p, q, r, sign] :
                 {std::tuple{a, b, c, expected}, std::tuple{b, c, a, expected},
                  std::tuple{c, a, b, expected}, std::tuple{b, a, c, -expected}}) {
              const double value = orient2d(p, q, r);
              ASSERT_EQ((value > 0.0) - (value < 0.0), sign)
                  << "scale 2^" << scale << ", " << bits << " bits, trial " << trial;
              if (sign == 0) {
                ASSERT_FALSE(std::signbit(value)) << "scale 2^" << scale << ", trial " << trial;
              }
            }
            degenerate += expected == 0;
          });
      EXPECT_GT(degenerate, 100) << "scale 2^" << scale << ", " << bits << " bits";
    }
  }
}

TEST(Predicates, FilterWithinACoordinateBoundKeepsOrient2dsValues) {
  // The decomposition orients points within a known box: the filter then compares with one bound
  // fixed for the box. It must return orient2d's values (so its exact signs), near-degenerate or
  // not. The points below stay within 2^42.
  const detail::CoordinateBound bound(std::ldexp(1.0, 42));
  const int degenerate = check_nearly_collinear_triples(
      2026, 40, 8, [](int trial, Vec2 a, Vec2 b, Vec2 c, int expected) {
        ASSERT_EQ(detail::fast_orientation(a, b, c), expected) << trial;
        ASSERT_EQ(detail::fast_orient2d(a, b, c), orient2d(a, b, c)) << trial;
      });
  EXPECT_GT(degenerate, 100);
}

TEST(Predicates, CoordinateBoundsNestAndRestore) {
  const double none = detail::static_orient_error_bound;
  EXPECT_TRUE(std::isinf(none));
  {
    const detail::CoordinateBound outer(1000.0);
    const double outer_bound = detail::static_orient_error_bound;
    EXPECT_GT(outer_bound, 0.0);
    {
      const detail::CoordinateBound inner(1.0);
      EXPECT_LT(detail::static_orient_error_bound, outer_bound);
    }
    EXPECT_EQ(detail::static_orient_error_bound, outer_bound);
    // Coordinates whose squares would overflow or underflow leave the per-call filter alone.
    const detail::CoordinateBound huge(1e200);
    EXPECT_TRUE(std::isinf(detail::static_orient_error_bound));
  }
  EXPECT_EQ(detail::static_orient_error_bound, none);
}

TEST(Predicates, OneUlpOffLine) {
  // y = 2x is exact in binary, so these points are exactly collinear.
  const Vec2 a{0.1, 0.2}, b{0.3, 0.6};
  for (double x : {0.7, 12.345678901234567, 1e-3, 3e15}) {
    const Vec2 on{x, 2.0 * x};
    EXPECT_EQ(orientation(a, b, on), 0) << x;
    EXPECT_EQ(orientation(a, b, {x, std::nextafter(2.0 * x, 1e300)}), 1) << x;
    EXPECT_EQ(orientation(a, b, {x, std::nextafter(2.0 * x, -1e300)}), -1) << x;
  }
}

TEST(Predicates, TinyOffsetsAtLargeCoordinates) {
  const double base = 1e15;
  const Vec2 a{base, base}, b{base + 1.0, base + 1.0};
  EXPECT_EQ(orientation(a, b, {base + 2.0, base + 2.0}), 0);
  EXPECT_EQ(orientation(a, b, {base + 2.0, base + 2.125}), 1);
  EXPECT_EQ(orientation(a, b, {base + 2.0, base + 1.875}), -1);
  // 1e-16 offsets near 1: representable, must not be lost.
  const Vec2 p{1.0, 1.0}, q{2.0, 2.0};
  EXPECT_EQ(orientation(p, q, {0.5, 0.5 + 1e-16}), 1);
  EXPECT_EQ(orientation(p, q, {0.5, 0.5 - 1e-16}), -1);
}

TEST(Predicates, SegmentIntersection) {
  EXPECT_TRUE(segments_intersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));
  EXPECT_TRUE(segments_cross_properly({0, 0}, {2, 2}, {0, 2}, {2, 0}));
  EXPECT_TRUE(segments_intersect({0, 0}, {2, 0}, {1, 0}, {1, 5}));  // touching
  EXPECT_FALSE(segments_cross_properly({0, 0}, {2, 0}, {1, 0}, {1, 5}));
  EXPECT_TRUE(segments_intersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));  // collinear overlap
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 1}, {0, 1e-300}, {1, 1 + 1e-15}));
  EXPECT_TRUE(on_segment({0.1, 0.2}, {0.7, 1.4}, {0.3, 0.6}));
  EXPECT_FALSE(on_segment({0.1, 0.2}, {0.7, 1.4}, {0.3, std::nextafter(0.6, 1.0)}));
  // A segment's ends, a point segment, -0 against 0, and NaN.
  const Vec2 a{1e15 + 1, -3e-300}, b{-7.25, 1e-310};
  EXPECT_TRUE(on_segment(a, b, a));
  EXPECT_TRUE(on_segment(a, b, b));
  EXPECT_TRUE(on_segment(b, b, b));
  EXPECT_FALSE(on_segment(b, b, a));
  EXPECT_TRUE(on_segment({0.0, 1.0}, {2.0, 3.0}, {-0.0, 1.0}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(on_segment({nan, 0.0}, {1.0, 1.0}, {nan, 0.0}));
}

// What a reader may hold a convex hull as (stop 48: the .hcb writer's test of the runtime's
// floats): collinear and repeated vertices pass; a reflex vertex, a spike, a second winding, a
// line, a point and clockwise order do not.
TEST(Predicates, WeaklyConvexRings) {
  const Ring square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_TRUE(is_weakly_convex(square));
  EXPECT_TRUE(is_weakly_convex({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));          // collinear
  EXPECT_TRUE(is_weakly_convex({{0, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}}));  // repeated
  EXPECT_FALSE(is_weakly_convex({{0, 0}, {1, 0.5}, {2, 0}, {2, 2}, {0, 2}}));       // reflex
  EXPECT_FALSE(is_weakly_convex({{0, 0}, {3, 0}, {2, 0}, {2, 2}, {0, 2}}));         // spike
  EXPECT_FALSE(is_weakly_convex({{0, 0}, {2, 0}, {4, 0}}));                         // line
  EXPECT_FALSE(is_weakly_convex({{1, 1}, {1, 1}, {1, 1}}));                         // point
  EXPECT_FALSE(is_weakly_convex({{0, 0}, {0, 2}, {2, 2}, {2, 0}}));                 // clockwise
  Ring pentagram;  // every turn left, wound twice
  for (int i = 0; i < 5; ++i) {
    const double angle = 2 * M_PI * 2 * i / 5;
    pentagram.push_back({std::cos(angle), std::sin(angle)});
  }
  EXPECT_TRUE(turns_left_somewhere(pentagram));
  EXPECT_FALSE(is_weakly_convex(pentagram));
  // Rotations of the square start anywhere and in every half-turn.
  for (double angle = 0; angle < 7; angle += 0.25) {
    Ring turned;
    for (const Vec2 p : square) {
      turned.push_back({p.x * std::cos(angle) - p.y * std::sin(angle),
                        p.x * std::sin(angle) + p.y * std::cos(angle)});
    }
    EXPECT_TRUE(is_weakly_convex(turned)) << angle;
  }
}

}  // namespace
}  // namespace hullcook
