// The contract's k-d tree of corners (point_tree.h): every point within the margin of a segment
// is visited, once, on clustered, repeated and spread points, for segments of every direction.
#include "point_tree.h"

#include "hullcook/core/geometry.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace hullcook {
namespace {

TEST(PointTree, VisitsEveryPointNearASegmentOnce) {
  std::mt19937 random(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Vec2> points;
    const int count = 1 + trial * 37;
    for (int k = 0; k < count; ++k) {
      switch (k % 4) {
        case 0:  // spread
          points.push_back({100 * unit(random), 100 * unit(random)});
          break;
        case 1:  // crowded into a tiny core
          points.push_back({50 + 1e-6 * unit(random), 50 + 1e-6 * unit(random)});
          break;
        case 2:  // on a vertical line
          points.push_back({25.0, 100 * unit(random)});
          break;
        default:  // repeated
          points.push_back(points[std::size_t(k) / 2]);
      }
    }
    const detail::PointTree tree(points);
    for (int query = 0; query < 40; ++query) {
      Vec2 a{100 * unit(random), 100 * unit(random)}, b{100 * unit(random), 100 * unit(random)};
      if (query % 5 == 1) b.x = a.x;  // vertical
      if (query % 5 == 2) b.y = a.y;  // horizontal
      if (query % 5 == 3) b = a;      // a point
      if (query % 5 == 4) a = {50, 50};
      const double margin = query % 2 ? 1e-3 : 5.0 * unit(random);
      std::vector<int> visits(points.size(), 0);
      tree.for_each_near(a, b, margin, 1e-9 * 100, [&](std::size_t k) { ++visits[k]; });
      for (std::size_t k = 0; k < points.size(); ++k) {
        ASSERT_LE(visits[k], 1) << "trial " << trial << " query " << query;
        if (point_segment_distance(points[k], a, b) <= margin) {
          ASSERT_EQ(visits[k], 1) << "trial " << trial << " query " << query << " point " << k;
        }
      }
    }
  }
}

}  // namespace
}  // namespace hullcook
