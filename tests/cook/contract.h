// The cooker's output contract (issue 4), checked independently of the code that produces it.
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/cook/constrain.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>

namespace hullcook::test {

// A tolerance in pixels at a number of pixels per output unit: the scales sprites are cooked at.
struct Scale {
  double tau_px;
  double pixels_per_unit;
};

inline void PrintTo(const Scale& scale, std::ostream* out) {
  *out << "tau " << scale.tau_px << " px at " << scale.pixels_per_unit << " px per unit";
}

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

// The outline's edges by rows of about √edges each, so that the contract's many distance
// queries on a large sprite take a row or a few rather than every edge.
class OutlineIndex {
 public:
  explicit OutlineIndex(const std::vector<Region>& regions) {
    auto add = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i)
        edges_.push_back({ring[i], ring[(i + 1) % ring.size()]});
    };
    for (const Region& region : regions) {
      add(region.outer);
      for (const Ring& hole : region.holes) add(hole);
    }
    if (edges_.empty()) return;
    low_ = high_ = edges_[0].first.y;
    for (const auto& [a, b] : edges_) {
      low_ = std::min({low_, a.y, b.y});
      high_ = std::max({high_, a.y, b.y});
    }
    rows_.resize(static_cast<std::size_t>(std::sqrt(double(edges_.size()))) + 1);
    height_ = std::max((high_ - low_) / double(rows_.size()), 1e-300);
    for (std::size_t k = 0; k < edges_.size(); ++k) {
      const auto& [a, b] = edges_[k];
      for (std::size_t r = row(std::min(a.y, b.y)); r <= row(std::max(a.y, b.y)); ++r)
        rows_[r].push_back(k);
    }
  }

  // Distance from p to the filled regions (zero inside one).
  double distance(Vec2 p) const {
    if (edges_.empty()) return std::numeric_limits<double>::infinity();
    std::size_t home = row(p.y);
    if (p.y >= low_ && p.y <= high_) {
      bool inside = false;
      for (std::size_t k : rows_[home]) {
        const auto& [a, b] = edges_[k];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
          inside = !inside;
      }
      if (inside) return 0;
    }
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t step = 0; step < 2 * rows_.size(); ++step) {
      bool any = false;
      for (long r : {long(home) - long(step), long(home) + long(step)}) {
        if (r < 0 || r >= long(rows_.size()) || (step == 0 && r != long(home))) continue;
        double band_low = low_ + double(r) * height_, band_high = band_low + height_;
        double gap = std::max({0.0, band_low - p.y, p.y - band_high});
        if (gap >= best) continue;
        any = true;
        for (std::size_t k : rows_[std::size_t(r)])
          best = std::min(best, segment_distance(p, edges_[k].first, edges_[k].second));
      }
      if (!any && step > 0) break;  // every row further out is further still
    }
    return best;
  }

 private:
  std::size_t row(double y) const {
    double r = std::floor((y - low_) / height_);
    return std::size_t(std::clamp(r, 0.0, double(rows_.size() - 1)));
  }

  std::vector<std::pair<Vec2, Vec2>> edges_;
  std::vector<std::vector<std::size_t>> rows_;
  double low_ = 0, high_ = 0, height_ = 1;
};

// How far beyond tau a point of segment ab lies from something, by its 1-Lipschitz distance
// function: 0 when none does. The segment is halved until the Lipschitz bound (its ends' distances
// and half its length) clears tau, or the halves are shorter than resolution: a peak between
// samples is not missed.
template <typename Distance>
double segment_excess(Vec2 a, Vec2 b, double at_a, double at_b, const Distance& distance,
                      double tau, double resolution, int depth = 0) {
  double excess = std::max({0.0, at_a - tau, at_b - tau});
  double length = glm::length(b - a);
  if ((at_a + at_b + length) / 2 <= tau || length < resolution || depth > 60) return excess;
  Vec2 middle = 0.5 * (a + b);
  double at_middle = distance(middle);
  return std::max(
      {excess, segment_excess(a, middle, at_a, at_middle, distance, tau, resolution, depth + 1),
       segment_excess(middle, b, at_middle, at_b, distance, tau, resolution, depth + 1)});
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

// The contract after the engine limits (issues 4 and 16), for one asset's finest level at
// tolerance tau: hulls engine-ready (at most max_verts vertices, no two closer than the weld, no
// collinear vertex); each component inside its hull with every point of its boundary within tau
// of the hull's boundary; the components cover the outline exactly (their areas add up to the
// outline's, so no piece was dropped); every point of every hull's boundary within tau of the
// outline (halved to a hundredth of tau, so that a peak between samples shows), and points inside
// it too.
inline void expect_cooked_contract(const CookedAsset& asset, double tau,
                                   const EngineLimits& limits) {
  double slack = 1e-9 * std::max(1.0, tau);
  double resolution = 1e-2 * tau;
  double component_area = 0;
  OutlineIndex outline(asset.regions);
  for (std::size_t k = 0; k < asset.pieces.size(); ++k) {
    const CookedPiece& piece = asset.pieces[k];
    std::string where = asset.name + " piece " + std::to_string(k);
    expect_engine_ready(piece.hull, limits, where);
    component_area += region_area(piece.component);
    auto check_ring = [&](const Ring& ring) {
      auto depth = [&](Vec2 p) { return boundary_distance(p, piece.hull); };
      for (std::size_t i = 0; i < ring.size(); ++i) {
        Vec2 v = ring[i], next = ring[(i + 1) % ring.size()];
        double d = depth(v);
        EXPECT_TRUE(point_in_ring(v, piece.hull) || d <= slack) << where << ": vertex outside hull";
        EXPECT_LE(d, tau + slack) << where << ": component vertex too far from its hull";
        // Between two vertices near the hull's boundary, an edge may pass under a grown corner.
        EXPECT_LE(segment_excess(v, next, d, depth(next), depth, tau, resolution), slack)
            << where << ": a point of component edge " << i << " too far from its hull";
      }
    };
    check_ring(piece.component.outer);
    for (const Ring& hole : piece.component.holes) check_ring(hole);
    const Ring& hull = piece.hull;
    std::vector<double> at_vertex;
    Vec2 centre{0, 0};
    for (Vec2 v : hull) {
      at_vertex.push_back(outline.distance(v));
      centre += v / static_cast<double>(hull.size());
    }
    for (std::size_t i = 0; i < hull.size(); ++i) {
      std::size_t j = (i + 1) % hull.size();
      auto to_outline = [&](Vec2 p) { return outline.distance(p); };
      EXPECT_LE(
          segment_excess(hull[i], hull[j], at_vertex[i], at_vertex[j], to_outline, tau, resolution),
          slack)
          << where << ": a point of hull edge " << i << " too far from the outline";
      Vec2 inside = 0.5 * (centre + hull[i]);
      EXPECT_LE(outline.distance(inside), tau + slack)
          << where << ": a point inside the hull too far from the outline";
    }
    EXPECT_LE(outline.distance(centre), tau + slack)
        << where << ": the hull's centre too far from the outline";
  }
  double outline_area = 0;
  for (const Region& region : asset.regions) outline_area += region_area(region);
  EXPECT_NEAR(component_area, outline_area, 1e-9 * std::max(1.0, outline_area)) << asset.name;
}

}  // namespace hullcook::test
