// Slicing asks RunsOfRing whether a cut is an inner diagonal of what is left of a piece; it must
// answer as is_inner_diagonal's scan of every edge does (stop 50: it skips the boxes of edges
// that the diagonal surely misses).
#include "diagonals.h"

#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace hullcook {
namespace {

// A star-shaped ring round the origin: n angles in order, each at a random radius, some vertices
// put on the line of their neighbours (collinear runs), scaled and moved.
Ring star(std::mt19937& random, std::size_t n, double scale, Vec2 offset) {
  std::uniform_real_distribution<double> radius(0.2, 1.0), unit(0.0, 1.0);
  Ring ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = 2 * M_PI * (double(k) + 0.8 * unit(random)) / double(n);
    ring.push_back(radius(random) * Vec2{std::cos(angle), std::sin(angle)});
  }
  for (std::size_t k = 1; k + 1 < n; k += 7) ring[k] = 0.5 * (ring[k - 1] + ring[k + 1]);
  for (Vec2& v : ring) v = v * scale + offset;
  return ring;
}

TEST(RunsOfRing, AnswersAsAScanOfEveryEdge) {
  std::mt19937 random(50);
  std::size_t inner = 0, crossing = 0, asked = 0;
  for (const auto& [scale, offset] : std::vector<std::pair<double, Vec2>>{
           {1.0, {0, 0}}, {1e-6, {0, 0}}, {1e3, {1e6, -1e6}}, {50, {3, 4}}}) {
    for (int shape = 0; shape < 6; ++shape) {
      const Ring base = star(random, 300, scale, offset);
      const RunsOfRing runs(base);
      for (int run = 0; run < 20; ++run) {
        std::uniform_int_distribution<std::size_t> pick_first(0, base.size() - 4);
        const std::size_t first = pick_first(random);
        std::uniform_int_distribution<std::size_t> pick_size(4, base.size() - first);
        const std::size_t size = pick_size(random);
        const Ring ring(base.begin() + std::ptrdiff_t(first),
                        base.begin() + std::ptrdiff_t(first + size));
        std::uniform_int_distribution<std::size_t> pick(0, size - 1);
        for (int ask = 0; ask < 40; ++ask) {
          const std::size_t i = pick(random), j = pick(random);
          if (i == j) continue;
          SCOPED_TRACE("scale " + std::to_string(scale) + ", first " + std::to_string(first) +
                       ", size " + std::to_string(size) + ", i " + std::to_string(i) + ", j " +
                       std::to_string(j));
          const bool expected = is_inner_diagonal(ring, i, j);
          ASSERT_EQ(runs.is_inner_diagonal(ring, first, i, j), expected);
          ++asked;
          inner += expected;
          // Cuts that cross an edge: what the boxes must not skip.
          for (std::size_t k = 0; k < size; ++k) {
            const std::size_t next = (k + 1) % size;
            if (k == i || k == j || next == i || next == j) continue;
            if (segments_intersect(ring[i], ring[j], ring[k], ring[next])) {
              ++crossing;
              break;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(inner, asked / 20);
  EXPECT_GT(asked - inner, asked / 10);
  EXPECT_GT(crossing, asked / 10);
}

}  // namespace
}  // namespace hullcook
