// Which slots that failed to merge into a neighbour may merge now (Constrainer::merge_while).
// Retrying a slot whenever a slot that touched it grew retried every piece of a fan, all of
// which meet at its apex, each time one of them grew: a comb 16,384 px wide, whose base the
// decomposition fans out from a corner, took 100 s (at 4,096 px and a coarser weld: 615 passes of
// 300 retries each).
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <unordered_map>
#include <vector>

namespace hullcook {

// A failed slot's try depends on its own piece and its neighbours' alone, so it can succeed only
// once it has grown, or once a slot that shares two boundary points with it (what a merge needs:
// boundary_points_shared) has grown since. Every live slot is a union of the slots live at the
// failed try, and a union's boundary lies on its parts' (merge_components makes no new point),
// so the points it shares with the failed slot are among those its parts shared then: a slot
// grown from parts that all touched the failed slot at one and the same point (the pieces of a
// fan, at its apex) shares no more than that point with it, and cannot take it.
//
// So each failed slot is listed by the slots it touched, with the points they shared (one, or two
// or more); when a slot merges into another their lists are joined, and a failed slot that shares
// two points with the grown slot's parts is marked worth a retry, as is a slot that grew itself.
class MergeRetries {
 public:
  // Forgets every try: each slot is worth trying once.
  void reset(std::size_t slots);

  // Whether slot k may merge now: never tried since reset, or marked since its last failure.
  bool worth_trying(std::size_t k) const { return worth_trying_[k] != 0; }

  // A slot the failed slot touched at its try, and the points they shared.
  struct Touch {
    std::size_t slot;
    int shared;  // 1, or 2 for two or more (boundary_points_shared)
    Vec2 point;  // the point shared, when only one is
  };
  // Slot k failed to merge, touching these slots (each live, listed once).
  void failed(std::size_t k, const std::vector<Touch>& touching);

  // Slot from merged into slot into.
  void merged(std::size_t from, std::size_t into);

 private:
  // The failed slot watcher touched parts of the slot whose list this is in, at the point point
  // (numbered by point_number), or at two or more distinct points (kTwoPoints). 8 bytes: a
  // comb's fan lists thousands per try.
  struct Watcher {
    std::uint32_t slot;
    std::uint32_t point;
  };
  static constexpr std::uint32_t kTwoPoints = std::numeric_limits<std::uint32_t>::max();
  // A number per distinct point (kTwoPoints once they run out, as if it were shared with another).
  std::uint32_t point_number(Vec2 p);

  // Without room for the slots' numbers in 32 bits, every slot is always worth trying.
  bool always_ = false;
  std::vector<char> worth_trying_;  // per slot
  // Per slot: whether it is listed as it is now. A failed slot is listed once, at its first
  // failure: while it does not grow, the slots it touched then show every point it shares with
  // any slot later. One that grew is listed again, with what it touches now; its older entries
  // stay, and can only mark it more often.
  std::vector<char> listed_;
  std::vector<char> merged_;                    // per slot: whether it merged (its entries lapse)
  std::vector<std::vector<Watcher>> watchers_;  // per live slot: the failed slots it touched
  struct PointHash {
    std::size_t operator()(Vec2 p) const {
      return std::hash<double>()(p.x) * 31 + std::hash<double>()(p.y);
    }
  };
  std::unordered_map<Vec2, std::uint32_t, PointHash> point_numbers_;  // see point_number
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> joined_at_;  // per watcher: its place in the list merged builds
};

}  // namespace hullcook
