#include "hidden_vertices.h"

#include "predicates_inline.h"

#include <algorithm>

namespace hullcook::detail {

void HiddenVertices::Box::add(Vec2 point) {
  low = {std::min(low.x, point.x), std::min(low.y, point.y)};
  high = {std::max(high.x, point.x), std::max(high.y, point.y)};
}

HiddenVertices::Box HiddenVertices::box_of(const Ring& ring, std::size_t first, std::size_t last) {
  Box box{ring[first], ring[first]};
  for (std::size_t i = first + 1; i < last; ++i) box.add(ring[i]);
  return box;
}

HiddenVertices::HiddenVertices(const Ring& outer) : outer_(outer) {
  run_boxes_.reserve((outer.size() + kRun - 1) / kRun);
  for (std::size_t first = 0; first < outer.size(); first += kRun) {
    run_boxes_.push_back(box_of(outer, first, std::min(first + kRun, outer.size())));
  }
}

// The corner of the box where orient2d(a, b, ·), times sign, is least. orient2d(a, b, p) is, in
// exact arithmetic, affine in p: (a.y - b.y) p.x + (b.x - a.x) p.y + const, and the sign of a
// floating-point difference is exact, so this corner is exactly the least one.
Vec2 HiddenVertices::least_corner(Vec2 a, Vec2 b, int sign, const Box& box) {
  return {sign * (a.y - b.y) > 0 ? box.low.x : box.high.x,
          sign * (b.x - a.x) > 0 ? box.low.y : box.high.y};
}

// Every point of the box lies strictly behind the edge c-d as seen from `from`: strictly beyond
// its line and strictly between the rays through c and d (the corners do, and that open region is
// convex). A segment from `from` to such a point crosses c-d at a point interior to both, and no
// end of c-d is an end of that segment (nor lies on it): c-d blocks it, so it is no diagonal.
// Each of the three strict sides holds at every corner when it holds at the least corner: three
// exact orientations instead of twelve.
bool HiddenVertices::box_behind(Vec2 from, const Edge& edge, const Box& box) {
  const auto [c, d] = edge;
  const int side = fast_orientation(c, d, from);
  if (side == 0) return false;
  return fast_orientation(c, d, least_corner(c, d, -side, box)) == -side &&
         fast_orientation(from, c, least_corner(from, c, side, box)) == side &&
         fast_orientation(from, d, least_corner(from, d, -side, box)) == -side;
}

void HiddenVertices::refuse(RegionView& view, VertexRef from_vertex,
                            std::vector<signed char>& seen) {
  const Vec2 from = view.at(from_vertex);
  // The edge that hid a run likely hides the next, which lies beside it: the edges are tried
  // most recent first.
  auto hidden = [&](const Box& box) {
    const auto wall = std::find_if(walls_.begin(), walls_.end(),
                                   [&](const Edge& edge) { return box_behind(from, edge, box); });
    if (wall == walls_.end()) return false;
    std::rotate(walls_.begin(), wall, wall + 1);
    return true;
  };
  // Else the edge that the sight line to the box's centre meets, found from its start.
  auto hidden_by_a_new_edge = [&](const Box& box) {
    const auto edge = view.edge_across(from_vertex, (box.low + box.high) * 0.5);
    if (!edge) return false;
    if (walls_.size() == kEdgesKept) walls_.pop_back();
    walls_.insert(walls_.begin(), *edge);
    return box_behind(from, *edge, box);
  };
  auto refuse_all = [&](std::size_t first, std::size_t last) {
    std::fill(seen.begin() + static_cast<std::ptrdiff_t>(first),
              seen.begin() + static_cast<std::ptrdiff_t>(last), 0);
  };
  for (std::size_t run = 0; run < run_boxes_.size(); ++run) {
    const std::size_t first = run * kRun, last = std::min(first + kRun, outer_.size());
    bool unknown = false, any_seen = false;
    for (std::size_t i = first; i < last; ++i) {
      unknown |= seen[i] < 0;
      any_seen |= seen[i] == 1;  // then no edge hides the run
    }
    if (!unknown || any_seen) continue;
    if (hidden(run_boxes_[run]) || hidden_by_a_new_edge(run_boxes_[run])) {
      refuse_all(first, last);
      continue;
    }
    for (std::size_t part = first; part < last; part += kPart) {
      const std::size_t end = std::min(part + kPart, last);
      if (hidden(box_of(outer_, part, end))) refuse_all(part, end);
    }
  }
}

}  // namespace hullcook::detail
