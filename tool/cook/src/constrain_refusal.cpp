// The refusal of a piece that fits nowhere, with the setting that would let it fit.
#include "constrainer.h"

#include "convex_width.h"

#include "hullcook/cook/contract.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hullcook {

double Constrainer::largest_weld_below(double width) const {
  const EngineLimits::RoundingSteps& steps = limits_.rounding_steps;
  double first = std::min(steps.grid_from, steps.float_from);
  double second = std::max(steps.grid_from, steps.float_from);
  double best = 0.0, low = 0.0;
  for (const double high : {first, second, std::numeric_limits<double>::infinity()}) {
    const double rounding =
        std::isfinite(high) ? steps.at(high) : steps.grid_margin + steps.float_margin;
    const double candidate = std::min(high, width - rounding);
    if (candidate > low) best = std::max(best, candidate);
    low = high;
  }
  return best;
}

void Constrainer::throw_unplaceable(const std::vector<std::size_t>& unplaced,
                                    std::string_view source) const {
  std::size_t named = unplaced.front();
  double named_width = std::numeric_limits<double>::infinity();
  for (std::size_t k : unplaced) {
    const Slot& slot = slots_[k];
    if (slot.is_sliver || slot.splits_into_slivers || !is_small(slot.piece)) {
      throw_unplaceable(slot, source, 0);
    }
    const double width = width_of(slot.piece.hull);
    if (width < named_width) named = k, named_width = width;
  }
  throw_unplaceable(slots_[named], source, unplaced.size() - 1);
}

void Constrainer::throw_unplaceable(const Slot& slot, std::string_view source,
                                    std::size_t others) const {
  if (slot.is_sliver) {
    std::ostringstream ending;
    ending << " and no neighbour could take within tau = " << tau_
           << "; raise --tau, or move the input nearer the origin";
    throw InputError(sliver_piece_refusal(slot.piece.component, source) + ending.str());
  }
  SlotBox box(slot.piece.component.outer);
  std::ostringstream message;
  message << source << ": a piece of " << region_area(slot.piece.component)
          << " square units near (" << 0.5 * (box.low.x + box.high.x) << ", "
          << 0.5 * (box.low.y + box.high.y) << ")";
  if (slot.splits_into_slivers) {
    // Its vertices lie so near a line that every split is thinner than the contract's
    // rounding (a side of 1e-7 bumps cut into triangles at --max-verts 3).
    message << " cannot be split into hulls of at most " << limits_.max_verts
            << " vertices: every split leaves a sliver (thinner than the rounding of its "
               "coordinates); raise --max-verts or --tau";
    throw InputError(message.str());
  }
  if (!is_small(slot.piece)) {
    message << " with " << slot.piece.component.holes.size()
            << " holes could not be split into pieces that fit the engine limits";
    throw std::logic_error(message.str());
  }
  // Its width decides (is_small): a weld whose distance is below it makes the piece an
  // ordinary one, which always fits.
  const double width = width_of(slot.piece.hull);
  message << " is " << width << " units wide, thinner than the weld distance " << limits_.weld;
  if (limits_.rounding > 0) {
    message << " (" << limits_.weld_distance() << " with the " << limits_.rounding
            << " that the writers' rounding may take from it)";
  }
  message << ", and can be neither merged into a neighbour nor given an engine-ready hull "
             "within tau = "
          << tau_ << " output units";
  if (others > 0) {
    message << "; neither can " << others << " other piece" << (others == 1 ? "" : "s")
            << ", none of them thinner";
  }
  message << "; ";
  // A weld w takes the piece where w plus the rounding at w is below its width. The rounding
  // steps down as the weld passes below the writers' grid and floats, so the largest such w
  // may lie just under a step rather than at the width less today's rounding (stop 55's review:
  // 99 of 209 Godot images told to go below 1e-5 cooked at 0.022).
  const double advised = largest_weld_below(width);
  if (limits_.rounding_steps.known() && advised > 0) {
    const double there = limits_.rounding_steps.at(advised);
    message << "lower --weld below " << advised
            << (advised == width           ? " (its width)"
                : advised == width - there ? " (its width less the rounding there)"
                                           : " (where the writers' rounding margin steps down)")
            << ", ";
  } else if (width > limits_.rounding) {
    message << "lower --weld below " << width - limits_.rounding << " (its width"
            << (limits_.rounding > 0 ? " less the rounding" : "") << "), ";
  } else {
    message << "turn the weld off (--weld 0), ";
  }
  message << "or raise --tau or lower --ppu";
  throw InputError(message.str());
}

}  // namespace hullcook
