// Merging pieces into their neighbours, and growing hulls over them, where no hull of their own
// fits.
#include "constrainer.h"

#include "hull_fitter.h"
#include "merge_retries.h"
#include "piece_merge.h"
#include "small_hull.h"

#include "hullcook/core/geometry.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <map>
#include <utility>

namespace hullcook {
namespace {

double perimeter(const Ring& ring) {
  double length = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    length += glm::length(ring[(i + 1) % n] - ring[i]);
  }
  return length;
}

constexpr std::size_t kHullVerticesWorthTheTest = 64;

// Whether the union of two pieces surely fails pockets_within(union, its hull, bound), which a
// merge needs, found without building the union (building every neighbour's union was a third of
// the time of cooking with --merge): a piece with holes leaves the union holes; and every vertex
// of a piece lies on its region's boundary (cuts join boundary points), so on the union's, where
// pockets_within measures it (or the vertices either side of it) against the line of a hull edge,
// no nearer than the nearest edge line of the hull of both pieces. A vertex farther than bound
// from all of them, beyond rounding, fails it.
bool union_surely_beyond(const CookedPiece& a, const CookedPiece& b, double bound) {
  if (!a.component.holes.empty() || !b.component.holes.empty()) return true;
  // Each vertex is measured against every edge line: for large hulls (a comb's base) that costs
  // more than the union it spares, and is left to pockets_within.
  if (a.hull.size() + b.hull.size() > kHullVerticesWorthTheTest) return false;
  Ring corners = a.hull;
  corners.insert(corners.end(), b.hull.begin(), b.hull.end());
  const Ring hull = convex_hull(corners);
  const std::size_t m = hull.size();
  if (m < 3) return false;
  const double extent = largest_coordinate(hull);
  const double beyond = bound + 1e-9 * (bound + extent);
  for (const Ring* ring : {&a.component.outer, &b.component.outer}) {
    for (Vec2 v : *ring) {
      bool near_an_edge = false;
      for (std::size_t e = 0; e < m && !near_an_edge; ++e) {
        const Vec2 start = hull[e], edge = hull[e + 1 == m ? 0 : e + 1] - start;
        const double length = glm::length(edge);
        near_an_edge = !(length > 0) || cross(edge, v - start) <= beyond * length;
      }
      if (!near_an_edge) return true;
    }
  }
  return false;
}

// A vertex's position, as a key for the depths it was allowed before a merge.
using VertexKey = std::pair<double, double>;

}  // namespace

std::vector<CookedPiece> Constrainer::finish(std::string_view source) {
  merge_while([](const Slot& slot) { return !slot.placed; });
  // A hull thinner than merge_width goes to a neighbour that can take it (one as thin too,
  // whose merged hull may not be).
  for (Slot& slot : slots_) slot.is_thin = slot.placed && is_thin(slot.hull);
  merge_while([](const Slot& slot) { return slot.is_thin; });
  // With merge_pieces, every piece goes to a neighbour that can take it within τ: the
  // decomposition cuts where a notch is deepest, and pieces cut apart by different notches
  // often make one piece within τ (the sample sprites: 10 % fewer hulls).
  if (merge_pieces_) merge_while([](const Slot& slot) { return slot.placed; });
  // Every piece is tried before one is refused, so that the advice fits them all: a weld
  // lowered below the first's width left the next one to refuse (2-3 rounds on real sprites).
  std::vector<std::size_t> unplaced;
  for (std::size_t k = 0; k < slots_.size(); ++k) {
    if (slots_[k].placed || slots_[k].merged) continue;
    // A grown hull would still hold a sliver.
    if (slots_[k].is_sliver || !grow(k)) unplaced.push_back(k);
  }
  if (!unplaced.empty()) throw_unplaceable(unplaced, source);
  std::vector<CookedPiece> pieces;
  pieces.reserve(slots_.size());
  for (Slot& slot : slots_) {
    if (slot.merged) continue;
    slot.piece.hull = std::move(slot.hull);
    pieces.push_back(std::move(slot.piece));
  }
  return pieces;
}

template <typename Wants>
void Constrainer::merge_while(const Wants& wants) {
  retries_.reset(slots_.size());
  bool progress = true;
  while (progress) {
    progress = false;
    for (std::size_t k = 0; k < slots_.size(); ++k) {
      if (!wants(slots_[k]) || slots_[k].merged || !retries_.worth_trying(k)) continue;
      if (merge_into_neighbour(k)) progress = true;
    }
  }
}

bool Constrainer::merge_into_neighbour(std::size_t k) {
  const CookedPiece& small = slots_[k].piece;
  const SlotBox& box = boxes_[k];
  struct Option {
    double shared;
    std::size_t slot;
    Region merged;
  };
  std::vector<Option> options;
  // Only the slots of its own region whose boxes touch its own (a scan of every slot took 10 s
  // to refuse an image of thousands of blobs whose pieces were all thinner than --weld). Tried
  // again unchanged, only those that touched it at its last try, or the slots they merged into
  // since: any other was apart from it then and has grown by none that touched it. (The boxes
  // of a star's spikes all meet at its hub: 800 of them per try.)
  std::vector<std::size_t>& touching = touching_[k];  // for its next try, should this fail
  std::vector<MergeRetries::Touch> touches;           // for merge_while, should this fail
  std::vector<std::size_t> candidates;
  const bool retouch = touched_at_[k] != 0 && grown_at_[k] <= touched_at_[k];
  if (retouch) {
    for (std::size_t j : touching) {
      while (slots_[j].merged) j = merged_into_[j];
      candidates.push_back(j);
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  }
  touching.clear();
  touched_at_[k] = clock_;
  for (std::size_t j : retouch ? candidates : slots_near(small.region, box)) {
    const Slot& other = slots_[j];
    if (j == k || other.merged || !box.touches(boxes_[j])) continue;
    // Cheap rejections first: most boxes that touch belong to pieces that meet at a point.
    const SharedBoundaryPoints points =
        shared_boundary_points(small.component.outer, other.piece.component.outer);
    const int shared = points.count;
    if (shared > 0) {
      touching.push_back(j);
      touches.push_back({j, shared, points.first});
    }
    if (!other.placed || shared < 2 || union_surely_beyond(small, other.piece, tau_)) continue;
    if (std::optional<Region> merged = merge_components(small.component, other.piece.component)) {
      double shared = perimeter(small.component.outer) + perimeter(other.piece.component.outer) -
                      perimeter(merged->outer);
      options.push_back({shared, j, std::move(*merged)});
    }
  }
  std::stable_sort(options.begin(), options.end(),
                   [](const Option& a, const Option& b) { return a.shared > b.shared; });
  for (Option& option : options) {
    Slot& neighbour = slots_[option.slot];
    const Region& merged = option.merged;
    Ring merged_hull = convex_hull(merged.outer);
    if (!pockets_within(merged, merged_hull, tau_)) continue;
    // The neighbour's engine-ready hull was proven; only what the small piece adds is new.
    Ring start = neighbour.hull;
    start.insert(start.end(), merged.outer.begin(), merged.outer.end());
    start = convex_hull(start);
    std::vector<double> allowed = merged_depths(merged, slots_[k], neighbour);
    OutlineDistance reach({&merged});
    HullFitter fitter(merged, allowed, reach, HullFitter::Reach::component, true, tau_, limits_);
    if (!fitter.holds_component(start) || !fitter.growth_within(start, merged_hull)) continue;
    std::optional<Ring> hull = fitter.fit(start);
    if (!hull) continue;
    // The merged component must be one piece at τ under the asset's measure.
    std::vector<CookedPiece> measured = split_(merged, tau_);
    if (measured.size() != 1) continue;
    neighbour.piece = CookedPiece{std::move(option.merged), std::move(merged_hull),
                                  measured[0].concavity, neighbour.piece.region};
    neighbour.hull = std::move(*hull);
    neighbour.is_thin = is_thin(neighbour.hull);
    slots_[k].merged = true;
    boxes_[option.slot] = SlotBox(neighbour.piece.component.outer);
    grown_at_[option.slot] = ++clock_;
    merged_into_[k] = option.slot;
    retries_.merged(k, option.slot);
    // It is tried no more. (Kept, the lists of a fan's merged pieces, each of all the others
    // that meet at its apex, took 80 MB for a comb 16,384 px wide.)
    std::vector<std::size_t>().swap(touching);
    if (grids_[neighbour.piece.region])
      grids_[neighbour.piece.region]->add(option.slot, boxes_[option.slot]);
    return true;
  }
  retries_.failed(k, touches);
  return false;
}

const std::vector<std::size_t>& Constrainer::slots_near(std::size_t region, const SlotBox& box) {
  const std::vector<std::size_t>& all = slots_of_region_[region];
  if (all.size() <= kSlotsWithoutGrid) return all;
  std::optional<SlotGrid>& grid = grids_[region];
  if (!grid) {
    SlotBox bounds;
    for (std::size_t j : all) {
      bounds.low = glm::min(bounds.low, boxes_[j].low);
      bounds.high = glm::max(bounds.high, boxes_[j].high);
    }
    grid.emplace(bounds, all.size());
    for (std::size_t j : all) grid->add(j, boxes_[j]);
  }
  near_.clear();
  if (!grid->collect(box, near_, all.size() / 2)) return all;
  std::sort(near_.begin(), near_.end());
  near_.erase(std::unique(near_.begin(), near_.end()), near_.end());
  return near_;
}

std::vector<double> Constrainer::merged_depths(const Region& merged, const Slot& a,
                                               const Slot& b) const {
  std::map<VertexKey, double> before;
  for (const Slot* slot : {&a, &b}) {
    const Ring& hull = slot->placed ? slot->hull : slot->piece.hull;
    std::vector<double> depths = allowed_depths(slot->piece.component, hull, tau_);
    std::size_t i = 0;
    auto note = [&](const Ring& ring) {
      for (Vec2 v : ring) {
        double& depth = before.try_emplace({v.x, v.y}, 0.0).first->second;
        depth = std::max(depth, depths[i++]);
      }
    };
    note(slot->piece.component.outer);
    for (const Ring& hole : slot->piece.component.holes) note(hole);
  }
  std::vector<double> allowed;
  auto take = [&](const Ring& ring) {
    for (Vec2 v : ring) {
      auto found = before.find({v.x, v.y});
      allowed.push_back(found == before.end() ? tau_ : found->second);
    }
  };
  take(merged.outer);
  for (const Ring& hole : merged.holes) take(hole);
  return allowed;
}

bool Constrainer::grow(std::size_t k) {
  if (!outline_) {
    std::vector<const Region*> components;
    for (const Slot& slot : slots_) {
      if (!slot.merged) components.push_back(&slot.piece.component);
    }
    outline_.emplace(components);
  }
  Slot& slot = slots_[k];
  const Ring& known = slot.piece.hull;
  bool known_inside = known.size() >= 3 && signed_area(known) > 0;
  std::vector<double> allowed = allowed_depths(slot.piece.component, known, tau_);
  HullFitter fitter(slot.piece.component, allowed, *outline_, HullFitter::Reach::outline, false,
                    tau_, limits_);
  // A hull grown for an earlier slot that holds this one, proven once wholly within τ, needs no
  // proof of its own: the teeth of a comb thinner than the weld each grew a hull round all of
  // them, each proven by cells that searched every tooth (1,000 teeth: 40 s).
  const SlotBox box(slot.piece.component.outer);
  for (GrownHull& grown : grown_hulls_) {
    if (grown.whole < 0 || !(grown.box.low.x <= box.low.x && grown.box.low.y <= box.low.y &&
                             box.high.x <= grown.box.high.x && box.high.y <= grown.box.high.y)) {
      continue;
    }
    if (!fitter.holds_component(grown.hull) || !fitter.edges_within_depth(grown.hull)) continue;
    std::optional<Ring> sealed = fitter.seal(grown.hull);
    if (!sealed || *sealed != grown.hull) continue;
    if (grown.whole == 0) grown.whole = outline_->growth_within(grown.hull, Ring{}, tau_) ? 1 : -1;
    if (grown.whole < 0) continue;
    slot.hull = grown.hull;
    slot.placed = true;
    return true;
  }
  for (Ring& candidate : small_hulls(slot.piece.component.outer, limits_, tau_)) {
    if (!hull_meets_limits(candidate, limits_) || !fitter.holds_component(candidate) ||
        !fitter.growth_within(candidate, known_inside ? known : Ring{})) {
      continue;
    }
    std::optional<Ring> sealed = fitter.seal(std::move(candidate));
    if (sealed && hull_meets_limits(*sealed, limits_) && fitter.edges_within_depth(*sealed)) {
      grown_hulls_.push_back({*sealed, SlotBox(*sealed)});
      slot.hull = std::move(*sealed);
      slot.placed = true;
      return true;
    }
  }
  return false;
}

}  // namespace hullcook
