#include "contract.h"

#include "hullcook/cook/constrain.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hullcook {
namespace {

using test::expect_engine_ready;
using test::ring_area;

Ring regular_polygon(std::size_t n, double radius, Vec2 centre = {0, 0}) {
  Ring ring;
  for (std::size_t i = 0; i < n; ++i) {
    double angle = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    ring.push_back(centre + radius * Vec2{std::cos(angle), std::sin(angle)});
  }
  return ring;
}

CookedPiece convex_piece(const Ring& ring) { return CookedPiece{Region{ring, {}}, ring, 0.0}; }

// No further decomposition: the convex fallback (halving) is exercised alone.
std::vector<CookedPiece> no_split(const Region& component, double) {
  return {CookedPiece{component, component.outer, 0.0}};
}

void expect_within(const std::vector<CookedPiece>& pieces, double tau, const EngineLimits& limits) {
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    expect_engine_ready(pieces[k].hull, limits, "piece " + std::to_string(k));
    for (Vec2 v : pieces[k].component.outer) {
      EXPECT_TRUE(test::point_in_ring(v, pieces[k].hull) ||
                  test::boundary_distance(v, pieces[k].hull) < 1e-12);
      EXPECT_LE(test::boundary_distance(v, pieces[k].hull), tau + 1e-12);
    }
    for (Vec2 h : pieces[k].hull) {
      EXPECT_LE(test::distance_to_regions(h, {pieces[k].component}), tau + 1e-12);
    }
  }
}

TEST(EngineLimits, RoundShapeGrowsToEightVerticesWithinTau) {
  // A circumscribed octagon around a radius-10 circle reaches 10 / cos(22.5°) - 10 ≈ 0.82 out.
  std::vector<std::string> warnings;
  EngineLimits limits{8, 0.005};
  auto pieces =
      apply_engine_limits({convex_piece(regular_polygon(40, 10))}, 1.0, limits, no_split, warnings);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_LE(pieces[0].hull.size(), 8u);
  EXPECT_TRUE(warnings.empty());
  expect_within(pieces, 1.0, limits);
}

TEST(EngineLimits, TightToleranceSplitsConvexPiecesExactly) {
  std::vector<std::string> warnings;
  EngineLimits limits{8, 0.005};
  Ring circle = regular_polygon(40, 10);
  auto pieces = apply_engine_limits({convex_piece(circle)}, 0.001, limits, no_split, warnings);
  EXPECT_GT(pieces.size(), 1u);
  double area = 0;
  for (const CookedPiece& piece : pieces) area += ring_area(piece.component.outer);
  EXPECT_NEAR(area, ring_area(circle), 1e-9);
  expect_within(pieces, 0.001, limits);
}

TEST(EngineLimits, UnlimitedVerticesKeepsTheHull) {
  std::vector<std::string> warnings;
  EngineLimits limits{0, 0.005};
  auto pieces =
      apply_engine_limits({convex_piece(regular_polygon(40, 10))}, 0.0, limits, no_split, warnings);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].hull.size(), 40u);
}

TEST(EngineLimits, CloseVerticesAreWeldedByGrowth) {
  Ring hull{{0, 0}, {4, 0}, {4.001, 0.0005}, {4, 4}, {0, 4}};
  std::vector<std::string> warnings;
  EngineLimits limits{8, 0.005};
  auto pieces = apply_engine_limits({CookedPiece{Region{hull, {}}, hull, 0.0}}, 0.01, limits,
                                    no_split, warnings);
  ASSERT_EQ(pieces.size(), 1u);
  expect_within(pieces, 0.01, limits);
  EXPECT_LT(pieces[0].hull.size(), hull.size());
}

TEST(EngineLimits, NearlyCollinearVertexIsRemoved) {
  Ring hull{{0, 0}, {2, -1e-7}, {4, 0}, {4, 4}, {0, 4}};
  std::vector<std::string> warnings;
  EngineLimits limits{8, 0.005};
  auto pieces = apply_engine_limits({CookedPiece{Region{hull, {}}, hull, 0.0}}, 0.01, limits,
                                    no_split, warnings);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].hull.size(), 4u);
  expect_within(pieces, 0.01, limits);
}

TEST(EngineLimits, PieceSmallerThanWeldIsReportedNotDroppedSilently) {
  Ring tiny{{0, 0}, {0.002, 0}, {0, 0.002}};
  std::vector<std::string> warnings;
  auto pieces = apply_engine_limits({CookedPiece{Region{tiny, {}}, tiny, 0.0}}, 0.0001,
                                    EngineLimits{8, 0.005}, no_split, warnings);
  EXPECT_TRUE(pieces.empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("too small"), std::string::npos);
}

TEST(EngineLimits, HullMeetsLimitsRejectsEachViolation) {
  EngineLimits limits{4, 0.01};
  EXPECT_TRUE(hull_meets_limits({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, limits));
  EXPECT_FALSE(hull_meets_limits({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, limits));  // clockwise
  EXPECT_FALSE(hull_meets_limits(regular_polygon(5, 1), limits));             // too many
  EXPECT_FALSE(hull_meets_limits({{0, 0}, {1, 0}, {1, 0.5}, {1, 1}}, EngineLimits{8, 0.01}));
  EXPECT_FALSE(hull_meets_limits({{0, 0}, {1, 0}, {1, 0.001}, {0, 1}}, limits));  // weld
}

}  // namespace
}  // namespace hullcook
