#include "hullcook/cook/constrain.h"

#include "constrainer.h"
#include "convex_width.h"
#include "diagonals.h"
#include "hull_fitter.h"
#include "slot_grid.h"

#include "hullcook/cook/contract.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <utility>

namespace hullcook {
namespace {

// width_of(hull) < width, for hull convex. Its area is at most its width times its diameter, at
// most its box's diagonal: most hulls are shown wide by that, without measuring the width. The
// factor 2 leaves room for the area's rounding: without it, a rectangle 2e6 units long and
// 1e-18 units under the weld wide was shown wide (stop 56).
bool narrower_than(const Ring& hull, double width) {
  const SlotBox box(hull);
  if (std::abs(signed_area(hull)) >= 2 * width * glm::length(box.high - box.low)) return false;
  return width_of(hull) < width;
}

}  // namespace

bool Constrainer::is_thin(const Ring& hull) const {
  return merge_width_ > 0 && narrower_than(hull, merge_width_);
}

bool Constrainer::is_small(const CookedPiece& piece) const {
  return piece.hull.size() < 3 || narrower_than(piece.hull, limits_.weld_distance());
}

bool EngineLimits::Box::holds(Vec2 p) const {
  const double slack = kOutsideBoxFraction * std::max(high.x - low.x, high.y - low.y);
  return p.x >= low.x - slack && p.x <= high.x + slack && p.y >= low.y - slack &&
         p.y <= high.y + slack;
}

bool hull_meets_limits(const Ring& hull, const EngineLimits& limits) {
  if (hull.size() < 3 || signed_area(hull) <= 0) return false;
  if (limits.max_verts != 0 && hull.size() > limits.max_verts) return false;
  if (limits.keep_inside) {
    for (Vec2 p : hull) {
      if (!limits.keep_inside->holds(p)) return false;
    }
  }
  for (std::size_t i = 0; i < hull.size(); ++i) {
    if (turn_height(hull, i) <= 0) return false;
  }
  return edges_to_mend(hull, limits).empty();
}

std::vector<CookedPiece> apply_engine_limits(std::vector<CookedPiece> pieces, double tau,
                                             const EngineLimits& limits,
                                             const SplitComponent& split, std::string_view source,
                                             unsigned threads, double merge_width, bool halving,
                                             bool merge_pieces) {
  std::vector<const Ring*> rings;
  rings.reserve(pieces.size());
  for (const CookedPiece& piece : pieces) rings.push_back(&piece.component.outer);
  // Halving a piece that is not convex along a diagonal needs fewer hulls than decomposing it
  // finer where the finer pieces' rims are cut into slivers (a traced disc: 154 hulls, halved 8),
  // but more where the slivers merge away afterwards (a rough disc at --max-verts 3: 80, halved
  // 149), which each piece cannot tell. So the pieces are placed both ways, where halving could
  // change anything, and the way with fewer hulls is kept (without halving on a tie); so is the
  // one that succeeds, when the other is refused.
  const double slack = contract_slack(rings);
  Constrainer without(tau, limits, split, slack, merge_width, false, merge_pieces);
  without.add_all(pieces, threads);
  if (!halving || !without.could_halve()) return without.finish(source);
  Constrainer with(tau, limits, split, slack, merge_width, true, merge_pieces);
  with.add_all_reusing(&without, std::move(pieces), threads);
  std::optional<std::vector<CookedPiece>> placed;
  std::exception_ptr refused;
  try {
    placed = without.finish(source);
  } catch (const InputError&) {
    refused = std::current_exception();
  }
  try {
    std::vector<CookedPiece> halved = with.finish(source);
    if (!placed || halved.size() < placed->size()) return halved;
  } catch (const std::exception&) {
    if (refused) std::rethrow_exception(refused);
  }
  return std::move(*placed);
}

}  // namespace hullcook
