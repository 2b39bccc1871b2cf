#include "hullcook/cook/constrain.h"

#include "convex_width.h"
#include "diagonals.h"
#include "hull_fitter.h"
#include "hullcook/core/parallel_for.h"
#include "outline_distance.h"
#include "piece_merge.h"
#include "small_hull.h"

#include "hullcook/cook/contract.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace hullcook {
namespace {

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

double perimeter(const Ring& ring) {
  double length = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    length += glm::length(ring[(i + 1) % n] - ring[i]);
  }
  return length;
}

struct Box {
  Vec2 low{std::numeric_limits<double>::infinity()};
  Vec2 high{-std::numeric_limits<double>::infinity()};
  Box() = default;
  explicit Box(const Ring& ring) {
    for (Vec2 p : ring) low = glm::min(low, p), high = glm::max(high, p);
  }
  bool touches(const Box& other) const {
    return low.x <= other.high.x && other.low.x <= high.x && low.y <= other.high.y &&
           other.low.y <= high.y;
  }
};

// width_of(hull) < width, for hull convex. Its area is at most its width times its diameter, at
// most its box's diagonal: most hulls are shown wide by that, without measuring the width. The
// factor 2 leaves room for the area's rounding: without it, a rectangle 2e6 units long and
// 1e-18 units under the weld wide was shown wide (stop 56).
bool narrower_than(const Ring& hull, double width) {
  const Box box(hull);
  if (std::abs(signed_area(hull)) >= 2 * width * glm::length(box.high - box.low)) return false;
  return width_of(hull) < width;
}

bool is_convex_without_holes(const CookedPiece& piece) {
  if (!piece.component.holes.empty()) return false;
  double component_area = std::abs(signed_area(piece.component.outer));
  double hull_area = std::abs(signed_area(piece.hull));
  return hull_area - component_area <= 1e-12 * std::max(1.0, hull_area);
}

// Slots listed by the cells of a uniform grid that their boxes overlap, about two cells a slot. A
// slot whose box grows is listed in the cells its box newly overlaps (listing it again in all
// of them made a comb's base, which every tooth merges into, fill every cell with copies: 39 s
// for a comb of 4,096 teeth that took 2.8 s before the grid).
class SlotGrid {
 public:
  SlotGrid(const Box& bounds, std::size_t slots) : low_(bounds.low) {
    const Vec2 extent = glm::max(bounds.high - bounds.low, Vec2{0, 0});
    const double area = std::max(extent.x * extent.y, 1e-300);
    cell_ = std::max({std::sqrt(2 * area / double(slots)), extent.x / 1024, extent.y / 1024});
    if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = std::max({extent.x, extent.y, 1.0});
    columns_ = static_cast<std::size_t>(extent.x / cell_) + 1;
    rows_ = static_cast<std::size_t>(extent.y / cell_) + 1;
    cells_.resize(columns_ * rows_);
  }
  void add(std::size_t slot, const Box& box) {
    const Cells now = cells_of(box);
    const auto [listed, added] = listed_.try_emplace(slot, now);
    const Cells before = added ? Cells{1, 0, 1, 0} : listed->second;  // empty when new
    for (std::size_t r = now.r0; r <= now.r1; ++r) {
      for (std::size_t c = now.c0; c <= now.c1; ++c) {
        if (!(before.r0 <= r && r <= before.r1 && before.c0 <= c && c <= before.c1)) {
          cells_[r * columns_ + c].push_back(slot);
        }
      }
    }
    listed->second = now;
  }
  // Appends the slots listed in the cells box overlaps (some more than once); false when that is
  // a quarter of the cells or more, or more than most listings (then out is left with some of
  // them): a scan of every slot costs less than sorting them (a comb's wide pieces each collected
  // tens of thousands).
  bool collect(const Box& box, std::vector<std::size_t>& out, std::size_t most) const {
    const Cells cells = cells_of(box);
    if (4 * (cells.r1 - cells.r0 + 1) * (cells.c1 - cells.c0 + 1) >= cells_.size()) return false;
    for (std::size_t r = cells.r0; r <= cells.r1; ++r) {
      for (std::size_t c = cells.c0; c <= cells.c1; ++c) {
        const std::vector<std::size_t>& cell = cells_[r * columns_ + c];
        out.insert(out.end(), cell.begin(), cell.end());
        if (out.size() > most) return false;
      }
    }
    return true;
  }

 private:
  struct Cells {
    std::size_t c0, c1, r0, r1;  // inclusive
  };
  std::size_t index(double v, double low, std::size_t count) const {
    const double at = (v - low) / cell_;
    if (!(at > 0)) return 0;
    return std::min(count - 1, static_cast<std::size_t>(std::min(at, 1e18)));
  }
  Cells cells_of(const Box& box) const {
    return {index(box.low.x, low_.x, columns_), index(box.high.x, low_.x, columns_),
            index(box.low.y, low_.y, rows_), index(box.high.y, low_.y, rows_)};
  }

  Vec2 low_;
  double cell_ = 1;
  std::size_t columns_ = 1, rows_ = 1;
  std::vector<std::vector<std::size_t>> cells_;
  std::unordered_map<std::size_t, Cells> listed_;  // per slot listed: the cells it is listed in
};

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
  double extent = 0;
  for (Vec2 p : hull) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
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

class Constrainer {
 public:
  // slack: the contract's slack for rounding (contract_slack of the pieces' outer rings);
  // halving: whether a piece may be halved along a diagonal where it is not convex (see add);
  // merge_pieces: whether every placed piece is offered to its neighbours (see finish).
  Constrainer(double tau, const EngineLimits& limits, const SplitComponent& split, double slack,
              double merge_width, bool halving, bool merge_pieces)
      : tau_(tau),
        limits_(limits),
        split_(split),
        slack_(slack),
        merge_width_(merge_width),
        halving_(halving),
        merge_pieces_(merge_pieces) {}

  // Whether some piece was split where halving could have been tried instead (without
  // halving: whether placing the pieces with halving could give other hulls).
  bool could_halve() const {
    return std::find(could_halve_.begin(), could_halve_.end(), 1) != could_halve_.end();
  }

  // Places every piece, on up to threads threads: each piece's slots are its own (they depend
  // on it alone) and are joined in the pieces' order, whatever the thread count.
  void add_all(std::vector<CookedPiece> pieces, unsigned threads) {
    add_all_reusing(nullptr, std::move(pieces), threads);
  }

  // add_all, taking from without (the same pieces placed without halving, not yet finished) the
  // slots of each piece that halving would not change.
  void add_all_reusing(const Constrainer* without, std::vector<CookedPiece> pieces,
                       unsigned threads) {
    std::vector<std::size_t> first_slot;
    if (without) {
      first_slot.push_back(0);
      for (std::size_t count : without->slot_count_)
        first_slot.push_back(first_slot.back() + count);
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
    merged_at_.assign(slots_.size(), 0);
    merged_into_.assign(slots_.size(), 0);
    touched_at_.assign(slots_.size(), 0);
    touching_.assign(slots_.size(), {});
  }

  // Places the pieces no hull of their own could hold: each is merged into a neighbour, or
  // given the smallest engine-ready hull that holds it. Throws InputError when neither keeps τ.
  std::vector<CookedPiece> finish(std::string_view source) {
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

 private:
  struct Slot {
    CookedPiece piece;  // its hull: the decomposition's
    Ring hull;          // the engine-ready hull once placed
    bool placed = false;
    bool merged = false;               // merged into another slot
    bool splits_into_slivers = false;  // every halving of its convex component left a sliver
    bool is_sliver = false;            // its component is a sliver: merged, or refused
    bool is_thin = false;              // placed, but thinner than merge_width
  };

  // Appends to out the slots of piece: one, or those of its parts when it is split.
  void add(CookedPiece piece, int depth, std::vector<Slot>& out, bool& could_halve) const {
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

  // An engine-ready hull for piece: the decomposition's, as most meet the limits, else one grown
  // within τ of its own component (stricter than the outline, it keeps hulls on their pieces
  // rather than spread over their neighbours).
  std::optional<Ring> engine_hull(const CookedPiece& piece) const {
    if (hull_meets_limits(piece.hull, limits_)) return piece.hull;
    std::vector<double> allowed = allowed_depths(piece.component, piece.hull, tau_);
    OutlineDistance reach({&piece.component});
    bool edges_suffice = pockets_within(piece.component, piece.hull, tau_);
    HullFitter fitter(piece.component, allowed, reach, HullFitter::Reach::component, edges_suffice,
                      tau_, limits_);
    return fitter.fit(piece.hull);
  }

  // The placed slot of ring when it is one piece at τ that one engine-ready hull holds.
  std::optional<Slot> one_placed_slot(Ring ring, std::uint32_t region) const {
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

  // Adds to out the slots of slices of component (without holes, not convex), cut off one after
  // another along inner diagonals, each the largest that one engine-ready hull holds; false
  // (out unchanged) when some slice cannot be cut, or the slices would be no fewer than
  // fewer_than. A slice straddles the diagonal the last one left, so the cuts run across the
  // piece like a loaf's: each hull takes about max_verts - 2 new vertices of the rim, where
  // halves of halves gave a traced 512 px disc 8 hulls (5 slices) and a 2048 px one 22 (13).
  // guess: the first slice's length to start the search from [vertices].
  bool slice(const Region& component, std::uint32_t region, std::vector<Slot>& out,
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

  // The depth add and split are given a half at (see halve_in_two): it is only halved further,
  // not decomposed finer, nor sliced (slicing every half of every halving was most of the time
  // of cutting a rough disc of 10,000 vertices into hulls of 4).
  static constexpr int kHalfDepth = 4;

  // Adds to out the slots of component (without holes, not convex) cut along diagonals: of its
  // halves (see halve_in_two) or its slices (see slice), whichever are fewer and all placed
  // (halves on a tie, and without slicing when the halves are two); false when neither cuts it.
  bool halve(const Region& component, std::uint32_t region, std::vector<Slot>& out,
             bool& could_halve, bool may_slice = true) const {
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

  // Adds to out the slots of the halves of component (without holes, not convex; see
  // halve_along_diagonal), each decomposed at τ and then only halved further; false when no
  // diagonal halves it.
  bool halve_in_two(const Region& component, std::uint32_t region, std::vector<Slot>& out,
                    bool& could_halve) const {
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

  // add's splits of a piece no hull fits: finer decompositions from depth on, then halves.
  void split(CookedPiece piece, int depth, std::vector<Slot>& out, bool& could_halve) const {
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
            add(CookedPiece{Region{std::move(*half), {}}, std::move(hull), 0.0, piece.region}, 3,
                out, could_halve);
          }
          return;
        }
      } else if (piece.component.holes.empty()) {
        // A half (see halve), or left whole at τ 0: a notch no deeper than the contract's slack,
        // which only cuts that leave slivers resolve (see resolve_notch); at 1e6 from the origin
        // a piece 25 long and 4e-3 wide kept one in a hull of 10 vertices, over --max-verts 8.
        if (halving_ &&
            halve(piece.component, piece.region, out, could_halve, depth != kHalfDepth)) {
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

 private:
  // Merges every slot that wants it (and is not merged already) into a neighbour, pass after
  // pass while one merges: a merge may make room for another. A slot that failed is tried again
  // only once it, or a slot that touched it when it failed, has grown or merged since: its try
  // depends on the slots that touch it alone, and a slot that touches it later has grown by one
  // that touched it. (Retrying it when any slot whose box may touch it grew retried every spike
  // of a star whenever its hub grew: a 32,000-vertex star's 219 merges took 300,000 tries.)
  template <typename Wants>
  void merge_while(const Wants& wants) {
    std::vector<std::size_t> failed_at(slots_.size(), 0);  // the clock then; 0: not failed
    auto changed_since = [&](std::size_t k, std::size_t time) {
      if (grown_at_[k] > time) return true;
      return std::any_of(touching_[k].begin(), touching_[k].end(), [&](std::size_t j) {
        return grown_at_[j] > time || merged_at_[j] > time;
      });
    };
    bool progress = true;
    while (progress) {
      progress = false;
      for (std::size_t k = 0; k < slots_.size(); ++k) {
        if (!wants(slots_[k]) || slots_[k].merged) continue;
        if (failed_at[k] != 0 && !changed_since(k, failed_at[k])) continue;
        if (merge_into_neighbour(k)) {
          progress = true;
        } else {
          failed_at[k] = clock_;
        }
      }
    }
  }

  // Merges slot k into the neighbour it shares the longest cut with, among those whose merged
  // component needs no split at τ and whose hull then fits within the limits.
  bool merge_into_neighbour(std::size_t k) {
    const CookedPiece& small = slots_[k].piece;
    const Box& box = boxes_[k];
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
    std::vector<std::size_t>& touching = touching_[k];  // for merge_while, should this fail
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
      const int shared = boundary_points_shared(small.component.outer, other.piece.component.outer);
      if (shared > 0) touching.push_back(j);
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
      boxes_[option.slot] = Box(neighbour.piece.component.outer);
      grown_at_[option.slot] = merged_at_[k] = ++clock_;
      merged_into_[k] = option.slot;
      if (grids_[neighbour.piece.region])
        grids_[neighbour.piece.region]->add(option.slot, boxes_[option.slot]);
      return true;
    }
    return false;
  }

  // The slots of a region whose boxes may touch box, ascending (as slots_of_region_ lists them):
  // a region of more than kSlotsWithoutGrid slots is searched through a grid of its boxes, where
  // a scan of all of them made merging the pieces of a maze quadratic.
  static constexpr std::size_t kSlotsWithoutGrid = 64;
  const std::vector<std::size_t>& slots_near(std::size_t region, const Box& box) {
    const std::vector<std::size_t>& all = slots_of_region_[region];
    if (all.size() <= kSlotsWithoutGrid) return all;
    std::optional<SlotGrid>& grid = grids_[region];
    if (!grid) {
      Box bounds;
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

  // For each vertex of merged, the depth it was allowed in the slot it came from.
  std::vector<double> merged_depths(const Region& merged, const Slot& a, const Slot& b) const {
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

  // Gives slot k the smallest engine-ready hull that holds its component. It may reach over the
  // neighbours: only the outline bounds it, and cells prove its area.
  bool grow(std::size_t k) {
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
    for (Ring& candidate : small_hulls(slot.piece.component.outer, limits_, tau_)) {
      if (!hull_meets_limits(candidate, limits_) || !fitter.holds_component(candidate) ||
          !fitter.growth_within(candidate, known_inside ? known : Ring{})) {
        continue;
      }
      std::optional<Ring> sealed = fitter.seal(std::move(candidate));
      if (sealed && hull_meets_limits(*sealed, limits_) && fitter.edges_within_depth(*sealed)) {
        slot.hull = std::move(*sealed);
        slot.placed = true;
        return true;
      }
    }
    return false;
  }

  // Whether hull (convex) is thinner than merge_width.
  bool is_thin(const Ring& hull) const {
    return merge_width_ > 0 && narrower_than(hull, merge_width_);
  }

  bool is_small(const CookedPiece& piece) const {
    return piece.hull.size() < 3 || narrower_than(piece.hull, limits_.weld_distance());
  }

  // The largest X such that every weld below X plus its rounding stays below width (0: none);
  // the rounding is constant between its steps (EngineLimits::RoundingSteps).
  double largest_weld_below(double width) const {
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

  // A piece thinner than the weld that no hull within τ holds: the weld is too coarse for τ. Any
  // other piece is split down to convex parts and halves of them, which always fit; one that
  // could not be split (holes the decomposition kept) is an internal error.
  // Of the unplaced slots (ascending), the first that is not merely thinner than the weld is
  // named; when all are, the thinnest, whose width the advice must go below.
  [[noreturn]] void throw_unplaceable(const std::vector<std::size_t>& unplaced,
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

  // others: how many more pieces are thinner than the weld and unplaced, none thinner.
  [[noreturn]] void throw_unplaceable(const Slot& slot, std::string_view source,
                                      std::size_t others) const {
    if (slot.is_sliver) {
      std::ostringstream ending;
      ending << " and no neighbour could take within tau = " << tau_
             << "; raise --tau, or move the input nearer the origin";
      throw InputError(sliver_piece_refusal(slot.piece.component, source) + ending.str());
    }
    Box box(slot.piece.component.outer);
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

  double tau_;
  EngineLimits limits_;
  const SplitComponent& split_;
  double slack_;
  double merge_width_;
  bool halving_;
  bool merge_pieces_;
  std::vector<char> could_halve_;        // per piece given to add_all: see could_halve
  std::vector<std::size_t> slot_count_;  // per piece given to add_all: its slots, in order
  std::vector<Slot> slots_;
  std::vector<std::vector<std::size_t>> slots_of_region_;  // ascending, as slots_ are ordered
  std::vector<Box> boxes_;                                 // per slot: its component's box
  std::vector<std::optional<SlotGrid>> grids_;             // per region: see slots_near
  std::vector<std::size_t> near_;                          // slots_near's answer
  std::size_t clock_ = 1;                                  // counts merges, from 1
  std::vector<std::size_t> grown_at_;     // per slot: the clock when it last grew by a merge
  std::vector<std::size_t> merged_at_;    // per slot: the clock when it merged (0: not)
  std::vector<std::size_t> merged_into_;  // per merged slot: the slot it merged into
  std::vector<std::vector<std::size_t>> touching_;  // per slot: those touching it at its last try
  std::vector<std::size_t> touched_at_;             // per slot: the clock at its last try (0: none)
  std::optional<OutlineDistance> outline_;  // the union of all components, built when needed
};

}  // namespace

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
