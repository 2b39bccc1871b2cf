// OutlineDistance: distances to and containment in a cook's outline.
#include "outline_distance.h"
#include "contract.h"
#include "engine_limits_fixtures.h"
#include "hull_fitter.h"
#include "mend_queue.h"
#include "piece_merge.h"

#include "hullcook/cook/constrain.h"
#include "hullcook/cook/cook.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace hullcook {
namespace {

using test::kNearlyCollinearPiece;

// A segment along both nearly collinear edges passes 4e-18 from their shared vertex: the disc
// there covers it. The discriminant b² - ac cancelled to a negative value, the capsules left a
// gap at the vertex, and the contract reported the hull edge "9.9e-10 beyond the outline" at τ 0.
TEST(OutlineDistance, SegmentAlongNearlyCollinearEdgesIsWithinThroughTheirSharedVertex) {
  const Region region{kNearlyCollinearPiece, {}};
  const OutlineDistance outline({&region});
  // The hull edge that skips (0.88, 0.18), its ends as seal() left them.
  EXPECT_TRUE(outline.segment_within({0.81999999999999984, 0.11999999999999958},
                                     {0.92000000000000026, 0.21999999999999989}, 1e-9));
  EXPECT_TRUE(outline.segment_within({0.82, 0.12}, {0.92, 0.22}, 1e-12));
  // Inside is within; 0.12 out of the piece is not.
  EXPECT_TRUE(outline.segment_within({0.82, 0.12}, {0.58, 0.45}, 1e-12));
  EXPECT_FALSE(outline.segment_within({0.82, 0.12}, {0.82, 0.0}, 1e-3));
}

// contains() in rows of many edges goes by the parity of crossings from its cell's centre (stop
// 54: a 10,000-vertex star's rows held thousands of spokes): it must answer as a ray's parity
// does, by exact orientations, for every point not on the outline. A star whose rows hold
// hundreds of edges, with a hole, and points on a fine lattice that meets vertices' heights and
// the cells' centres exactly.
TEST(OutlineDistance, Issue54_ContainsInRowsOfManyEdgesAnswersAsARayParity) {
  Ring star;
  const int spokes = 300;
  for (int k = 0; k < 2 * spokes; ++k) {
    const double angle = M_PI * k / spokes, radius = k % 2 ? 4.0 : 100.0;
    // Coordinates on a 1/64 grid: lattice points meet them exactly.
    star.push_back({std::round(64 * radius * std::cos(angle)) / 64,
                    std::round(64 * radius * std::sin(angle)) / 64});
  }
  const Ring hole{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};
  const Region whole{star, {hole}};
  const OutlineDistance outline({&whole});
  std::vector<std::pair<Vec2, Vec2>> edges;
  for (const Ring* ring : std::initializer_list<const Ring*>{&star, &hole}) {
    for (std::size_t i = 0; i < ring->size(); ++i) {
      edges.push_back({(*ring)[i], (*ring)[(i + 1) % ring->size()]});
    }
  }
  auto on_outline = [&](Vec2 p) {
    for (const auto& [a, b] : edges) {
      if (orient2d(a, b, p) == 0 && p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) &&
          p.y >= std::min(a.y, b.y) && p.y <= std::max(a.y, b.y)) {
        return true;
      }
    }
    return false;
  };
  auto ray_parity = [&](Vec2 p) {
    bool inside = false;
    for (const auto& [a, b] : edges) {
      if ((a.y > p.y) == (b.y > p.y)) continue;
      const bool upward = b.y > a.y;
      if ((upward ? orient2d(a, b, p) : orient2d(b, a, p)) > 0) inside = !inside;
    }
    return inside;
  };
  std::mt19937_64 random(54);
  std::uniform_int_distribution<int> lattice(-105 * 32, 105 * 32);
  int checked = 0, inside = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 p{lattice(random) / 32.0, lattice(random) / 32.0};
    if (on_outline(p)) continue;
    ++checked;
    const bool expected = ray_parity(p);
    inside += expected;
    ASSERT_EQ(outline.contains(p), expected) << "(" << p.x << ", " << p.y << ")";
  }
  EXPECT_GT(checked, 19000);
  EXPECT_GT(inside, 300);
}

// Stop 59: a point's distance stops at its own cell when the nearest edge found is nearer than
// the cell's sides (a disc of thousands of vertices measured the nine cells round each point).
// The answer must stay the whole scan's: the least distance to any edge, 0 inside, on outlines
// dense and sparse, at scales from 1e-6 to 1e6, for points near and far.
TEST(OutlineDistance, Stop59_DistanceIsTheLeastToAnyEdgeWhereverItStopsScanning) {
  std::mt19937_64 random(59);
  std::uniform_real_distribution<double> unit(0, 1);
  for (double scale : {1e-6, 1.0, 1e6}) {
    for (int vertices : {12, 400, 6000}) {
      SCOPED_TRACE(std::to_string(vertices) + " vertices at scale " + std::to_string(scale));
      Ring rough;
      for (int k = 0; k < vertices; ++k) {
        const double angle = 2 * M_PI * k / vertices;
        const double radius = scale * (100 + (k % 7 == 3 ? 30 : 0) + unit(random));
        rough.push_back({radius * std::cos(angle) + 7 * scale, radius * std::sin(angle)});
      }
      const Region region{rough, {}};
      const OutlineDistance outline({&region});
      for (int k = 0; k < 2000; ++k) {
        const double angle = 2 * M_PI * unit(random);
        const double radius =
            scale * (k % 2 ? 100 + 40 * (unit(random) - 0.5) : 160 * unit(random));
        const Vec2 p{radius * std::cos(angle) + 7 * scale, radius * std::sin(angle)};
        double least = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < rough.size(); ++i) {
          least =
              std::min(least, point_segment_distance(p, rough[i], rough[(i + 1) % rough.size()]));
        }
        const double expected = locate_point(rough, p) == Location::outside ? least : 0.0;
        const double found = outline.distance(p, std::numeric_limits<double>::infinity());
        ASSERT_EQ(found == 0.0, expected == 0.0) << k;
        ASSERT_NEAR(found, expected, 1e-12 * scale) << k;
      }
    }
  }
}

// Stop 59: the fitters skip the search along a segment whose ends lie within the bound when the
// outline is one convex polygon (the distance to it is convex along the segment). A polygon that
// turns left at every vertex but winds twice (a pentagram's vertices in star order), or one with
// a notch or a hole, is not one.
TEST(OutlineDistance, Stop59_OnlyOneConvexRingCountsAsConvex) {
  Ring pentagon, pentagram;
  for (int k = 0; k < 5; ++k) {
    pentagon.push_back({std::cos(2 * M_PI * k / 5), std::sin(2 * M_PI * k / 5)});
    pentagram.push_back({std::cos(4 * M_PI * k / 5), std::sin(4 * M_PI * k / 5)});
  }
  const Region convex{pentagon, {}};
  EXPECT_TRUE(OutlineDistance({&convex}).is_convex());
  const Region twice{pentagram, {}};
  EXPECT_FALSE(OutlineDistance({&twice}).is_convex());
  const Region notched{{{0, 0}, {4, 0}, {4, 4}, {2, 3}, {0, 4}}, {}};
  EXPECT_FALSE(OutlineDistance({&notched}).is_convex());
  const Region holed{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}};
  EXPECT_FALSE(OutlineDistance({&holed}).is_convex());
  const Region collinear{{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, {}};
  EXPECT_FALSE(OutlineDistance({&collinear}).is_convex());
  const Region other{{{10, 0}, {14, 0}, {14, 4}}, {}};
  EXPECT_FALSE(OutlineDistance({&convex, &other}).is_convex());
}

}  // namespace
}  // namespace hullcook
