// The decomposition's contract (issue 3), checked independently of the decomposer: every piece a
// valid polygon within τ (re-measured, and against brute-force SL and SP), the pieces a partition
// of the input, the tree's levels equal to fresh decompositions. Shared by the core tests.
#pragma once

#include "hullcook/core/clean.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace hullcook::test {

inline constexpr Measure kMeasures[] = {Measure::sl, Measure::sp, Measure::h1, Measure::h2};

// SL concavity computed independently: distance to the line of the hull edge over each pocket.
inline double brute_sl_concavity(const Ring& ring) {
  const std::size_t n = ring.size();
  double worst = 0.0;
  const Ring hull = convex_hull(ring);
  for (std::size_t i = 0; i < n; ++i) {
    if (locate_point(hull, ring[i]) == Location::boundary) continue;
    // The pocket's bridge: the hull edge whose endpoints enclose i along the ring.
    std::size_t s = i, t = i;
    while (locate_point(hull, ring[s]) != Location::boundary) s = (s + n - 1) % n;
    while (locate_point(hull, ring[t]) != Location::boundary) t = (t + 1) % n;
    const Vec2 d = ring[t] - ring[s];
    worst = std::max(worst, std::abs(orient2d(ring[s], ring[t], ring[i])) / std::hypot(d.x, d.y));
  }
  return worst;
}

// Shortest-path concavity by Dijkstra on the visibility graph of each pocket polygon (slow; small
// rings only), checked against the library per vertex.
inline bool visible_in(const Ring& polygon, Vec2 a, Vec2 b) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 c = polygon[i], d = polygon[(i + 1) % n];
    if ((c == a && d == b) || (c == b && d == a)) return true;  // an edge (its midpoint rounds)
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 c = polygon[i], d = polygon[(i + 1) % n];
    if (segments_cross_properly(a, b, c, d)) return false;
    if (c != a && c != b && on_segment(a, b, c)) return false;
  }
  const Vec2 middle = (a + b) * 0.5;
  return locate_point(polygon, middle) != Location::outside;
}

inline std::vector<double> brute_sp_vertex_concavity(const Ring& ring) {
  const std::size_t n = ring.size();
  std::vector<double> result(n, 0.0);
  const Ring hull = convex_hull(ring);
  std::vector<char> on_hull(n);
  for (std::size_t i = 0; i < n; ++i)
    on_hull[i] = locate_point(hull, ring[i]) == Location::boundary;
  for (std::size_t s = 0; s < n; ++s) {
    if (!on_hull[s] || on_hull[(s + 1) % n]) continue;
    std::vector<std::size_t> chain{s};
    for (std::size_t i = (s + 1) % n;; i = (i + 1) % n) {
      chain.push_back(i);
      if (on_hull[i]) break;
    }
    Ring pocket;
    for (std::size_t i : chain) pocket.push_back(ring[i]);
    const Vec2 bs = pocket.front(), bt = pocket.back();
    const std::size_t m = pocket.size();
    std::vector<double> dist(m, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < m; ++i) {
      const Vec2 ab = bt - bs;
      double u =
          ((pocket[i] - bs).x * ab.x + (pocket[i] - bs).y * ab.y) / (ab.x * ab.x + ab.y * ab.y);
      u = std::clamp(u, 0.0, 1.0);
      const Vec2 foot = bs + ab * u;
      // The foot, nudged into the pocket so its rounding cannot put it across the bridge.
      const Vec2 inside = foot + (pocket[i] - foot) * 1e-9;
      if (i == 0 || i + 1 == m || visible_in(pocket, pocket[i], inside)) {
        dist[i] = std::hypot(pocket[i].x - foot.x, pocket[i].y - foot.y);
      }
    }
    std::vector<char> done(m, 0);
    for (std::size_t round = 0; round < m; ++round) {
      std::size_t best = m;
      for (std::size_t i = 0; i < m; ++i) {
        if (!done[i] && (best == m || dist[i] < dist[best])) best = i;
      }
      done[best] = 1;
      for (std::size_t i = 0; i < m; ++i) {
        if (done[i] || !visible_in(pocket, pocket[best], pocket[i])) continue;
        dist[i] = std::min(dist[i], dist[best] + std::hypot(pocket[i].x - pocket[best].x,
                                                            pocket[i].y - pocket[best].y));
      }
    }
    for (std::size_t k = 1; k + 1 < m; ++k) result[chain[k]] = dist[k];
  }
  return result;
}

inline void expect_contract(const Region& input, const std::vector<Piece>& pieces, double tau,
                            Measure measure, const std::string& what, int samples = 400) {
  SCOPED_TRACE(what);
  ASSERT_FALSE(pieces.empty());
  const double input_area = region_area(input);
  double area_sum = 0.0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Piece& piece = pieces[k];
    SCOPED_TRACE("piece " + std::to_string(k));
    // A valid polygon: cleaning and validation leave it unchanged.
    std::vector<Region> cleaned;
    ASSERT_NO_THROW(cleaned = clean_and_validate({piece.component}, "piece"));
    ASSERT_EQ(cleaned[0].outer.size(), piece.component.outer.size());
    area_sum += region_area(piece.component);
    for (Vec2 p : piece.component.outer) ASSERT_NE(locate_point(input, p), Location::outside);
    // Concavity within τ, re-measured.
    const double measured = measure_concavity(piece.component, measure, tau);
    EXPECT_LE(measured, tau * (1 + 1e-12) + 1e-12);
    EXPECT_NEAR(measured, piece.concavity, 1e-9 * (1 + measured));
    if (piece.component.holes.empty()) {
      const double sl = brute_sl_concavity(piece.component.outer);
      if (measure == Measure::sl) {
        EXPECT_NEAR(sl, measured, 1e-9 * (1 + sl));
      }
      EXPECT_LE(sl, tau * (1 + 1e-12) + 1e-12);  // every measure is at least SL
    }
    if (tau == 0.0) {
      EXPECT_TRUE(piece.component.holes.empty());
      const Ring& ring = piece.component.outer;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        ASSERT_GT(orientation(ring[i], ring[(i + 1) % ring.size()], ring[(i + 2) % ring.size()]),
                  0);
      }
    }
    // The hull: the component's convex hull, CCW, strictly convex.
    EXPECT_EQ(piece.hull, convex_hull(piece.component.outer));
    ASSERT_GE(piece.hull.size(), 3u);
    for (std::size_t i = 0; i < piece.hull.size(); ++i) {
      ASSERT_GT(orientation(piece.hull[i], piece.hull[(i + 1) % piece.hull.size()],
                            piece.hull[(i + 2) % piece.hull.size()]),
                0);
    }
  }
  EXPECT_NEAR(area_sum, input_area, 1e-9 * input_area);
  // Interiors disjoint and covering: sampled points inside the input lie in exactly one piece.
  const Ring box_hull = convex_hull(input.outer);
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
  for (Vec2 p : box_hull) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  std::mt19937 random(99);
  std::uniform_real_distribution<double> ux(min_x, max_x), uy(min_y, max_y);
  for (int i = 0; i < samples; ++i) {
    const Vec2 p{ux(random), uy(random)};
    int inside = 0;
    bool on_boundary = false;
    for (const Piece& piece : pieces) {
      const Location where = locate_point(piece.component, p);
      inside += where == Location::inside;
      on_boundary |= where == Location::boundary;
    }
    if (on_boundary) continue;
    ASSERT_EQ(inside, locate_point(input, p) == Location::inside ? 1 : 0) << p.x << " " << p.y;
  }
}

inline void check_tree(const Region& region, const DecompositionTree& tree, Measure measure,
                       const std::string& what) {
  SCOPED_TRACE(what + " tree");
  const std::vector<double> taus = tree.level_taus();
  std::size_t previous = std::numeric_limits<std::size_t>::max();
  std::size_t checked = 0;
  for (std::size_t i = 0; i < taus.size(); i += std::max<std::size_t>(1, taus.size() / 4)) {
    const std::vector<Piece> pieces = tree.pieces_at(taus[i]);
    EXPECT_LE(pieces.size(), previous);
    previous = pieces.size();
    expect_contract(region, pieces, taus[i], measure, "level " + std::to_string(i), 100);
    if (measure != Measure::h2 && ++checked <= 2) {
      // The levels equal a fresh decomposition at that τ.
      DecomposeSettings settings{taus[i], measure, 0.1, 1.0};
      const std::vector<Piece> fresh = decompose(region, settings).pieces_at(taus[i]);
      ASSERT_EQ(fresh.size(), pieces.size());
      for (std::size_t k = 0; k < fresh.size(); ++k) {
        EXPECT_EQ(fresh[k].component.outer, pieces[k].component.outer);
      }
    }
  }
  // Children inherit their parents' values where a pocket is kept whole: every node must still
  // hold what a fresh measurement of its component gives (see Issue3 in tests/cook).
  for (std::size_t id = 0; id < tree.nodes().size(); ++id) {
    const DecompositionTree::Node& node = tree.nodes()[id];
    ASSERT_EQ(node.concavity, measure_concavity(node.component, measure, tree.built_tau()))
        << "node " << id;
  }
  EXPECT_EQ(tree.pieces_at(std::numeric_limits<double>::infinity()).size(), 1u);
  const std::size_t finest = tree.pieces_at(tree.built_tau()).size();
  for (std::size_t budget : {std::size_t{1}, std::size_t{2}, finest / 2, finest}) {
    const std::vector<Piece> within = tree.pieces_within(budget);
    EXPECT_LE(within.size(), std::max<std::size_t>(budget, 1));
    // The finest such level: the next finer level breaks the budget.
    const auto level = std::find_if(taus.begin(), taus.end(), [&](double t) {
      return tree.piece_count_at(t) == within.size();
    });
    ASSERT_NE(level, taus.end());
    EXPECT_EQ(tree.tau_within(budget), *level);
    if (level != taus.begin()) {
      EXPECT_GT(tree.piece_count_at(*(level - 1)), budget);
    }
  }
}

}  // namespace hullcook::test
