// The signed distance from a point to an asset's outline (every region's outer ring and holes),
// by a grid of its edges: what the output contract asks of every hull point.
#pragma once

#include "cell_grid.h"

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace hullcook::detail {

class OutlineDistance {
 public:
  static constexpr std::size_t kNoEdge = std::numeric_limits<std::size_t>::max();

  // outline: cleaned regions (outer rings counter-clockwise, holes clockwise), not overlapping.
  explicit OutlineDistance(const std::vector<Region>& outline);

  struct Nearest {
    // Positive outside the outline, negative inside, 0 on it [units]. With edge == kNoEdge no edge
    // lies within reach: its magnitude is then only a lower bound (at least reach), and its sign
    // is still exact.
    double signed_distance = 0.0;
    std::size_t edge = kNoEdge;  // an edge at that distance
  };

  // The outline's nearest edge to p, and on which side of the outline p lies: the side of that
  // edge, or of the two edges at its end where the nearest point is a vertex (exact predicates).
  // Searching stops at reach when no edge is nearer.
  Nearest nearest(Vec2 p, double reach) const;

  // Distance from p to one edge of the outline (an edge of nearest()).
  double distance_to_edge(Vec2 p, std::size_t edge) const;

  // Distance from p to the filled outline (0 inside), by a scan of every edge and ring: slow, for
  // confirming what nearest() found.
  double distance_by_scan(Vec2 p) const;

  bool empty() const { return edges_.empty(); }

 private:
  struct Edge {
    Vec2 a, b;
    std::size_t previous, next;  // the ring's edges ending at a and starting at b
  };

  int side_at_nearest_point(Vec2 p, std::size_t edge, double along) const;

  const std::vector<Region>& outline_;
  std::vector<Edge> edges_;
  CellGrid grid_;
  CellBuckets buckets_;
  // Per cell without edges: +1 outside the outline, -1 inside (0 for a cell with edges).
  std::vector<signed char> empty_cell_side_;
};

}  // namespace hullcook::detail
