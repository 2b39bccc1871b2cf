// The linear-time hull of simple polygons against the general point-set hull, on rings full of
// collinear and doubling-back vertices (small integer grids) and on every sample's components.
#include "hullcook/core/clean.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"
#include "predicates_inline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <random>

namespace hullcook {
namespace {

void expect_same_hull(const Ring& ring, const std::string& what) {
  SCOPED_TRACE(what);
  const std::vector<std::size_t> expected = convex_hull_indices(ring);
  ASSERT_EQ(simple_polygon_hull_indices(ring), expected);
  // Started at any vertex of the hull (a few, on large rings).
  for (std::size_t k = 0; k < expected.size(); k += 1 + expected.size() / 8) {
    ASSERT_EQ(simple_polygon_hull_indices(ring, expected[k]), expected) << "from " << expected[k];
  }
  {
    // Within a decomposition a static error bound is in force: the scan then takes the filtered
    // steps, and an exact step wherever the bound cannot decide (these grids make many).
    const detail::CoordinateBound bound(detail::max_abs_coordinate(ring));
    ASSERT_EQ(simple_polygon_hull_indices(ring), expected) << "with a static bound";
    for (std::size_t k = 0; k < expected.size(); k += 1 + expected.size() / 8) {
      ASSERT_EQ(simple_polygon_hull_indices(ring, expected[k]), expected)
          << "with a static bound, from " << expected[k];
    }
  }
  Ring reversed(ring.rbegin(), ring.rend());
  ASSERT_EQ(simple_polygon_hull_indices(reversed), convex_hull_indices(reversed));
  for (std::size_t shift : {std::size_t{1}, ring.size() / 2}) {
    Ring rotated = ring;
    std::rotate(rotated.begin(), rotated.begin() + static_cast<long>(shift), rotated.end());
    ASSERT_EQ(simple_polygon_hull_indices(rotated), convex_hull_indices(rotated));
  }
}

// The region cleaned, or nothing where validation refuses it (the generators make both).
std::optional<Region> valid_or_nothing(const Region& region) {
  try {
    return clean_and_validate({region}, "generated")[0];
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

TEST(SimplePolygonHull, MatchesPointSetHullOnIntegerGridPolygons) {
  std::mt19937 random(7);
  int checked = 0;
  for (int attempt = 0; attempt < 4000; ++attempt) {
    const int grid = 3 + attempt % 9;
    const int n = 4 + attempt % 23;
    std::uniform_int_distribution<int> coordinate(0, grid);
    // Star-shaped around the grid's centre (angles sorted), rounded to the grid: many collinear,
    // repeated and backtracking vertices; clean_and_validate keeps the simple ones.
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(unit(random) * 2 * M_PI);
    std::sort(angles.begin(), angles.end());
    Region region;
    for (double a : angles) {
      const double r = grid * 0.5 * (0.2 + 0.8 * unit(random));
      region.outer.push_back(
          {std::round(grid * 0.5 + r * std::cos(a)), std::round(grid * 0.5 + r * std::sin(a))});
    }
    if (attempt % 3 == 0) {
      // Arbitrary (mostly non-simple) orderings: only the simple ones survive.
      for (Vec2& p : region.outer) p = {double(coordinate(random)), double(coordinate(random))};
    }
    const std::optional<Region> cleaned = valid_or_nothing(region);
    if (!cleaned) continue;
    expect_same_hull(cleaned->outer, "attempt " + std::to_string(attempt));
    ++checked;
  }
  EXPECT_GT(checked, 500);
}

// Chains along a line, each vertex a few ulps off it, closed by a vertex far below: which of them
// are hull vertices depends on orientations whose rounded determinants have the wrong sign.
TEST(SimplePolygonHull, MatchesPointSetHullOnNearlyCollinearChains) {
  std::mt19937 random(5);
  std::uniform_int_distribution<int> ulps(-3, 3);
  int checked = 0;
  for (int attempt = 0; attempt < 300; ++attempt) {
    const int n = 5 + attempt % 40;
    const double slope = 1.0 / (3 + attempt % 5), step = 1.0 / (7 + attempt % 3);
    Region region;
    for (int i = 0; i < n; ++i) {
      const double x = 0.5 + i * step;
      double y = x * slope;
      for (int k = ulps(random); k != 0; k += k > 0 ? -1 : 1) {
        y = std::nextafter(y, k > 0 ? 1e300 : -1e300);
      }
      region.outer.push_back({x, y});
    }
    region.outer.push_back({0.5 + n * step * 0.5, -10.0});
    std::reverse(region.outer.begin(), region.outer.end());  // counter-clockwise
    const std::optional<Region> cleaned = valid_or_nothing(region);
    if (!cleaned) continue;
    expect_same_hull(cleaned->outer, "attempt " + std::to_string(attempt));
    ++checked;
  }
  EXPECT_GT(checked, 250);
}

TEST(SimplePolygonHull, MatchesPointSetHullOnSampleComponents) {
  const auto root = std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons";
  for (const char* file : {"nazca/nazca_monkey.poly", "neuron/neuron.poly", "misc/mammoth.poly",
                           "misc/BarbedThing.poly", "misc/texas.poly"}) {
    const std::vector<Region> regions = read_poly_file(root / file);
    for (const Region& region : regions) {
      for (const Ring& hole : region.holes) expect_same_hull(hole, file);
      const DecompositionTree tree = decompose(region, {0.0, Measure::sl, 0.1, 1.0});
      for (const auto& node : tree.nodes()) expect_same_hull(node.component.outer, file);
    }
  }
}

}  // namespace
}  // namespace hullcook
