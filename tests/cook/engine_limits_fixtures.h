// Pieces, decompositions and checks that the engine-limit tests share (constrain_test,
// hull_fitter_test, outline_distance_test).
#pragma once

#include "contract.h"
#include "hull_fitter.h"
#include "outline_distance.h"

#include "hullcook/cook/constrain.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace hullcook::test {

inline Ring regular_polygon(std::size_t n, double radius, Vec2 centre = {0, 0}) {
  Ring ring;
  for (std::size_t i = 0; i < n; ++i) {
    double angle = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    ring.push_back(centre + radius * Vec2{std::cos(angle), std::sin(angle)});
  }
  return ring;
}

inline CookedPiece convex_piece(const Ring& ring) {
  return CookedPiece{Region{ring, {}}, ring, 0.0};
}

inline CookedPiece convex_piece_of(const Ring& ring) {
  return CookedPiece{Region{ring, {}}, convex_hull(ring), 0.0};
}

// No further decomposition: the convex fallback (halving) is exercised alone.
inline std::vector<CookedPiece> no_split(const Region& component, double) {
  return {CookedPiece{component, component.outer, 0.0}};
}

inline void expect_within(const std::vector<CookedPiece>& pieces, double tau,
                          const EngineLimits& limits) {
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

inline double area_of(const std::vector<CookedPiece>& pieces) {
  double area = 0;
  for (const CookedPiece& piece : pieces) area += ring_area(piece.component.outer);
  return area;
}

// The decomposition itself, as cook() passes it.
inline std::vector<CookedPiece> decompose_at(const Region& component, double tau) {
  std::vector<CookedPiece> pieces;
  for (Piece& piece : decompose(component, {tau, Measure::h1, 0.1, 1.0}).pieces_at(tau)) {
    pieces.push_back({piece.component, piece.hull, piece.concavity});
  }
  return pieces;
}

// What a HullFitter of piece at τ reads (it keeps references): its vertices' allowed depths, the
// distances to its component, and whether its pockets' edges suffice to prove growth.
struct FitterInputs {
  FitterInputs(const CookedPiece& piece, double tau)
      : piece(piece),
        tau(tau),
        allowed(allowed_depths(piece.component, piece.hull, tau)),
        reach({&piece.component}),
        edges_suffice(pockets_within(piece.component, piece.hull, tau)) {}
  HullFitter fitter(const EngineLimits& limits,
                    HullFitter::Reach kind = HullFitter::Reach::component) const {
    return HullFitter(piece.component, allowed, reach, kind, edges_suffice, tau, limits);
  }
  const CookedPiece& piece;
  double tau;
  std::vector<double> allowed;
  OutlineDistance reach;
  bool edges_suffice;
};

// The contract of issue 16 on pieces that partition outline.
inline void expect_pieces_contract(const std::vector<CookedPiece>& pieces,
                                   const std::vector<Region>& outline, double tau,
                                   const EngineLimits& limits) {
  CookedAsset asset;
  asset.name = "pieces";
  asset.regions = outline;
  asset.pieces = pieces;
  test::expect_cooked_contract(asset, tau, limits);
}

inline Ring scaled(Ring ring, double factor) {
  for (Vec2& v : ring) v *= factor;
  return ring;
}

// A rough disc: n vertices at radius radius, each moved in or out by up to roughness (seeded).
inline Ring rough_disc(std::size_t n, double radius, double roughness, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-roughness, roughness);
  Ring ring = regular_polygon(n, radius);
  for (Vec2& v : ring) v *= (radius + offset(random)) / radius;
  return ring;
}

// From a seeded random simple polygon on a 0.01 grid (the stress family random_simple): its
// vertices (0.82, 0.12), (0.88, 0.18), (0.92, 0.22) are collinear in decimal, but in binary the
// middle one turns left by an orientation of 5.6e-19. At τ 0 they stay in one convex piece.
inline const Ring kNearlyCollinearPiece{
    {0.82, 0.12}, {0.88, 0.18}, {0.92, 0.22}, {0.58, 0.45}, {0.72, 0.19}};

}  // namespace hullcook::test
