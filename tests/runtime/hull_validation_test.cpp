// The hull checks that Bundle::open runs on every stored vertex, against SPEC §8's rule written
// plainly (one hull at a time, the winding by the signs of the edges' components): on convex,
// reflex, straight, repeated, clockwise and twice-winding hulls, small and wide coordinates,
// hulls longer than a batch, and broken vertex ranges.
#include "../../runtime/src/hull_validation.h"
#include "hullcook/format/bundle_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace hullcook {
namespace {

using runtime::Status;

struct Point {
  std::int32_t x, y;
};

// SPEC §8 as written: every turn strictly left, and the edges' x components, and their y
// components, change sign at most twice around the hull (zero components skipped).
bool spec_convex(const std::vector<Point>& hull) {
  const std::size_t n = hull.size();
  if (n < 3) return false;
  auto edge = [&](std::size_t i) {
    const Point a = hull[i % n], b = hull[(i + 1) % n];
    return Point{b.x - a.x, b.y - a.y};
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Point e = edge(i), f = edge(i + 1);
    if (std::int64_t{e.x} * f.y - std::int64_t{e.y} * f.x <= 0) return false;
  }
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<int> signs;
    for (std::size_t i = 0; i < n; ++i) {
      const std::int32_t c = axis == 0 ? edge(i).x : edge(i).y;
      if (c != 0) signs.push_back(c > 0 ? 1 : -1);
    }
    int changes = 0;
    for (std::size_t i = 0; i < signs.size(); ++i)
      changes += signs[i] != signs[(i + 1) % signs.size()];
    if (changes > 2) return false;
  }
  return true;
}

struct Section {
  std::vector<unsigned char> records, vertices;
  std::vector<std::uint32_t> firsts;
  std::vector<std::vector<Point>> hulls;

  void add(const std::vector<Point>& hull) {
    firsts.push_back(static_cast<std::uint32_t>(vertices.size() / 4));
    hulls.push_back(hull);
    for (const Point& p : hull) {
      const format::VertexRecord v{static_cast<std::int16_t>(p.x), static_cast<std::int16_t>(p.y)};
      vertices.resize(vertices.size() + 4);
      std::memcpy(vertices.data() + vertices.size() - 4, &v, 4);
    }
  }
  std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(vertices.size() / 4); }
  Status validate() {
    records.assign(firsts.size() * sizeof(format::HullRecord), 0);
    for (std::size_t h = 0; h < firsts.size(); ++h)
      std::memcpy(records.data() + h * sizeof(format::HullRecord), &firsts[h], 4);
    vertices.resize(vertices.size() + 64);  // bytes after the section, as in a bundle
    const Status status = runtime::detail::validate_hulls(
        records.data(), static_cast<std::uint32_t>(firsts.size()), vertices.data(),
        static_cast<std::uint32_t>(vertices.size() / 4 - 16));
    vertices.resize(vertices.size() - 64);
    return status;
  }
  // What a hull-by-hull check of SPEC §8 and §11 returns.
  Status expected() const {
    if (!firsts.empty() && firsts[0] != 0) return Status::malformed;
    for (std::size_t h = 0; h < firsts.size(); ++h) {
      const std::uint32_t end = h + 1 < firsts.size() ? firsts[h + 1] : vertex_count();
      if (end > vertex_count()) return Status::out_of_bounds;
      if (end < firsts[h] || end - firsts[h] < 3) return Status::malformed;
      std::vector<Point> hull;
      for (std::uint32_t v = firsts[h]; v < end; ++v) {
        format::VertexRecord r;
        std::memcpy(&r, vertices.data() + 4 * std::size_t{v}, 4);
        hull.push_back({r.dx, r.dy});
      }
      if (!spec_convex(hull)) return Status::malformed;
    }
    return Status::ok;
  }
};

std::vector<Point> polygon(std::mt19937& random, int sides, double radius, int turns = 1) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double phase = unit(random) * 6.283;
  const double cx = (unit(random) - 0.5) * (32767 - radius),
               cy = (unit(random) - 0.5) * (32767 - radius);
  std::vector<Point> points;
  for (int i = 0; i < sides; ++i) {
    const double angle = phase + 6.283185307179586 * turns * i / sides;
    points.push_back({static_cast<std::int32_t>(std::lround(cx + radius * std::cos(angle))),
                      static_cast<std::int32_t>(std::lround(cy + radius * std::sin(angle)))});
  }
  return points;
}

// One random hull: mostly convex, else broken in one of the ways SPEC §8 forbids.
std::vector<Point> random_hull(std::mt19937& random, bool allow_broken) {
  std::uniform_int_distribution<int> pick(0, 99);
  const int size_pick = pick(random);
  const int sides = size_pick < 90 ? 3 + size_pick % 6 : size_pick < 97 ? 9 + size_pick % 24 : 600;
  const double radius =
      pick(random) < 20 ? 16000.0 + 100 * pick(random) : 20.0 + 300 * pick(random);
  if (!allow_broken || pick(random) < 80) return polygon(random, sides, radius);
  std::vector<Point> hull = polygon(random, sides | 1, radius);
  std::uniform_int_distribution<std::size_t> at(0, hull.size() - 1);
  switch (pick(random) % 6) {
    case 0:  // clockwise
      return {hull.rbegin(), hull.rend()};
    case 1:  // a reflex vertex
      hull[at(random)] = {(hull[0].x + hull[hull.size() / 2].x) / 2,
                          (hull[0].y + hull[hull.size() / 2].y) / 2};
      return hull;
    case 2: {  // a repeated vertex
      const std::size_t i = at(random);
      hull.insert(hull.begin() + static_cast<std::ptrdiff_t>(i), hull[i]);
      return hull;
    }
    case 3: {  // a straight turn: an edge's midpoint on exact integers
      const Point a = hull[0], b = hull[1];
      if ((a.x + b.x) % 2 == 0 && (a.y + b.y) % 2 == 0)
        hull.insert(hull.begin() + 1, {(a.x + b.x) / 2, (a.y + b.y) / 2});
      else
        std::swap(hull[0], hull[1]);
      return hull;
    }
    case 4:  // every turn left, winding twice (a star polygon)
      return polygon(random, (sides | 1) < 5 ? 5 : sides | 1, radius, 2);
    default:  // two vertices swapped
      std::swap(hull[at(random)], hull[at(random)]);
      return hull;
  }
}

TEST(HullValidation, AgreesWithTheSpecRuleHullByHull) {
  std::mt19937 random(21);
  int rejected = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Section section;
    const int hulls = 1 + trial % 200;
    const bool broken = trial % 3 == 0;
    for (int h = 0; h < hulls; ++h) section.add(random_hull(random, broken && h % 17 == 3));
    const Status expected = section.expected();
    rejected += expected != Status::ok;
    ASSERT_EQ(section.validate(), expected) << "trial " << trial;
    for (const auto& hull : section.hulls) {
      std::vector<unsigned char> bytes;
      for (const Point& p : hull) {
        const format::VertexRecord v{static_cast<std::int16_t>(p.x),
                                     static_cast<std::int16_t>(p.y)};
        bytes.resize(bytes.size() + 4);
        std::memcpy(bytes.data() + bytes.size() - 4, &v, 4);
      }
      ASSERT_EQ(
          format::hull_is_strictly_convex(bytes.data(), static_cast<std::uint32_t>(hull.size())),
          spec_convex(hull))
          << "trial " << trial;
    }
  }
  // Both outcomes are exercised.
  EXPECT_GT(rejected, 300);
  EXPECT_LT(rejected, 2900);
}

TEST(HullValidation, ReportsBrokenRangesAfterTheConvexityOfEarlierHulls) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 400; ++trial) {
    Section section;
    for (int h = 0; h < 40; ++h) section.add(random_hull(random, trial % 2 == 0 && h == 7));
    std::uniform_int_distribution<std::size_t> hull(1, section.firsts.size() - 1);
    switch (trial % 4) {
      case 0:  // a hull of 2 vertices
        section.firsts[hull(random)] = section.firsts[hull(random)];
        break;
      case 1:  // past the end
        section.firsts.back() = section.vertex_count() + 1;
        break;
      case 2:  // ranges out of order
        std::swap(section.firsts[5], section.firsts[30]);
        break;
      default:  // hull 0 does not start at vertex 0
        section.firsts[0] = 1;
    }
    ASSERT_EQ(section.validate(), section.expected()) << "trial " << trial;
  }
}

TEST(HullValidation, AcceptsTheWidestHullsTheFormatHolds) {
  Section section;
  // Edges spanning the whole 16-bit range: cross products need more than 32 bits.
  section.add({{-32768, -32768}, {32767, -32768}, {32767, 32767}, {-32768, 32767}});
  section.add({{-32768, -32768}, {32767, -32767}, {-32767, 32767}});
  section.add({{-32768, 0}, {0, -32768}, {32767, 0}, {0, 32767}});
  ASSERT_EQ(section.expected(), Status::ok);
  EXPECT_EQ(section.validate(), Status::ok);
  // The same hull clockwise is refused, wide or not.
  section.add({{-32768, 32767}, {32767, 32767}, {32767, -32768}, {-32768, -32768}});
  EXPECT_EQ(section.validate(), Status::malformed);
}

}  // namespace
}  // namespace hullcook
