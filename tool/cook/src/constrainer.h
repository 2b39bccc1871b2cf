// The Constrainer: it places a decomposition's pieces in hulls that meet the engine limits
// (splitting, slicing and halving the pieces no hull of their own holds: constrain_place.cpp),
// merges the unplaced and thin ones into their neighbours (constrain_merge.cpp), and words the
// refusal when some piece fits nowhere (constrain_refusal.cpp). apply_engine_limits
// (constrain.cpp) runs it, with and without halving.
#pragma once

#include "merge_retries.h"
#include "outline_distance.h"
#include "slot_grid.h"

#include "hullcook/cook/constrain.h"
#include "hullcook/core/polygon.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace hullcook {

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
                       unsigned threads);

  // Places the pieces no hull of their own could hold: each is merged into a neighbour, or
  // given the smallest engine-ready hull that holds it. Throws InputError when neither keeps τ.
  std::vector<CookedPiece> finish(std::string_view source);

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

  // Placing (constrain_place.cpp).

  // Appends to out the slots of piece: one, or those of its parts when it is split.
  void add(CookedPiece piece, int depth, std::vector<Slot>& out, bool& could_halve) const;

  // An engine-ready hull for piece: the decomposition's, as most meet the limits, else one grown
  // within τ of its own component (stricter than the outline, it keeps hulls on their pieces
  // rather than spread over their neighbours).
  std::optional<Ring> engine_hull(const CookedPiece& piece) const;

  // The placed slot of ring when it is one piece at τ that one engine-ready hull holds.
  std::optional<Slot> one_placed_slot(Ring ring, std::uint32_t region) const;

  // Adds to out the slots of slices of component (without holes, not convex), cut off one after
  // another along inner diagonals, each the largest that one engine-ready hull holds; false
  // (out unchanged) when some slice cannot be cut, or the slices would be no fewer than
  // fewer_than. A slice straddles the diagonal the last one left, so the cuts run across the
  // piece like a loaf's: each hull takes about max_verts - 2 new vertices of the rim, where
  // halves of halves gave a traced 512 px disc 8 hulls (5 slices) and a 2048 px one 22 (13).
  // guess: the first slice's length to start the search from [vertices].
  bool slice(const Region& component, std::uint32_t region, std::vector<Slot>& out,
             std::size_t guess, std::size_t fewer_than) const;

  // The depth add and split are given a half at (see halve_in_two): it is only halved further,
  // not decomposed finer, nor sliced (slicing every half of every halving was most of the time
  // of cutting a rough disc of 10,000 vertices into hulls of 4).
  static constexpr int kHalfDepth = 4;

  // Adds to out the slots of component (without holes, not convex) cut along diagonals: of its
  // halves (see halve_in_two) or its slices (see slice), whichever are fewer and all placed
  // (halves on a tie, and without slicing when the halves are two); false when neither cuts it.
  bool halve(const Region& component, std::uint32_t region, std::vector<Slot>& out,
             bool& could_halve, bool may_slice = true) const;

  // Adds to out the slots of the halves of component (without holes, not convex; see
  // halve_along_diagonal), each decomposed at τ and then only halved further; false when no
  // diagonal halves it.
  bool halve_in_two(const Region& component, std::uint32_t region, std::vector<Slot>& out,
                    bool& could_halve) const;

  // add's splits of a piece no hull fits: finer decompositions from depth on, then halves.
  void split(CookedPiece piece, int depth, std::vector<Slot>& out, bool& could_halve) const;

  // Merging (constrain_merge.cpp).
  // Merges every slot that wants it (and is not merged already) into a neighbour, pass after
  // pass while one merges: a merge may make room for another. A slot that failed is tried again
  // only once it has grown, or a slot that may now share a cut with it has grown (see
  // MergeRetries): its try depends on the slots that touch it alone, and a slot that touches it
  // later has grown by one that touched it. (Retrying it when any slot whose box may touch it
  // grew retried every spike of a star whenever its hub grew: a 32,000-vertex star's 219 merges
  // took 300,000 tries.)
  template <typename Wants>
  void merge_while(const Wants& wants);

  // Merges slot k into the neighbour it shares the longest cut with, among those whose merged
  // component needs no split at τ and whose hull then fits within the limits.
  bool merge_into_neighbour(std::size_t k);

  // The slots of a region whose boxes may touch box, ascending (as slots_of_region_ lists them):
  // a region of more than kSlotsWithoutGrid slots is searched through a grid of its boxes, where
  // a scan of all of them made merging the pieces of a maze quadratic.
  static constexpr std::size_t kSlotsWithoutGrid = 64;
  const std::vector<std::size_t>& slots_near(std::size_t region, const SlotBox& box);

  // For each vertex of merged, the depth it was allowed in the slot it came from.
  std::vector<double> merged_depths(const Region& merged, const Slot& a, const Slot& b) const;

  // Gives slot k the smallest engine-ready hull that holds its component, or a hull grown for an
  // earlier slot that holds it too. It may reach over the neighbours: only the outline bounds
  // it, and cells prove its area.
  bool grow(std::size_t k);

  // Whether hull (convex) is thinner than merge_width.
  bool is_thin(const Ring& hull) const;

  bool is_small(const CookedPiece& piece) const;

  // Refusing (constrain_refusal.cpp).

  // The largest X such that every weld below X plus its rounding stays below width (0: none);
  // the rounding is constant between its steps (EngineLimits::RoundingSteps).
  double largest_weld_below(double width) const;

  // A piece thinner than the weld that no hull within τ holds: the weld is too coarse for τ. Any
  // other piece is split down to convex parts and halves of them, which always fit; one that
  // could not be split (holes the decomposition kept) is an internal error.
  // Of the unplaced slots (ascending), the first that is not merely thinner than the weld is
  // named; when all are, the thinnest, whose width the advice must go below.
  [[noreturn]] void throw_unplaceable(const std::vector<std::size_t>& unplaced,
                                      std::string_view source) const;

  // others: how many more pieces are thinner than the weld and unplaced, none thinner.
  [[noreturn]] void throw_unplaceable(const Slot& slot, std::string_view source,
                                      std::size_t others) const;

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
  std::vector<SlotBox> boxes_;                             // per slot: its component's box
  std::vector<std::optional<SlotGrid>> grids_;             // per region: see slots_near
  std::vector<std::size_t> near_;                          // slots_near's answer
  std::size_t clock_ = 1;                                  // counts merges, from 1
  std::vector<std::size_t> grown_at_;     // per slot: the clock when it last grew by a merge
  std::vector<std::size_t> merged_into_;  // per merged slot: the slot it merged into
  std::vector<std::vector<std::size_t>> touching_;  // per slot: those touching it at its last try
  std::vector<std::size_t> touched_at_;             // per slot: the clock at its last try (0: none)
  MergeRetries retries_;                            // merge_while's: which slots may merge now
  std::optional<OutlineDistance> outline_;  // the union of all components, built when needed
  // The hulls grow gave, in order, with whether each is proven wholly within τ of the outline
  // (0: not yet asked, 1: yes, -1: not proven), for the slots grown after it.
  struct GrownHull {
    Ring hull;
    SlotBox box;
    signed char whole = 0;
  };
  std::vector<GrownHull> grown_hulls_;
};

}  // namespace hullcook
