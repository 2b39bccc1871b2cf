// Engine constraints, applied after the decomposition: Box2D and Chipmunk accept every hull we
// write unchanged, and the error bound τ still holds.
#pragma once

#include "hullcook/cook/asset.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

// A vertex is collinear with its neighbours (and removed) when it is closer than this fraction
// of the weld distance to the line through them: engines computing hulls in float must see a
// strict turn.
inline constexpr double kCollinearFractionOfWeld = 0.1;

struct EngineLimits {
  std::size_t max_verts = 8;  // per hull; 0 = unlimited
  double weld = 0.005;        // [output units] minimum distance between two hull vertices; 0: none
  // [output units] what a writer's rounding may take from the distance between two hull vertices
  // or from a vertex's height over its neighbours' line: twice the most it moves a vertex (the
  // bundle's error bound E and a float's spacing there, formats/SPEC.md §9). With a weld, the
  // cooked hulls keep that much more, so that what a reader gets still keeps the weld.
  double rounding = 0.0;
  // How that rounding depends on the weld [output units]: grid_margin where grid_from < weld, and
  // float_margin where float_from < weld (the writers' grid and floats finer than the weld). All
  // 0: unknown. Only the advice of a refusal uses it, to name a weld that takes the piece.
  struct RoundingSteps {
    double grid_from = 0.0, grid_margin = 0.0;
    double float_from = 0.0, float_margin = 0.0;
    bool known() const { return grid_margin > 0 || float_margin > 0; }
    double at(double weld) const {
      return (grid_from < weld ? grid_margin : 0.0) + (float_from < weld ? float_margin : 0.0);
    }
  };
  RoundingSteps rounding_steps{};
  // The least distance between two vertices of a cooked hull: the weld and the rounding (0
  // without a weld).
  double weld_distance() const { return weld > 0 ? weld + rounding : 0.0; }
  // The least height of a cooked hull's vertex over its neighbours' line (with a weld; without,
  // any strict turn).
  double least_turn() const { return weld > 0 ? kCollinearFractionOfWeld * weld + rounding : 0.0; }
  // --tile: every hull point lies in this box [output units] (the cell), but for rounding
  // (kOutsideBoxFraction of its size): a hull grown past a tile's border is a bump at its seam.
  struct Box {
    Vec2 low, high;
    bool holds(Vec2 p) const;
  };
  std::optional<Box> keep_inside = std::nullopt;
};

// How far, as a fraction of the box's larger side, a hull point may lie outside keep_inside.
inline constexpr double kOutsideBoxFraction = 1e-9;

// Splits a component that no hull within the limits can cover into smaller pieces, each with
// its component, convex hull and concavity; tau is the tolerance to split at. Returns the
// component unchanged (one piece) when it cannot split it further.
using SplitComponent = std::function<std::vector<CookedPiece>(const Region& component, double tau)>;

// Makes every hull satisfy the limits while keeping, for tolerance tau [output units]:
//  - each hull convex, counter-clockwise, with at most max_verts vertices, no two vertices closer
//    than weld and no vertex within kCollinearFractionOfWeld * weld of its neighbours' line;
//  - each component inside its hull, and each component vertex within max(tau, its distance
//    before) of its hull's boundary;
//  - every point of every hull within tau of the outline (the union of the components), proven
//    rather than sampled;
//  - the components partitioning the outline: no piece is ever dropped.
// Hulls only grow (edges are removed by extending their neighbours), within tau of their own
// component: stricter than the outline, it keeps each hull on its piece rather than spread over
// its neighbours. Or components are split further with split, down to convex pieces and halves
// of them, or halved along diagonals where they are not convex: the pieces are placed both ways
// (where halving could change anything) and the way with fewer hulls is kept (halving: false
// places them only the first way, for tests). split must also measure a component whole: called
// with tau itself, it returns one piece exactly when the component needs no split.
// A piece too small for the weld (thinner than weld, or left so by the splits) is merged into the
// neighbour it shares the longest cut with, when the merged component is one piece at tau and its
// hull then meets the limits; otherwise it is given the smallest engine-ready rectangle or
// triangle around it (about weld across) that stays within tau of the outline, over its
// neighbours if need be. Neither is possible only where tau is below the weld, at the outline's
// edge (tau = 0 on a sliver there, or tau a fraction of weld): no hull within tau exists that the
// engine would accept unchanged, so it throws InputError naming source and the piece (lower the
// weld or raise tau) rather than drop the piece or write a hull beyond tau.
// The pieces keep their order; a merged piece takes its neighbour's place. threads: how many may
// fit the pieces' hulls at once (split is then called from as many); the result is the same for
// any count.
// merge_pieces: every placed piece is then also merged into a neighbour that can take it (the
// merged component one piece at tau, its hull within the limits), pass after pass while one
// merges: fewer hulls under the same contract, for more time.
// merge_width [output units]: a hull thinner than this, though it meets the limits, is merged
// into a neighbour as a piece too small for the weld is, where one can take it (the cooker passes
// the bundle's quantization bound, on whose grid such a hull rounds to a segment).
std::vector<CookedPiece> apply_engine_limits(std::vector<CookedPiece> pieces, double tau,
                                             const EngineLimits& limits,
                                             const SplitComponent& split, std::string_view source,
                                             unsigned threads = 1, double merge_width = 0.0,
                                             bool halving = true, bool merge_pieces = false);

// True when hull meets the limits' vertex count, weld and collinearity rules and is a convex,
// counter-clockwise polygon with at least 3 vertices.
bool hull_meets_limits(const Ring& hull, const EngineLimits& limits);

}  // namespace hullcook
