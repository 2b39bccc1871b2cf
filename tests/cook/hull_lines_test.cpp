// HullLines answers as a scan of every line does (issue 17's review: a hull of 100,000 vertices
// took 38 s to check against its component, every vertex measured against every line; its runs of
// lines now skip what cannot hold an answer).
#include "hull_lines.h"
#include "nearest_edges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace hullcook {
namespace {

std::pair<double, std::size_t> scanned_nearest(const HullLines& lines, Vec2 p) {
  std::pair<double, std::size_t> best{std::numeric_limits<double>::infinity(), 0};
  for (std::size_t k = 0; k < lines.size(); ++k) best = std::min(best, {lines.distance(k, p), k});
  return best;
}

bool scanned_one_within(const HullLines& lines, Vec2 p, Vec2 q, double limit) {
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (lines.distance(k, p) <= limit && lines.distance(k, q) <= limit) return true;
  }
  return false;
}

// Convex counter-clockwise hulls: regular polygons, flat ellipses, and polygons whose vertices
// crowd on a few directions (runs of nearly collinear edges), at scales and offsets from tiny to
// huge.
std::vector<Ring> hulls(std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Ring> result;
  for (int trial = 0; trial < 60; ++trial) {
    const int n =
        trial % 3 == 0 ? 3 + trial : static_cast<int>(std::pow(10.0, 1 + 2.5 * unit(random)));
    const double scale = std::pow(10.0, -6 + 14 * unit(random));
    const Vec2 offset = scale * std::pow(10.0, 3 * unit(random)) * Vec2{unit(random), unit(random)};
    const double flat = trial % 4 == 1 ? 1e-3 : 0.2 + unit(random);
    Ring hull;
    for (int i = 0; i < n; ++i) {
      double angle = 2 * M_PI * i / n;
      // Crowded: most vertices within a few degrees of four directions.
      if (trial % 4 == 2) angle += 0.4 * std::sin(4 * angle);
      hull.push_back(offset + scale * Vec2{std::cos(angle), flat * std::sin(angle)});
    }
    result.push_back(hull);
  }
  return result;
}

TEST(HullLines, Issue17_NearestAndOneWithinAnswerAsAScanOfEveryLine) {
  std::mt19937 random(1717);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t queries = 0, large = 0, ties = 0;
  for (const Ring& hull : hulls(random)) {
    HullLines lines;
    lines.assign(hull);
    ASSERT_EQ(lines.size(), hull.size());
    large += hull.size() >= 64;
    const std::size_t n = hull.size();
    double size = 0;
    for (Vec2 v : hull)
      size = std::max({size, std::abs(v.x - hull[0].x), std::abs(v.y - hull[0].y)});
    std::vector<Vec2> points;
    for (std::size_t i = 0; i < n; i += 1 + n / 50) {
      const Vec2 a = hull[i], b = hull[(i + 1) % n], c = hull[(i + n / 2) % n];
      points.push_back(a);                                    // a vertex: on two lines
      points.push_back((a + b) * 0.5);                        // on a line
      points.push_back(a + (c - a) * unit(random));           // inside
      points.push_back(a + (a - c) * (1e-9 * unit(random)));  // just outside
      points.push_back(a + (a - c) * (2 * unit(random)));     // far outside
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec2 p = points[i], q = points[(i * 7 + 3) % points.size()];
      const auto expected = scanned_nearest(lines, p);
      for (std::size_t hint : {std::size_t{0}, n - 1, i % n, expected.second}) {
        ASSERT_EQ(lines.nearest(p, hint), expected)
            << n << " lines, point " << i << ", hint " << hint;
      }
      // Limits at a distance measured (ties), between them, and none.
      const std::size_t k = (i * 13) % n;
      for (double limit : {lines.distance(k, p), lines.distance(k, q), expected.first,
                           expected.first + 1e-3 * size, -size, size}) {
        ties += limit == lines.distance(k, p);
        ASSERT_EQ(lines.one_within(p, q, limit), scanned_one_within(lines, p, q, limit))
            << n << " lines, points " << i << ", limit " << limit;
      }
      ++queries;
    }
  }
  // A point that is not finite (the review: a NaN hint pinned the answer to itself).
  const Ring circle = [] {
    Ring ring;
    for (int i = 0; i < 100; ++i)
      ring.push_back({std::cos(i * M_PI / 50), std::sin(i * M_PI / 50)});
    return ring;
  }();
  HullLines lines;
  lines.assign(circle);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = HUGE_VAL;
  for (const Vec2 p : {Vec2{nan, 0}, Vec2{inf, inf}, Vec2{-inf, 1}, Vec2{0, nan}}) {
    EXPECT_EQ(lines.nearest(p, 25), scanned_nearest(lines, p)) << p.x << ", " << p.y;
  }
  EXPECT_GT(queries, 5000u);
  EXPECT_GT(large, 20u);  // hulls whose queries skip runs of lines
  EXPECT_GT(ties, 1000u);
}

// NearestEdges (HullFitter's depths) against a scan of every edge, on the same hulls and points
// near them, inside, on them and far away.
TEST(NearestEdges, Issue17_NearestEdgeAsAScanOfEveryEdge) {
  std::mt19937 random(1718);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t queries = 0;
  for (const Ring& hull : hulls(random)) {
    const NearestEdges nearest(hull);
    const std::size_t n = hull.size();
    std::size_t hint = 0;
    for (std::size_t i = 0; i < n; i += 1 + n / 40) {
      const Vec2 a = hull[i], b = hull[(i + 1) % n], c = hull[(i + n / 2) % n];
      for (const Vec2 p : {a, (a + b) * 0.5, a + (c - a) * unit(random), a + (a - c) * 1e-9,
                           a + (a - c) * (3 * unit(random))}) {
        std::pair<double, std::size_t> expected{std::numeric_limits<double>::infinity(), 0};
        for (std::size_t k = 0; k < n; ++k) {
          const double squared = point_segment_distance_squared(p, hull[k], hull[(k + 1) % n]);
          if (squared < expected.first) expected = {squared, k};
        }
        for (std::size_t h : {hint, std::size_t{0}, n - 1, expected.second}) {
          ASSERT_EQ(nearest(p, h), expected) << n << " edges, vertex " << i << ", hint " << h;
        }
        hint = expected.second;
        ++queries;
      }
    }
  }
  EXPECT_GT(queries, 5000u);
}

}  // namespace
}  // namespace hullcook
