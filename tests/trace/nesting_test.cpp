// The tracer's ring geometry (tool/trace/src/rings.h, internal): which ring encloses which, and
// which rings break the orientation rule (outer boundaries counter-clockwise, holes clockwise),
// checked against a brute-force even-odd count; and the simplification of long rings, checked
// against a plain Douglas-Peucker.
#include "rings.h"

#include "hullcook/core/geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace hullcook::trace_detail {
namespace {

Ring rectangle(double x0, double y0, double x1, double y1, bool outer) {
  Ring ring{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  if ((signed_area(ring) > 0) != outer) std::reverse(ring.begin(), ring.end());
  return ring;
}

Ring oriented(Ring ring, bool outer) {
  if ((signed_area(ring) > 0) != outer) std::reverse(ring.begin(), ring.end());
  return ring;
}

bool inside(const Ring& ring, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 c = ring[i], d = ring[(i + 1) % n];
    if ((c.y > p.y) != (d.y > p.y) && p.x < c.x + (d.x - c.x) * (p.y - c.y) / (d.y - c.y)) {
      in = !in;
    }
  }
  return in;
}

// What nesting_parents must say of each ring, found by brute force: the ring a leftward ray from
// its leftmost (then lowest) vertex meets first, vertices and horizontal edges included, and
// whether that ring encloses it (tested at the ring's vertex average, which no other ring
// touches in these cases).
void expect_nesting_as_brute_force(const std::vector<Ring>& rings, const std::string& what) {
  std::vector<char> misplaced;
  const std::vector<int> parents = nesting_parents(rings, 1, &misplaced);
  ASSERT_EQ(misplaced.size(), rings.size()) << what;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    Vec2 p = rings[r][0], middle{0, 0};
    for (Vec2 v : rings[r]) {
      if (v.x < p.x || (v.x == p.x && v.y < p.y)) p = v;
      middle += v / static_cast<double>(rings[r].size());
    }
    int hit = -1;
    double hit_x = std::numeric_limits<double>::lowest();
    for (std::size_t s = 0; s < rings.size(); ++s) {
      if (s == r) continue;
      for (std::size_t i = 0, n = rings[s].size(); i < n; ++i) {
        const Vec2 a = rings[s][i], b = rings[s][(i + 1) % n];
        if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) continue;
        const double x =
            a.y == b.y ? std::max(a.x, b.x) : a.x + (b.x - a.x) * (p.y - a.y) / (b.y - a.y);
        if (x < p.x && x > hit_x) hit_x = x, hit = static_cast<int>(s);
      }
    }
    const std::string ring = what + ", ring " + std::to_string(r);
    if (hit < 0) {
      EXPECT_EQ(parents[r], -1) << ring;
      EXPECT_EQ(misplaced[r], 0) << ring;
      continue;
    }
    const bool outer = signed_area(rings[r]) > 0, hit_outer = signed_area(rings[hit]) > 0;
    const bool encloses = inside(rings[hit], middle);
    EXPECT_EQ(misplaced[r] != 0, encloses != (outer != hit_outer)) << ring << ", hit " << hit;
  }
}

// The ray from a ring's leftmost vertex meets the ring hit exactly at a vertex, in each way that
// can happen: a vertex in a straight run (one of its edges crosses a ray just above the row), the
// right end of a horizontal edge above or below the ring hit, and a turn in y (both edges or
// neither cross), with the ring inside or beside the ring hit and either orientation.
TEST(Nesting, RayThroughAVertexOfTheRingHitInEveryWay) {
  const double py = 40;
  for (bool small_outer : {false, true}) {
    for (bool big_outer : {false, true}) {
      const Ring small = rectangle(50, py, 60, py + 10, small_outer);
      const std::vector<std::pair<std::string, Ring>> bigs = {
          {"enclosing, a vertex on its left side",
           oriented({{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, py}}, big_outer)},
          {"beside, a vertex on its right side",
           oriented({{0, 0}, {10, 0}, {10, py}, {10, 100}, {0, 100}}, big_outer)},
          {"beside, its top edge at the row", rectangle(0, py, 10, py + 30, big_outer)},
          {"beside, its bottom edge at the row", rectangle(0, py - 30, 10, py, big_outer)},
          {"beside, a turn down at the row",
           oriented({{0, py + 20}, {10, py}, {20, py + 20}}, big_outer)},
          {"beside, a turn up at the row",
           oriented({{0, py - 20}, {20, py - 20}, {10, py}}, big_outer)},
          {"enclosing, a notch of its left side pointing at the row",
           oriented({{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, py + 5}, {8, py}, {0, py - 5}},
                    big_outer)},
          {"enclosing, a step of its left side at the row",
           oriented({{0, 0}, {100, 0}, {100, 100}, {5, 100}, {5, py}, {0, py}}, big_outer)},
      };
      for (const auto& [name, big] : bigs) {
        expect_nesting_as_brute_force({big, small}, name + (small_outer ? ", outer" : ", hole") +
                                                        (big_outer ? " in outer" : " in hole"));
      }
    }
  }
}

// Seeded random rectangles on an integer grid, some nested, each of a random orientation: rows of
// them share their top and bottom rows, so the rays meet vertices and horizontal edges often.
TEST(Nesting, RandomRectanglesOnAGridAsByBruteForce) {
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    std::uint32_t state = seed * 2654435761u;
    auto random = [&](std::uint32_t below) {
      state ^= state << 13, state ^= state >> 17, state ^= state << 5;
      return static_cast<int>(state % below);
    };
    std::vector<Ring> rings;
    for (int row = 0; row < 6; ++row) {
      for (int column = 0; column < 6; ++column) {
        if (random(4) == 0) continue;
        const int x0 = column * 12 + random(2), y0 = row * 12 + random(2);
        const int x1 = column * 12 + 10 - random(2), y1 = row * 12 + 10 - random(2);
        rings.push_back(rectangle(x0, y0, x1, y1, random(2) == 0));
        if (random(2) == 0) {
          rings.push_back(
              rectangle(x0 + 2, y0 + 1 + random(2), x1 - 2 - random(2), y1 - 2, random(2) == 0));
        }
      }
    }
    expect_nesting_as_brute_force(rings, "seed " + std::to_string(seed));
  }
}

// Enough edges (over 2^18) that nesting splits its bucket grid into bands of rows, one per
// thread: the parents and the misplaced rings of one thread, whatever the count. Rectangles on a
// grid, some with a ring inside, either orientation (so some misplaced), their rows staggered.
TEST(Nesting, Issue17_BandsOnThreadsGiveTheOneThreadParents) {
  std::uint32_t state = 20261205u;
  auto random = [&](std::uint32_t below) {
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;
    return static_cast<int>(state % below);
  };
  std::vector<Ring> rings;
  std::size_t edges = 0;
  for (int row = 0; row < 300; ++row) {
    for (int column = 0; column < 300; ++column) {
      if (random(4) == 0) continue;
      const int x0 = column * 12 + random(2), y0 = row * 12 + random(3);
      const int x1 = column * 12 + 10 - random(2), y1 = row * 12 + 10 - random(3);
      rings.push_back(rectangle(x0, y0, x1, y1, random(8) != 0));
      if (random(2) == 0) {
        rings.push_back(
            rectangle(x0 + 2, y0 + 1 + random(2), x1 - 2 - random(2), y1 - 2, random(8) == 0));
      }
    }
  }
  for (const Ring& ring : rings) edges += ring.size();
  ASSERT_GE(edges, std::size_t{1} << 18);
  std::vector<char> misplaced_one;
  const std::vector<int> parents_one = nesting_parents(rings, 1, &misplaced_one);
  ASSERT_GT(std::count(misplaced_one.begin(), misplaced_one.end(), 1), 0);
  for (unsigned threads : {2u, 3u}) {
    std::vector<char> misplaced;
    EXPECT_EQ(nesting_parents(rings, threads, &misplaced), parents_one) << threads << " threads";
    EXPECT_EQ(misplaced, misplaced_one) << threads << " threads";
  }
}

// Douglas-Peucker as the simplifier runs it, plainly: from the leftmost (then lowest) vertex and
// the vertex farthest from it, each stretch split at its interior vertex farthest from its chord,
// the first of equal distances, while that lies more than eps away.
Ring plain_douglas_peucker(const Ring& ring, double eps) {
  const int n = static_cast<int>(ring.size());
  auto farthest = [&](int from, int to, Vec2 a, Vec2 b) {
    int index = -1;
    double best = -1;
    for (int i = (from + 1) % n; i != to; i = (i + 1) % n) {
      const double distance = std::sqrt(point_segment_distance_squared(ring[i], a, b));
      if (distance > best) best = distance, index = i;
    }
    return std::pair{index, best};
  };
  int a = 0;
  for (int i = 1; i < n; ++i) {
    if (ring[i].x < ring[a].x || (ring[i].x == ring[a].x && ring[i].y < ring[a].y)) a = i;
  }
  int b = 0;
  double far = -1;
  for (int i = 0; i < n; ++i) {
    const Vec2 v = ring[i] - ring[a];
    const double distance = std::sqrt(v.x * v.x + v.y * v.y);
    if (distance > far) far = distance, b = i;
  }
  std::vector<char> keep(n, 0);
  keep[a] = keep[b] = 1;
  std::vector<std::pair<int, int>> stack{{a, b}, {b, a}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const auto [m, distance] = farthest(i, j, ring[i], ring[j]);
    if (m < 0 || distance <= eps) continue;
    keep[m] = 1;
    stack.emplace_back(i, m);
    stack.emplace_back(m, j);
  }
  Ring kept;
  for (int i = 0; i < n; ++i) {
    if (keep[i]) kept.push_back(ring[i]);
  }
  return kept;
}

// Rings of thousands of vertices are searched for their farthest vertex by blocks, skipping
// those whose bounding box lies nearer than a distance already found (a plain scan peeled one
// tooth a level off a comb: quadratic). The vertices kept must be the plain scan's, ties
// included: combs whose teeth end on one line (every tip at the same distance from a chord along
// them) and combs of jittered teeth (seeded), with the teeth far enough apart for no chord to
// come near another tooth.
TEST(Simplify, LongRingsKeepThePlainDouglasPeuckerVertices) {
  for (std::uint32_t seed = 0; seed <= 6; ++seed) {
    std::uint32_t state = seed * 2654435761u + 1;
    auto jitter = [&] {
      if (seed == 0) return 0.0;
      state ^= state << 13, state ^= state >> 17, state ^= state << 5;
      return (static_cast<double>(state % 1000) / 1000 - 0.5) * 0.6;
    };
    // Counter-clockwise (y up): along the base, then up and down each tooth in unit steps. The
    // corners are exact; the steps between them move off their line by the jitter, which is
    // small enough to keep the ring simple.
    Ring comb;
    // Seed 6's 600 teeth make a tree of boxes ten levels deep.
    const int teeth = seed == 6 ? 600 : 100 + 10 * static_cast<int>(seed), height = 40;
    comb.push_back({0, 0});
    for (int x = 1; x < 10 * teeth; ++x) comb.push_back({double(x), jitter() * 0.1});
    comb.push_back({10.0 * teeth, 0});
    for (int t = teeth - 1; t >= 0; --t) {
      const double x0 = 10.0 * t;
      comb.push_back({x0 + 10, 1});
      for (int y = 2; y < height; ++y) comb.push_back({x0 + 10 + jitter() * 0.3, double(y)});
      comb.push_back({x0 + 10, double(height)});
      for (int x = 1; x < 4; ++x) comb.push_back({x0 + 10 - x, height + jitter() * 0.3});
      comb.push_back({x0 + 6, double(height)});
      for (int y = height - 1; y > 1; --y) comb.push_back({x0 + 6 + jitter() * 0.3, double(y)});
      comb.push_back({x0 + 6, 1});
      // The floor of the slot before the next tooth (the last tooth's leads to the start).
      for (int x = 1; x < 6 && t > 0; ++x) comb.push_back({x0 + 6 - x, 1 + jitter() * 0.3});
    }
    ASSERT_GT(comb.size(), 8000u);  // searched by blocks
    ASSERT_GT(signed_area(comb), 0);
    // Started mid-ring too, so that the ranges searched wrap past the ring's last vertex and
    // start and end inside blocks.
    Ring turned = comb;
    std::rotate(turned.begin(), turned.begin() + static_cast<long>(comb.size() / 3 + seed),
                turned.end());
    for (const Ring* ring : {&comb, &turned}) {
      for (double eps : {0.05, 0.25}) {
        const std::vector<Ring> simplified = simplify_rings({*ring}, {-1}, eps);
        ASSERT_EQ(simplified.size(), 1u);
        EXPECT_EQ(simplified[0], plain_douglas_peucker(*ring, eps))
            << "seed " << seed << ", eps " << eps << (ring == &turned ? ", turned" : "");
      }
    }
  }
}

// Review 52: a stretch that runs to the ring's end from inside the block before the ring's short
// last block (8,300 vertices: blocks of 128 end at 8,192) was bounded by its first block's box
// alone, and a spike in the last block was dropped: a vertex 94 px from the ring simplified at
// eps 60. The ring starts (its leftmost vertex) at index 8,100, so that the bottom chain from it
// wraps past the last index: a deep spike on that chain's first hundred vertices (the last
// block), a smaller one further on. The top runs back 90 above (more than eps: no simplified edge
// touches another; less than 94: the bottom's far end stays the vertex farthest from the start)
// and comes down to the start in steps, so that the start's block lies near the bottom's chord.
TEST(Simplify, Review52_AStretchEndingInTheShortLastBlockKeepsItsFarthestVertex) {
  const int n = 8300, leftmost = 8100, right = 4200, steps = 40;
  auto bottom = [](double x) {
    if (x > 100 && x < 200) return -100 * (1 - std::abs(x - 150) / 50);
    if (x > 1150 && x < 1250) return -50 * (1 - std::abs(x - 1200) / 50);
    return 0.0;
  };
  Ring ring(n);
  const int along = n - leftmost + right;  // the bottom chain's last x
  for (int k = 0; k <= along; ++k) ring[(leftmost + k) % n] = Vec2{double(k), bottom(k)};
  const int top = leftmost - right - 1 - steps;
  for (int k = 0; k < top; ++k) {
    ring[right + 1 + k] = Vec2{(along - 1) - (along - 3) * k / double(top - 1), 90.0};
  }
  for (int k = 0; k < steps; ++k) ring[right + 1 + top + k] = Vec2{1.0, double(steps - k)};
  ASSERT_GT(signed_area(ring), 0);
  for (double eps : {60.0, 30.0, 0.5}) {
    const std::vector<Ring> simplified = simplify_rings({ring}, {-1}, eps);
    ASSERT_EQ(simplified.size(), 1u);
    EXPECT_EQ(simplified[0], plain_douglas_peucker(ring, eps)) << "eps " << eps;
  }
}

}  // namespace
}  // namespace hullcook::trace_detail
