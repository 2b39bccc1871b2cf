// The validation's sweep (crossing_sweep.h) against every pair, on rings of a few points of a
// small integer grid: shared vertices, T-junctions, collinear overlaps, vertical and horizontal
// edges, holes touching their boundary; and through clean_and_validate on the long spiky shapes
// that made the grid quadratic.
#include "crossing_sweep.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"
#include "hullcook/core/predicates.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace hullcook {
namespace {

using detail::RingEdge;
using ::testing::HasSubstr;

struct Edges {
  std::vector<RingEdge> edges;
  std::vector<std::size_t> ring_sizes;
};

Edges edges_of(const std::vector<Ring>& rings) {
  Edges out;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = rings[r];
    out.ring_sizes.push_back(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
      out.edges.push_back({int(r), i, ring[i], ring[(i + 1) % ring.size()]});
    }
  }
  return out;
}

bool any_pair_meets(const Edges& e) {
  for (std::size_t i = 0; i < e.edges.size(); ++i) {
    for (std::size_t j = i + 1; j < e.edges.size(); ++j) {
      if (detail::consecutive(e.edges[i], e.edges[j], e.ring_sizes)) continue;
      if (segments_intersect(e.edges[i].a, e.edges[i].b, e.edges[j].a, e.edges[j].b)) return true;
    }
  }
  return false;
}

// A ring around a centre, its points at increasing angles and random distances on an integer grid
// (a star-shaped ring: simple but for collinear and touching points), or in random order.
Ring random_ring(std::mt19937& random, int grid, bool star_shaped) {
  std::uniform_int_distribution<int> coordinate(0, grid), count(3, 8);
  const int n = count(random);
  Ring ring;
  if (!star_shaped) {
    for (int i = 0; i < n; ++i)
      ring.push_back({double(coordinate(random)), double(coordinate(random))});
    return ring;
  }
  const Vec2 centre{coordinate(random) + 0.5, coordinate(random) + 0.5};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(2 * std::numbers::pi * unit(random));
  std::sort(angles.begin(), angles.end());
  for (double angle : angles) {
    const double reach = 0.5 + grid * 0.5 * unit(random);
    ring.push_back({std::round(centre.x + reach * std::cos(angle)),
                    std::round(centre.y + reach * std::sin(angle))});
  }
  return ring;
}

TEST(CrossingSweep, AgreesWithEveryPairOnDegenerateRings) {
  std::mt19937 random(20261205);
  int meeting = 0, apart = 0;
  for (int trial = 0; trial < 30000; ++trial) {
    const int grid = 2 + trial % 7;
    const int ring_count = 1 + trial % 3;
    std::vector<Ring> rings;
    for (int r = 0; r < ring_count; ++r) {
      Ring ring = remove_degenerate_vertices(random_ring(random, grid, trial % 4 != 0));
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
    if (rings.empty()) continue;
    // Turned a quarter, mirrored, or scaled to coordinates far from the origin: the sweep's order
    // (x, then y) meets vertical edges and ties differently.
    for (Ring& ring : rings) {
      for (Vec2& p : ring) {
        if (trial % 5 == 1) p = {-p.y, p.x};
        if (trial % 5 == 2) p = {p.x, -p.y};
        if (trial % 5 == 3) p = {p.x * 1e-7 + 12345.0, p.y * 1e-7 - 6789.0};
      }
    }
    const Edges e = edges_of(rings);
    const bool expected = any_pair_meets(e);
    const auto found = detail::find_crossing_by_sweep(e.edges, e.ring_sizes);
    ASSERT_EQ(found.has_value(), expected) << "trial " << trial;
    if (found) {
      const RingEdge& f = e.edges[found->first];
      const RingEdge& g = e.edges[found->second];
      EXPECT_LT(found->first, found->second);
      EXPECT_FALSE(detail::consecutive(f, g, e.ring_sizes));
      EXPECT_TRUE(segments_intersect(f.a, f.b, g.a, g.b));
    }
    (expected ? meeting : apart) += 1;
  }
  // Both answers, many times: a sweep that always said one would fail above.
  EXPECT_GT(meeting, 5000);
  EXPECT_GT(apart, 5000);
}

// A star of long spikes from a tiny core: every spike's edges pass by the centre, where a grid's
// cells held them all (a 32,000-vertex star took 6.4 s to validate).
Ring star(int spikes, double core, double reach) {
  Ring ring;
  for (int i = 0; i < spikes; ++i) {
    const double a = 2 * std::numbers::pi * i / spikes,
                 b = 2 * std::numbers::pi * (i + 0.5) / spikes;
    ring.push_back({reach * std::cos(a), reach * std::sin(a)});
    ring.push_back({core * std::cos(b), core * std::sin(b)});
  }
  return ring;
}

// The validation's error for a region, or "" when it is accepted.
std::string validation_error(const Region& region) {
  try {
    clean_and_validate({region}, "star");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CrossingSweep, ValidationOfLongSpikesAcceptsTheValidAndNamesACrossing) {
  const Ring valid = star(20000, 1.0, 1000.0);
  const std::vector<Region> cleaned = clean_and_validate({Region{valid, {}}}, "star");
  EXPECT_EQ(cleaned[0].outer.size(), valid.size());
  const std::string self_intersection = "star: region 1 outer boundary: self-intersection";
  // One spike's tip moved past its neighbour's: two spikes cross. Naming the first crossing
  // takes the grid (quadratic here), so a smaller star.
  const Ring smaller = star(3000, 1.0, 1000.0);
  Ring crossing = smaller;
  crossing[1000] = crossing[1004];
  crossing[1000].y += 1.0;
  EXPECT_THAT(validation_error(Region{crossing, {}}), HasSubstr(self_intersection));
  // Two tips swapped half way round a large star: finding the first crossing in edge order would
  // test pairs for seconds (2.3 s at 32,000 vertices), so the sweep's crossing is named.
  Ring swapped = valid;
  std::swap(swapped[valid.size() / 2], swapped[valid.size() / 2 + 2]);
  EXPECT_THAT(validation_error(Region{swapped, {}}), HasSubstr(self_intersection));
  // A hole touching a spike at a vertex of it.
  const Ring hole{smaller[2000], smaller[2000] + Vec2{-10, 0}, smaller[2000] + Vec2{-10, -10}};
  EXPECT_THAT(validation_error(Region{smaller, {hole}}),
              HasSubstr("hole 1 crosses or touches the outer boundary"));
}

}  // namespace
}  // namespace hullcook
