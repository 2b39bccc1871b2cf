// The internal triangulation the shortest-path measure walks (tool/core/src/triangulate.h): the
// plane sweep must triangulate every clean simple polygon by itself, including rings full of
// equal heights and horizontal edges (integer grids), and the result must be a triangulation:
// n - 2 counter-clockwise triangles of positive area whose areas add up to the polygon's, every
// polygon edge in one triangle and every other edge in two (opposite directions), with the
// neighbour table naming the triangle across each edge.
#include "triangulate.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"
#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace hullcook {
namespace {

using Triangles = std::vector<std::array<int, 3>>;

void expect_triangulation(const Ring& polygon, const Triangles& triangles,
                          const Triangles& neighbours) {
  const int n = static_cast<int>(polygon.size());
  ASSERT_EQ(triangles.size(), static_cast<std::size_t>(n - 2));
  ASSERT_EQ(neighbours.size(), triangles.size());
  double area = 0.0;
  // Directed edge -> (triangle, edge index).
  std::map<std::pair<int, int>, std::pair<int, int>> owner;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (int v : tri) ASSERT_TRUE(v >= 0 && v < n);
    const Vec2 a = polygon[std::size_t(tri[0])], b = polygon[std::size_t(tri[1])],
               c = polygon[std::size_t(tri[2])];
    ASSERT_GT(orient2d(a, b, c), 0.0) << "triangle " << t << " is not counter-clockwise";
    area += signed_area({a, b, c});
    for (int e = 0; e < 3; ++e) {
      const std::pair<int, int> edge{tri[std::size_t(e)], tri[std::size_t((e + 1) % 3)]};
      ASSERT_TRUE(owner.emplace(edge, std::pair<int, int>{int(t), e}).second)
          << "directed edge " << edge.first << "-" << edge.second << " used twice";
    }
  }
  EXPECT_NEAR(area, signed_area(polygon), 1e-9 * std::abs(signed_area(polygon)));
  for (const auto& [edge, where] : owner) {
    const auto [t, e] = where;
    const bool polygon_edge = edge.second == (edge.first + 1) % n;
    const auto twin = owner.find({edge.second, edge.first});
    if (polygon_edge) {
      EXPECT_TRUE(twin == owner.end()) << "polygon edge " << edge.first << " has a twin";
      EXPECT_EQ(neighbours[std::size_t(t)][std::size_t(e)], -1);
    } else {
      ASSERT_TRUE(twin != owner.end())
          << "inner edge " << edge.first << "-" << edge.second << " has one triangle";
      EXPECT_EQ(neighbours[std::size_t(t)][std::size_t(e)], twin->second.first);
    }
  }
}

void expect_sweep_triangulates(const Ring& polygon, const std::string& what) {
  SCOPED_TRACE(what);
  Triangles triangles, neighbours;
  ASSERT_TRUE(detail::triangulate_by_sweep(polygon, triangles, &neighbours));
  expect_triangulation(polygon, triangles, neighbours);
}

TEST(Triangulate, SweepHandlesIntegerGridPolygons) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int attempt = 0; attempt < 3000; ++attempt) {
    const int grid = 3 + attempt % 13;
    const int n = 4 + attempt % 29;
    Region region;
    if (attempt % 3 == 0) {
      // Arbitrary orderings of grid points: only the simple ones survive the clean-up.
      std::uniform_int_distribution<int> coordinate(0, grid);
      for (int i = 0; i < n; ++i)
        region.outer.push_back({double(coordinate(random)), double(coordinate(random))});
    } else {
      std::vector<double> angles;
      for (int i = 0; i < n; ++i) angles.push_back(unit(random) * 2 * M_PI);
      std::sort(angles.begin(), angles.end());
      for (double a : angles) {
        const double r = grid * 0.5 * (0.2 + 0.8 * unit(random));
        region.outer.push_back(
            {std::round(grid * 0.5 + r * std::cos(a)), std::round(grid * 0.5 + r * std::sin(a))});
      }
    }
    std::vector<Region> cleaned;
    try {
      cleaned = clean_and_validate({region}, "random");
    } catch (const std::exception&) {
      continue;
    }
    expect_sweep_triangulates(cleaned[0].outer, "attempt " + std::to_string(attempt));
    if (HasFatalFailure()) return;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(Triangulate, SweepHandlesCombsAndSpirals) {
  // A comb with teeth up and down: split and merge vertices at shared heights, horizontal edges.
  Ring comb;
  const int teeth = 40;
  for (int i = 0; i < teeth; ++i) {
    comb.push_back({2.0 * i, 0.0});
    comb.push_back({2.0 * i + 1, (i % 3 == 0) ? -5.0 : -3.0});
  }
  comb.push_back({2.0 * teeth, 0.0});
  comb.push_back({2.0 * teeth, 10.0});
  for (int i = teeth; i > 0; --i) {
    comb.push_back({2.0 * i - 1, (i % 2 == 0) ? 15.0 : 10.0});
    comb.push_back({2.0 * i - 2, 10.0});
  }
  ASSERT_GT(signed_area(comb), 0.0);
  expect_sweep_triangulates(remove_degenerate_vertices(comb), "comb");

  // A thick spiral: pockets that fold back, the case ear clipping was slow on.
  Ring spiral;
  const int turns = 6, per_turn = 60;
  for (int i = 0; i <= turns * per_turn; ++i) {
    const double a = 2 * M_PI * i / per_turn, r = 10.0 + 3.0 * a;
    spiral.push_back({r * std::cos(a), r * std::sin(a)});
  }
  for (int i = turns * per_turn; i >= 0; --i) {
    const double a = 2 * M_PI * i / per_turn, r = 10.0 + 3.0 * a + 1.5;
    spiral.push_back({r * std::cos(a), r * std::sin(a)});
  }
  if (signed_area(spiral) < 0) std::reverse(spiral.begin(), spiral.end());
  expect_sweep_triangulates(spiral, "spiral");
}

TEST(Triangulate, SweepHandlesNearDegenerateCoordinates) {
  // Small stars far from the origin: most orientation tests fall to the exact arithmetic.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int attempt = 0; attempt < 300; ++attempt) {
    const double offset = std::ldexp(1.0, 20 + attempt % 24), radius = 1e-3 * (1 + attempt % 7);
    const int n = 5 + attempt % 40;
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(unit(random) * 2 * M_PI);
    std::sort(angles.begin(), angles.end());
    Region region;
    for (double a : angles) {
      const double r = radius * (0.1 + 0.9 * unit(random));
      region.outer.push_back({offset + r * std::cos(a), offset * 0.5 + r * std::sin(a)});
    }
    std::vector<Region> cleaned;
    try {
      cleaned = clean_and_validate({region}, "random");
    } catch (const std::exception&) {
      continue;
    }
    expect_sweep_triangulates(cleaned[0].outer, "attempt " + std::to_string(attempt));
    if (HasFatalFailure()) return;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(Triangulate, SweepHandlesEverySampleRing) {
  const auto root = std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons";
  int rings = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".poly") continue;
    for (const Region& region : read_poly_file(entry.path())) {
      expect_sweep_triangulates(region.outer, entry.path().filename().string());
      for (const Ring& hole : region.holes) {
        expect_sweep_triangulates(Ring(hole.rbegin(), hole.rend()),
                                  entry.path().filename().string() + " hole");
      }
      rings += 1 + static_cast<int>(region.holes.size());
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GT(rings, 20);
}

TEST(Triangulate, EarClippingFallbackIsATriangulationToo) {
  Ring spiral;
  for (int i = 0; i <= 120; ++i) {
    const double a = 2 * M_PI * i / 40, r = 10.0 + 3.0 * a;
    spiral.push_back({r * std::cos(a), r * std::sin(a)});
  }
  for (int i = 120; i >= 0; --i) {
    const double a = 2 * M_PI * i / 40, r = 11.5 + 3.0 * a;
    spiral.push_back({r * std::cos(a), r * std::sin(a)});
  }
  if (signed_area(spiral) < 0) std::reverse(spiral.begin(), spiral.end());
  Triangles triangles, neighbours;
  detail::triangulate_by_ear_clipping(spiral, triangles, &neighbours);
  expect_triangulation(spiral, triangles, neighbours);
}

}  // namespace
}  // namespace hullcook
