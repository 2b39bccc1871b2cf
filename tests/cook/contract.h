// The cooker's output contract (issue 4), checked independently of the code that produces it.
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/cook/constrain.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace hullcook::test {

inline double cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

inline double ring_area(const Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    twice += cross2(ring[i], ring[(i + 1) % ring.size()]);
  return twice / 2;
}

inline double region_area(const Region& region) {
  double area = std::abs(ring_area(region.outer));
  for (const Ring& hole : region.holes) area -= std::abs(ring_area(hole));
  return area;
}

inline double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  Vec2 ab = b - a;
  double t =
      glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0;
  return glm::length(p - (a + t * ab));
}

inline double boundary_distance(Vec2 p, const Ring& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ring.size(); ++i)
    best = std::min(best, segment_distance(p, ring[i], ring[(i + 1) % ring.size()]));
  return best;
}

inline bool point_in_ring(Vec2 p, const Ring& ring) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
        p.x < (ring[j].x - ring[i].x) * (p.y - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x)
      inside = !inside;
  }
  return inside;
}

// Distance from p to a set of filled regions (zero inside one).
inline double distance_to_regions(Vec2 p, const std::vector<Region>& regions) {
  double best = std::numeric_limits<double>::infinity();
  for (const Region& region : regions) {
    bool inside = point_in_ring(p, region.outer);
    double d = boundary_distance(p, region.outer);
    for (const Ring& hole : region.holes) {
      inside = inside && !point_in_ring(p, hole);
      d = std::min(d, boundary_distance(p, hole));
    }
    best = std::min(best, inside ? 0.0 : d);
  }
  return best;
}

// Convex, counter-clockwise, within max_verts, no vertex pair closer than weld, no collinear
// vertex (turn height at least kCollinearFractionOfWeld * weld).
inline void expect_engine_ready(const Ring& hull, const EngineLimits& limits,
                                const std::string& where) {
  ASSERT_GE(hull.size(), 3u) << where;
  if (limits.max_verts) {
    EXPECT_LE(hull.size(), limits.max_verts) << where;
  }
  EXPECT_GT(ring_area(hull), 0) << where << ": not counter-clockwise";
  std::size_t n = hull.size();
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 a = hull[(i + n - 1) % n], b = hull[i], c = hull[(i + 1) % n];
    double height = cross2(c - a, b - a) * -1 / glm::length(c - a);
    EXPECT_GE(height, kCollinearFractionOfWeld * limits.weld) << where << ": vertex " << i;
    for (std::size_t j = i + 1; j < n; ++j)
      EXPECT_GE(glm::length(hull[i] - hull[j]), limits.weld)
          << where << ": vertices " << i << "," << j;
  }
}

// The contract after the engine limits, for one asset's finest level at tolerance tau:
// hulls engine-ready; each component inside its hull with every vertex within tau of the hull's
// boundary; the components cover the outline exactly (areas); every hull point (sampled along
// the boundary) within tau of the outline.
inline void expect_cooked_contract(const CookedAsset& asset, double tau,
                                   const EngineLimits& limits) {
  double slack = 1e-9 * std::max(1.0, tau);
  double component_area = 0;
  for (std::size_t k = 0; k < asset.pieces.size(); ++k) {
    const CookedPiece& piece = asset.pieces[k];
    std::string where = asset.name + " piece " + std::to_string(k);
    expect_engine_ready(piece.hull, limits, where);
    component_area += region_area(piece.component);
    auto check_vertex = [&](Vec2 v) {
      double d = boundary_distance(v, piece.hull);
      EXPECT_TRUE(point_in_ring(v, piece.hull) || d <= slack) << where << ": vertex outside hull";
      EXPECT_LE(d, tau + slack) << where << ": component vertex too far from its hull";
    };
    for (Vec2 v : piece.component.outer) check_vertex(v);
    for (const Ring& hole : piece.component.holes)
      for (Vec2 v : hole) check_vertex(v);
    for (std::size_t i = 0; i < piece.hull.size(); ++i) {
      Vec2 a = piece.hull[i], b = piece.hull[(i + 1) % piece.hull.size()];
      for (int s = 0; s < 8; ++s) {
        Vec2 p = a + (b - a) * (s / 8.0);
        EXPECT_LE(distance_to_regions(p, asset.regions), tau + slack)
            << where << ": hull point too far";
      }
    }
  }
  double outline_area = 0;
  for (const Region& region : asset.regions) outline_area += region_area(region);
  EXPECT_NEAR(component_area, outline_area, 1e-9 * std::max(1.0, outline_area)) << asset.name;
}

}  // namespace hullcook::test
