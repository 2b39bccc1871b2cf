// width_of by rotating calipers against the scan of every vertex per edge.
#include "convex_width.h"

#include "hullcook/core/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hullcook {
namespace {

// Circles, ellipses of aspect up to 10^4, jittered radii, thin arcs' hulls and points far from
// the origin: convex hulls of 64 to 4,000 vertices, with long nearly straight runs where a
// rounding step back could stop the calipers short.
TEST(ConvexWidth, Stop56_CalipersGiveTheScansWidthOnHullsOfManyVertices) {
  std::mt19937_64 random(20261207);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, calipers = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 64 + static_cast<int>(unit(random) * (trial % 10 == 0 ? 4000 : 400));
    const double aspect = std::pow(10.0, 4 * unit(random));
    const double jitter = std::pow(10.0, -3 - 9 * unit(random));
    // Every fifth: a sliver of a huge circle, whose turns are near the rounding of its heights.
    const bool sliver = trial % 5 == 1;
    const double sweep = sliver           ? 1e-6 * (1 + unit(random))
                         : trial % 3 == 0 ? 2 * M_PI
                                          : (0.05 + 1.5 * unit(random)) * M_PI;
    const Vec2 offset = trial % 4 == 0 ? Vec2{1e6 * unit(random), -1e7 * unit(random)} : Vec2{};
    const double radius =
        sliver ? std::pow(10.0, 8 + 4 * unit(random)) : std::pow(10.0, -3 + 7 * unit(random));
    Ring points;
    for (int i = 0; i < n; ++i) {
      const double angle = sweep * i / n + 0.3 * trial;
      const double r = radius * (1 + jitter * (unit(random) - 0.5));
      points.push_back(offset + Vec2{r * std::cos(angle), r / aspect * std::sin(angle)});
    }
    const Ring hull = convex_hull(points);
    if (hull.size() < 3) continue;
    ++compared;
    calipers += hull.size() >= kCalipersFrom;
    ASSERT_EQ(width_of(hull), width_of_by_scan(hull))
        << "trial " << trial << ": " << hull.size() << " vertices, aspect " << aspect;
  }
  EXPECT_GT(compared, 280);
  EXPECT_GT(calipers, 150);
  // A lens 2e-15 thick over 2 long, turned by 30 degrees: its heights tie within rounding over
  // runs longer than the calipers look ahead (the stop 56 review: 3.998e-15 against 4e-15), so it
  // takes the scan.
  Ring lens;
  for (int side : {1, -1}) {
    for (int i = 0; i <= 200; ++i) {
      const double x = side * (-1 + 2.0 * i / 200), y = side * 2e-15 * (1 - x * x);
      lens.push_back({x * std::cos(M_PI / 6) - y * std::sin(M_PI / 6),
                      x * std::sin(M_PI / 6) + y * std::cos(M_PI / 6)});
    }
  }
  const Ring lens_hull = convex_hull(lens);
  ASSERT_GE(lens_hull.size(), kCalipersFrom);
  EXPECT_EQ(width_of(lens_hull), width_of_by_scan(lens_hull));
  // A rectangle: its width is its shorter side, however many points its long sides carry.
  Ring rectangle;
  for (int i = 0; i <= 100; ++i) rectangle.push_back({i * 0.5, 0.0});
  for (int i = 100; i >= 0; --i) rectangle.push_back({i * 0.5, 0.25});
  EXPECT_EQ(width_of(convex_hull(rectangle)), 0.25);
}

}  // namespace
}  // namespace hullcook
