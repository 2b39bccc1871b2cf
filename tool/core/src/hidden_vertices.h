// Internal: vertices of ∂P0 that a vertex of a hole cannot see, proved a run at a time. A full
// search for the vertex of ∂P0 nearest to a hole's vertex that it sees tests every vertex of ∂P0
// when it sees none (a hole walled in by other holes: 1,177 holes of a noise texture, and most of
// its decomposition). A run of consecutive vertices whose box lies behind one edge, as seen from
// the hole's vertex, is refused by that edge without a test of its own.
#pragma once

#include "decomposition_types.h"
#include "sight.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace hullcook::detail {

class HiddenVertices {
 public:
  // outer: the region's ∂P0, which the view's region holds; it must outlive this object.
  explicit HiddenVertices(const Ring& outer);

  // Sets seen[i] = 0 (unseen) for vertices i of ∂P0 that lie behind an edge of the region as seen
  // from vertex `from` (of a hole) of the view's region. seen[i] is 1 where from is known to see
  // i (no edge hides that run), 0 where it is known not to, -1 where unknown; it has one entry
  // per vertex of ∂P0. The edges found serve the next calls, from any vertex.
  void refuse(RegionView& view, VertexRef from, std::vector<signed char>& seen);

  struct Box {
    Vec2 low, high;
    void add(Vec2 point);
  };
  using Edge = std::pair<Vec2, Vec2>;
  // Whether every point of the box lies strictly behind the edge as seen from `from` (exact).
  static bool box_behind(Vec2 from, const Edge& edge, const Box& box);

 private:
  static Box box_of(const Ring& ring, std::size_t first, std::size_t last);
  static Vec2 least_corner(Vec2 a, Vec2 b, int sign, const Box& box);

  static constexpr std::size_t kRun = 16;
  static constexpr std::size_t kPart = 4;  // a run no single edge hides is tried in parts
  static constexpr std::size_t kEdgesKept = 4;
  const Ring& outer_;
  std::vector<Box> run_boxes_;  // of each run of kRun vertices of ∂P0
  std::vector<Edge> walls_;     // the edges that hid runs, most recent first
};

}  // namespace hullcook::detail
