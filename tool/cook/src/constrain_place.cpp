// Placing pieces in engine-ready hulls: each piece whole, or split finer, sliced or halved.
#include "constrainer.h"

#include "diagonals.h"
#include "hull_fitter.h"

#include "hullcook/cook/contract.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/parallel_for.h"

#include <glm/geometric.hpp>

#include <iterator>

namespace hullcook {
namespace {

bool is_convex_without_holes(const CookedPiece& piece) {
  if (!piece.component.holes.empty()) return false;
  double component_area = std::abs(signed_area(piece.component.outer));
  double hull_area = std::abs(signed_area(piece.hull));
  return hull_area - component_area <= 1e-12 * std::max(1.0, hull_area);
}

}  // namespace

void Constrainer::add_all_reusing(const Constrainer* without, std::vector<CookedPiece> pieces,
                                  unsigned threads) {
  std::vector<std::size_t> first_slot;
  if (without) {
    first_slot.push_back(0);
    for (std::size_t count : without->slot_count_) first_slot.push_back(first_slot.back() + count);
  }
  could_halve_.assign(pieces.size(), 0);
  slot_count_.assign(pieces.size(), 0);
  // Most pieces are one slot each.
  slots_ = parallel_join<Slot>(
      pieces.size(), threads,
      [&](std::size_t k, unsigned, std::vector<Slot>& out) {
        const std::size_t before = out.size();
        if (without && !without->could_halve_[k]) {
          out.insert(out.end(), without->slots_.begin() + first_slot[k],
                     without->slots_.begin() + first_slot[k + 1]);
        } else {
          bool could_halve = false;
          add(std::move(pieces[k]), 0, out, could_halve);
          could_halve_[k] = could_halve;
        }
        slot_count_[k] = out.size() - before;
      },
      kItemsWorthAThread, pieces.size());
  boxes_.clear();
  boxes_.reserve(slots_.size());
  for (std::size_t k = 0; k < slots_.size(); ++k) {
    const std::size_t region = slots_[k].piece.region;
    if (region >= slots_of_region_.size()) slots_of_region_.resize(region + 1);
    slots_of_region_[region].push_back(k);
    boxes_.emplace_back(slots_[k].piece.component.outer);
  }
  grids_.resize(slots_of_region_.size());
  grown_at_.assign(slots_.size(), 0);
  merged_into_.assign(slots_.size(), 0);
  touched_at_.assign(slots_.size(), 0);
  touching_.assign(slots_.size(), {});
}

void Constrainer::add(CookedPiece piece, int depth, std::vector<Slot>& out,
                      bool& could_halve) const {
  // A sliver at the contract's rounding, which the decomposition takes only when no other cut
  // is valid (between nearly collinear vertices of different rings, in an outline whose slack
  // is coarse beside its size: 1e-4 wide 1e5 from the origin), is merged into a neighbour.
  if (is_contract_sliver(piece.component, slack_)) {
    Ring hull = piece.hull;
    out.push_back({.piece = std::move(piece), .hull = std::move(hull), .is_sliver = true});
    return;
  }
  if (std::optional<Ring> hull = engine_hull(piece)) {
    out.push_back({.piece = std::move(piece), .hull = std::move(*hull), .placed = true});
    return;
  }
  // Of the two ways to split a piece without holes, the one that gives fewer hulls, all
  // placed: finer decompositions (below), or halving along a diagonal (then halves are only
  // halved again). Halving is tried only where decomposing finer gives more than two slots or
  // leaves one unplaced, so most pieces keep the hulls they had.
  const std::uint32_t region = piece.region;
  std::optional<Region> component;
  if (depth < 3 && piece.component.holes.empty() && !is_small(piece)) {
    component = piece.component;
  }
  const std::size_t first = out.size();
  split(std::move(piece), depth, out, could_halve);
  if (!component) return;
  auto unplaced = [](const Slot& slot) { return !slot.placed; };
  const bool some_unplaced = std::any_of(out.begin() + first, out.end(), unplaced);
  if (out.size() - first <= 2 && !some_unplaced) return;
  could_halve = true;
  if (!halving_) return;
  std::vector<Slot> halved;
  if (!halve(*component, region, halved, could_halve) ||
      std::any_of(halved.begin(), halved.end(), unplaced) ||
      !(halved.size() < out.size() - first || some_unplaced)) {
    return;
  }
  out.resize(first);
  std::move(halved.begin(), halved.end(), std::back_inserter(out));
}

std::optional<Ring> Constrainer::engine_hull(const CookedPiece& piece) const {
  if (hull_meets_limits(piece.hull, limits_)) return piece.hull;
  std::vector<double> allowed = allowed_depths(piece.component, piece.hull, tau_);
  OutlineDistance reach({&piece.component});
  bool edges_suffice = pockets_within(piece.component, piece.hull, tau_);
  HullFitter fitter(piece.component, allowed, reach, HullFitter::Reach::component, edges_suffice,
                    tau_, limits_);
  return fitter.fit(piece.hull);
}

std::optional<Constrainer::Slot> Constrainer::one_placed_slot(Ring ring,
                                                              std::uint32_t region) const {
  Region component{std::move(ring), {}};
  if (!(signed_area(component.outer) > 0) || is_contract_sliver(component, slack_)) {
    return std::nullopt;
  }
  std::vector<CookedPiece> parts = split_(component, tau_);
  if (parts.size() != 1 || is_small(parts[0])) return std::nullopt;
  CookedPiece& piece = parts[0];
  piece.region = region;
  std::optional<Ring> hull = engine_hull(piece);
  if (!hull) return std::nullopt;
  return Slot{.piece = std::move(piece), .hull = std::move(*hull), .placed = true};
}

bool Constrainer::slice(const Region& component, std::uint32_t region, std::vector<Slot>& out,
                        std::size_t guess, std::size_t fewer_than) const {
  // From the vertex farthest from the vertices' mean: an end of an elongated piece, so that
  // the slices cut across it.
  const Ring& outer = component.outer;
  Vec2 mean{0, 0};
  for (Vec2 v : outer) mean += v;
  mean /= static_cast<double>(outer.size());
  std::size_t start = 0;
  for (std::size_t i = 1; i < outer.size(); ++i) {
    if (glm::length(outer[i] - mean) > glm::length(outer[start] - mean)) start = i;
  }
  Ring ring(outer.begin() + std::ptrdiff_t(start), outer.end());
  ring.insert(ring.end(), outer.begin(), outer.begin() + std::ptrdiff_t(start));
  const Ring base = ring;
  const RunsOfRing runs(base);
  std::size_t first = 0;  // ring is base[first .. first + ring.size() - 1]
  std::vector<Slot> slots;
  for (;;) {
    // Slices as many as fewer_than - 1 and a rest that one hull does not hold are no fewer.
    if (slots.size() + 1 >= fewer_than) return false;
    const std::size_t n = ring.size();
    // The rest is tried whole once it is no longer than four slices (decomposing a long rest
    // after every slice was quadratic).
    if (!slots.empty() && n <= 4 * guess) {
      if (std::optional<Slot> whole = one_placed_slot(ring, region)) {
        slots.push_back(std::move(*whole));
        break;
      }
    }
    // The slice of `length` vertices: ring[n - before .. n - 1] and ring[0 .. after], cut
    // along the diagonal from ring[after] to ring[n - before]; the rest of the ring remains.
    if (n < 4) return false;
    // Whether the slice of `length` can be cut along an inner diagonal: a traced rim's pixel
    // steps leave many lengths that cannot.
    auto can_cut = [&](std::size_t length) {
      if (length < 3 || length + 1 > n) return false;
      const std::size_t before = length / 2, after = length - 1 - before;
      return runs.is_inner_diagonal(ring, first, after, n - before);
    };
    // The first length from `length` on, below limit, that can be cut; limit if none.
    auto cuttable_from = [&](std::size_t length, std::size_t limit) {
      while (length < limit && !can_cut(length)) ++length;
      return length;
    };
    // The slot of the slice of `length` (one that can be cut) when one hull holds it and the
    // rest keeps an area that is no sliver (a slice too long leaves none).
    auto holds = [&](std::size_t length) -> std::optional<Slot> {
      const std::size_t before = length / 2, after = length - 1 - before;
      Ring rest(ring.begin() + std::ptrdiff_t(after),
                ring.begin() + std::ptrdiff_t(n - before + 1));
      if (!(signed_area(rest) > 0) || is_contract_sliver(Region{std::move(rest), {}}, slack_)) {
        return std::nullopt;
      }
      Ring cap(ring.end() - std::ptrdiff_t(before), ring.end());
      cap.insert(cap.end(), ring.begin(), ring.begin() + std::ptrdiff_t(after + 1));
      return one_placed_slot(std::move(cap), region);
    };
    // The longest slice one hull holds, by steps of 1, 2, 4, ... from the last one's length, up
    // while they hold and down while they do not, then bisecting; lengths that cannot be cut
    // are passed over. A slice that holds fits, most often, when a shorter one does; a disc's
    // slices are alike, two tries each, most of them.
    std::size_t fits = 2, fails = n;  // a length that holds (nothing below 3), one that not
    std::optional<Slot> best;
    auto try_length = [&](std::size_t length) {
      std::optional<Slot> slot = holds(length);
      if (!slot) {
        fails = length;
        return false;
      }
      fits = length, best = std::move(slot);
      return true;
    };
    const std::size_t guessed = cuttable_from(std::clamp<std::size_t>(guess, 3, n - 1), fails);
    if (guessed < fails && try_length(guessed)) {
      for (std::size_t step = 1; fits + 1 < fails; step *= 2) {
        const std::size_t next = cuttable_from(std::min(fits + step, n - 1), fails);
        if (next >= fails || !try_length(next)) break;
      }
    } else {
      fails = guessed;
      for (std::size_t step = 1; fails > 3 && fits < 3; step *= 2) {
        const std::size_t from = fails > 3 + step ? fails - step : 3;
        const std::size_t next = cuttable_from(from, fails);
        if (next >= fails) {
          fails = from;
        } else {
          try_length(next);
        }
      }
    }
    while (fails - fits > 1) {
      const std::size_t middle = cuttable_from(fits + (fails - fits) / 2, fails);
      if (middle >= fails) {
        fails = fits + (fails - fits) / 2;
      } else {
        try_length(middle);
      }
    }
    if (!best) return false;
    const std::size_t before = fits / 2, after = fits - 1 - before;
    slots.push_back(std::move(*best));
    first += after;
    ring =
        Ring(ring.begin() + std::ptrdiff_t(after), ring.begin() + std::ptrdiff_t(n - before + 1));
    guess = fits;
  }
  std::move(slots.begin(), slots.end(), std::back_inserter(out));
  return true;
}

bool Constrainer::halve(const Region& component, std::uint32_t region, std::vector<Slot>& out,
                        bool& could_halve, bool may_slice) const {
  std::vector<Slot> halves, slices;
  const bool halved = halve_in_two(component, region, halves, could_halve);
  const bool halves_placed = halved && std::all_of(halves.begin(), halves.end(),
                                                   [](const Slot& slot) { return slot.placed; });
  // The first slice's length is guessed from the halves: about as many slices, most often.
  const std::size_t guess = component.outer.size() / std::max<std::size_t>(halves.size(), 2);
  const bool sliced =
      may_slice && !(halves_placed && halves.size() <= 2) &&
      slice(component, region, slices, guess, halves_placed ? halves.size() : std::size_t(-1));
  if (!sliced && !halved) return false;
  std::vector<Slot>& kept =
      sliced && (!halves_placed || slices.size() < halves.size()) ? slices : halves;
  std::move(kept.begin(), kept.end(), std::back_inserter(out));
  return true;
}

bool Constrainer::halve_in_two(const Region& component, std::uint32_t region,
                               std::vector<Slot>& out, bool& could_halve) const {
  auto halves = halve_along_diagonal(component.outer, slack_);
  if (!halves) return false;
  for (Ring* half : {&halves->first, &halves->second}) {
    for (CookedPiece& part : split_(Region{std::move(*half), {}}, tau_)) {
      part.region = region;
      add(std::move(part), kHalfDepth, out, could_halve);
    }
  }
  return true;
}

void Constrainer::split(CookedPiece piece, int depth, std::vector<Slot>& out,
                        bool& could_halve) const {
  // A piece thinner than the weld cannot hold an engine hull of its own, nor can its parts.
  bool splits_into_slivers = false;
  if (!is_small(piece)) {
    // Finer decompositions leave more room for growth; at τ = 0 the pieces are convex.
    static constexpr double kSplitFractions[] = {0.5, 0.125, 0.0};
    for (; depth < 3; ++depth) {
      std::vector<CookedPiece> parts = split_(piece.component, tau_ * kSplitFractions[depth]);
      if (parts.size() > 1) {
        for (CookedPiece& part : parts) {
          part.region = piece.region;
          add(std::move(part), depth + 1, out, could_halve);
        }
        return;
      }
    }
    if (is_convex_without_holes(piece)) {
      if (auto halves = halve_convex(piece.component.outer, slack_, &splits_into_slivers)) {
        for (Ring* half : {&halves->first, &halves->second}) {
          Ring hull = convex_hull(*half);
          add(CookedPiece{Region{std::move(*half), {}}, std::move(hull), 0.0, piece.region}, 3, out,
              could_halve);
        }
        return;
      }
    } else if (piece.component.holes.empty()) {
      // A half (see halve), or left whole at τ 0: a notch no deeper than the contract's slack,
      // which only cuts that leave slivers resolve (see resolve_notch); at 1e6 from the origin
      // a piece 25 long and 4e-3 wide kept one in a hull of 10 vertices, over --max-verts 8.
      if (halving_ && halve(piece.component, piece.region, out, could_halve, depth != kHalfDepth)) {
        return;
      }
      could_halve = true;
      splits_into_slivers = true;
    }
  }
  Ring hull = piece.hull;
  out.push_back({.piece = std::move(piece),
                 .hull = std::move(hull),
                 .splits_into_slivers = splits_into_slivers});
}

}  // namespace hullcook
