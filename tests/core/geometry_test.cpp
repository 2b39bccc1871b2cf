#include "hullcook/core/geometry.h"

#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace hullcook {
namespace {

TEST(Geometry, SignedAreaAndLocation) {
  const Ring square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(signed_area(square), 4.0);
  EXPECT_DOUBLE_EQ(signed_area(Ring(square.rbegin(), square.rend())), -4.0);
  EXPECT_EQ(locate_point(square, {1, 1}), Location::inside);
  EXPECT_EQ(locate_point(square, {2, 1}), Location::boundary);
  EXPECT_EQ(locate_point(square, {0, 0}), Location::boundary);
  EXPECT_EQ(locate_point(square, {3, 1}), Location::outside);
  const Region with_hole{square, {{{0.5, 0.5}, {0.5, 1.5}, {1.5, 1.5}, {1.5, 0.5}}}};
  EXPECT_DOUBLE_EQ(region_area(with_hole), 3.0);
  EXPECT_EQ(locate_point(with_hole, {1, 1}), Location::outside);
  EXPECT_EQ(locate_point(with_hole, {0.25, 1}), Location::inside);
  EXPECT_DOUBLE_EQ(point_segment_distance({1, 1}, {0, 0}, {2, 0}), 1.0);
  EXPECT_DOUBLE_EQ(point_segment_distance({3, 4}, {0, 0}, {0, 0}), 5.0);
  EXPECT_DOUBLE_EQ(point_segment_distance({-3, 4}, {0, 0}, {2, 0}), 5.0);
}

// The many-holes check (stop 57: 180,000 holes of a checkerboard took 20 s to locate) answers as
// locate_point does, for points inside, outside, on edges and vertices, above and below the
// ring, and NaN; on stars (one of 10 vertices, scanned plainly), a staircase, and a comb whose
// teeth span every band (filed in 4 bands instead).
TEST(Geometry, Stop57_RingLocatorAnswersAsLocatePoint) {
  std::mt19937_64 random(57);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Ring> rings;
  for (int n : {10, 16, 100, 3000}) {
    Ring star;
    for (int i = 0; i < n; ++i) {
      const double angle = 2.0 * M_PI * i / n, radius = 50.0 + 50.0 * unit(random);
      star.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    rings.push_back(star);
  }
  Ring staircase{{0, 0}};
  for (int step = 0; step < 500; ++step) {
    staircase.push_back({step + 1.0, step + 0.0});
    staircase.push_back({step + 1.0, step + 1.0});
  }
  staircase.push_back({0, 500});
  rings.push_back(staircase);
  Ring comb;
  for (int tooth = 0; tooth < 300; ++tooth) {
    comb.push_back({2.0 * tooth, 1000.0});
    comb.push_back({2.0 * tooth + 1.0, 1000.0});
    comb.push_back({2.0 * tooth + 1.0, 1.0});
    comb.push_back({2.0 * tooth + 2.0, 1.0});
  }
  comb.push_back({600, 0});
  comb.push_back({0, 0});
  rings.push_back(comb);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::size_t inside = 0, boundary = 0;
  for (const Ring& ring : rings) {
    const RingLocator locator(ring);
    double low_x = ring[0].x, high_x = low_x, low_y = ring[0].y, high_y = low_y;
    for (Vec2 v : ring) {
      low_x = std::min(low_x, v.x), high_x = std::max(high_x, v.x);
      low_y = std::min(low_y, v.y), high_y = std::max(high_y, v.y);
    }
    std::vector<Vec2> points{{nan, 0.0}, {0.0, nan}, {0.0, low_y - 1}, {0.0, high_y + 1}};
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      points.push_back(a);
      points.push_back((a + b) * 0.5);
      points.push_back({a.x - 1e-9, a.y});
    }
    for (int k = 0; k < 20000; ++k) {
      points.push_back({low_x - 1 + (high_x - low_x + 2) * unit(random),
                        low_y - 1 + (high_y - low_y + 2) * unit(random)});
    }
    for (Vec2 p : points) {
      const Location expected = locate_point(ring, p);
      ASSERT_EQ(locator.locate(p), expected)
          << p.x << ", " << p.y << " in a ring of " << ring.size();
      inside += expected == Location::inside;
      boundary += expected == Location::boundary;
    }
  }
  EXPECT_GT(inside, 10000u);
  EXPECT_GT(boundary, 1000u);
}

// Distance searches keep the least square and take one square root (issue 17): that must be the
// least of the distances to the last bit, at every scale and for degenerate segments.
TEST(Geometry, Issue17_LeastSquaredDistanceGivesTheLeastDistanceExactly) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int group = 0; group < 2000; ++group) {
    const double scale = std::ldexp(1.0, exponent(random));
    auto point = [&] { return Vec2{scale * unit(random), scale * unit(random)}; };
    const Vec2 p = point();
    double least = std::numeric_limits<double>::infinity();
    double least_squared = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 12; ++k) {
      const Vec2 a = point();
      // Every fourth segment is a point, and every fourth nearly one.
      const Vec2 b = k % 4 == 0 ? a : (k % 4 == 1 ? a + Vec2{scale * 1e-13, 0} : point());
      const double distance = point_segment_distance(p, a, b);
      EXPECT_EQ(distance, std::sqrt(point_segment_distance_squared(p, a, b)));
      EXPECT_EQ(distance, project_on_segment(p, a, b).distance);
      least = std::min(least, distance);
      least_squared = std::min(least_squared, point_segment_distance_squared(p, a, b));
    }
    EXPECT_EQ(least, std::sqrt(least_squared)) << "group " << group;
  }
}

TEST(Geometry, ConvexHullIsStrictlyConvexAndContainsEveryPoint) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> grid(0, 12);  // many collinear and repeated points
  for (int trial = 0; trial < 200; ++trial) {
    Ring points;
    for (int i = 0; i < 40; ++i) points.push_back({double(grid(random)), double(grid(random))});
    const Ring hull = convex_hull(points);
    ASSERT_GE(hull.size(), 3u);
    for (std::size_t i = 0; i < hull.size(); ++i) {
      ASSERT_GT(orientation(hull[i], hull[(i + 1) % hull.size()], hull[(i + 2) % hull.size()]), 0);
    }
    for (Vec2 p : points) ASSERT_NE(locate_point(hull, p), Location::outside);
  }
  EXPECT_EQ(convex_hull({{0, 0}, {1, 1}, {2, 2}, {1, 1}}).size(), 2u);
  EXPECT_EQ(convex_hull({{3, 3}, {3, 3}}).size(), 1u);
}

TEST(Geometry, MinimumEnclosingCircleMatchesBruteForce) {
  std::mt19937 random(11);
  std::normal_distribution<double> normal(0.0, 10.0);
  for (int trial = 0; trial < 100; ++trial) {
    Ring points;
    for (int i = 0; i < 15; ++i) points.push_back({normal(random), normal(random)});
    const Circle circle = minimum_enclosing_circle(points);
    for (Vec2 p : points) {
      ASSERT_LE(std::hypot(p.x - circle.center.x, p.y - circle.center.y),
                circle.radius * (1 + 1e-9));
    }
    // The smallest circle through 2 or 3 of the points that holds them all.
    double best = 1e300;
    auto try_circle = [&](Vec2 center, double radius) {
      for (Vec2 p : points) {
        if (std::hypot(p.x - center.x, p.y - center.y) > radius * (1 + 1e-9)) return;
      }
      best = std::min(best, radius);
    };
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        try_circle((points[i] + points[j]) * 0.5,
                   std::hypot(points[i].x - points[j].x, points[i].y - points[j].y) / 2);
        for (std::size_t k = j + 1; k < n; ++k) {
          const Circle c = minimum_enclosing_circle({points[i], points[j], points[k]});
          try_circle(c.center, c.radius);
        }
      }
    }
    EXPECT_NEAR(circle.radius, best, 1e-9 * best);
  }
}

// Before the centre was computed on differences scaled by a power of two, its products of three
// coordinate differences overflowed beyond about 1e100 (R came back infinite, and τ = 1% of R with
// it) and underflowed below about 1e-100 (R = 0). Scaling by a power of two is exact, so the circle
// of scaled points is the circle of the points scaled, bit for bit.
TEST(Geometry, MinimumEnclosingCircleScalesExactlyWithItsPoints) {
  std::mt19937 random(12);
  std::normal_distribution<double> normal(0.0, 100.0);
  for (int trial = 0; trial < 50; ++trial) {
    Ring points;
    for (int i = 0; i < 40; ++i) points.push_back({normal(random), normal(random)});
    const Circle circle = minimum_enclosing_circle(points);
    ASSERT_GT(circle.radius, 0.0);
    for (int exponent : {-450, -300, -120, 120, 300, 480}) {
      Ring scaled = points;
      for (Vec2& p : scaled) p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)};
      const Circle expected{
          {std::ldexp(circle.center.x, exponent), std::ldexp(circle.center.y, exponent)},
          std::ldexp(circle.radius, exponent)};
      const Circle found = minimum_enclosing_circle(scaled);
      EXPECT_EQ(found.radius, expected.radius) << "trial " << trial << ", 2^" << exponent;
      EXPECT_EQ(found.center.x, expected.center.x) << "trial " << trial << ", 2^" << exponent;
      EXPECT_EQ(found.center.y, expected.center.y) << "trial " << trial << ", 2^" << exponent;
    }
  }
}

}  // namespace
}  // namespace hullcook
