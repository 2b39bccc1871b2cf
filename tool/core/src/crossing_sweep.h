// Internal: whether the edges of a region's rings meet anywhere but at the vertex two consecutive
// edges share, by a sweep (Shamos and Hoey): the validation's fallback when its grid would test
// too many pairs (spiky stars, long combs).
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace hullcook::detail {

struct RingEdge {
  int ring;           // 0 = outer, h = hole h (1-based)
  std::size_t index;  // the edge from vertex index to the next
  Vec2 a, b;
};

// Consecutive edges of one ring: the only pairs allowed to share a point (their vertex).
inline bool consecutive(const RingEdge& e, const RingEdge& f,
                        const std::vector<std::size_t>& ring_sizes) {
  if (e.ring != f.ring) return false;
  const std::size_t n = ring_sizes[static_cast<std::size_t>(e.ring)];
  return (e.index + 1) % n == f.index || (f.index + 1) % n == e.index;
}

// A pair (i < j) of edges that meet without being consecutive, or nullopt when there is none.
// The rings must have no repeated consecutive vertex and no spike (remove_degenerate_vertices),
// and their points must be finite. O(n log n) with exact predicates; which pair it returns when
// there are several is not specified (but the same for the same input).
std::optional<std::pair<std::size_t, std::size_t>> find_crossing_by_sweep(
    const std::vector<RingEdge>& edges, const std::vector<std::size_t>& ring_sizes);

}  // namespace hullcook::detail
