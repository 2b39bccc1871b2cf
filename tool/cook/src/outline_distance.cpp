#include "outline_distance.h"

#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace hullcook::detail {
OutlineDistance::OutlineDistance(const std::vector<Region>& outline) : outline_(outline) {
  Vec2 low{0.0, 0.0}, high{0.0, 0.0};
  auto add_ring = [&](const Ring& ring) {
    const std::size_t first = edges_.size(), n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = ring[i];
      if (edges_.empty()) low = high = a;
      low = glm::min(low, a), high = glm::max(high, a);
      edges_.push_back({a, ring[(i + 1) % n], first + (i + n - 1) % n, first + (i + 1) % n});
    }
  };
  for (const Region& region : outline) {
    add_ring(region.outer);
    for (const Ring& hole : region.holes) add_ring(hole);
  }
  if (edges_.empty()) return;
  grid_ = CellGrid(low, high, edges_.size());
  // A margin of a millionth of a cell makes the cells a superset of those an edge meets, whatever
  // the rounding of the band limits.
  const double margin = grid_.cell_size() * 1e-6;
  buckets_ = CellBuckets(grid_.cells(), edges_.size(), [&](std::size_t e, auto&& add) {
    grid_.for_each_cell(edges_[e].a, edges_[e].b, margin, add);
  });

  // The side of each cell without edges is that of its centre: the parity of the edges crossing
  // its row's centre line to the left of it. No edge comes near such a cell, so no crossing
  // falls inside it.
  const int rows = grid_.rows(), columns = grid_.columns();
  const double size = grid_.cell_size();
  std::vector<std::pair<int, double>> crossings;  // (row, x)
  for (const Edge& e : edges_) {
    const double y_low = std::min(e.a.y, e.b.y), y_high = std::max(e.a.y, e.b.y);
    const int first = std::max(0, static_cast<int>(std::ceil((y_low - low.y) / size - 0.5)) - 1);
    const int last =
        std::min(rows - 1, static_cast<int>(std::floor((y_high - low.y) / size - 0.5)) + 1);
    for (int r = first; r <= last; ++r) {
      const double y = low.y + (r + 0.5) * size;
      if ((e.a.y > y) == (e.b.y > y)) continue;
      crossings.emplace_back(r, e.a.x + (y - e.a.y) / (e.b.y - e.a.y) * (e.b.x - e.a.x));
    }
  }
  std::sort(crossings.begin(), crossings.end());
  empty_cell_side_.assign(grid_.cells(), 0);
  std::size_t next = 0;
  for (int r = 0; r < rows; ++r) {
    std::size_t left = 0;  // crossings of row r left of the cell's centre
    for (int c = 0; c < columns; ++c) {
      const double x = low.x + (c + 0.5) * size;
      for (; next < crossings.size() && crossings[next].first == r && crossings[next].second < x;
           ++next) {
        ++left;
      }
      const std::size_t cell = grid_.cell(c, r);
      if (buckets_.empty(cell)) empty_cell_side_[cell] = left % 2 ? -1 : 1;
    }
    while (next < crossings.size() && crossings[next].first == r) ++next;
  }
}

int OutlineDistance::side_at_nearest_point(Vec2 p, std::size_t edge, double along) const {
  const Edge& e = edges_[edge];
  if (along > 0.0 && along < 1.0) return -orientation(e.a, e.b, p);
  // The nearest point is a vertex: the open segment from p to it meets no edge, so p lies on the
  // side that the two edges at the vertex give the directions around it.
  const Vec2 before = along == 0.0 ? edges_[e.previous].a : e.a;
  const Vec2 vertex = along == 0.0 ? e.a : e.b;
  const Vec2 after = along == 0.0 ? e.b : edges_[e.next].b;
  if (p == vertex) return 0;
  const bool left_of_in = orientation(before, vertex, p) > 0;
  const bool left_of_out = orientation(vertex, after, p) > 0;
  const bool convex = orientation(before, vertex, after) > 0;
  const bool inside = convex ? left_of_in && left_of_out : left_of_in || left_of_out;
  return inside ? -1 : 1;
}

OutlineDistance::Nearest OutlineDistance::nearest(Vec2 p, double reach) const {
  if (edges_.empty()) return {std::numeric_limits<double>::infinity(), kNoEdge};
  const int columns = grid_.columns(), rows = grid_.rows();
  const int cx = grid_.column(p.x), cy = grid_.row(p.y);
  const double size = grid_.cell_size();
  const Vec2 low = grid_.low();
  double best = std::numeric_limits<double>::infinity(), best_along = 0.0;
  std::size_t best_edge = kNoEdge;
  auto visit = [&](int c, int r) {
    const std::size_t cell = grid_.cell(c, r);
    for (const std::size_t* e = buckets_.begin(cell); e != buckets_.end(cell); ++e) {
      const SegmentProjection projection = project_on_segment(p, edges_[*e].a, edges_[*e].b);
      if (projection.distance < best) {
        best = projection.distance, best_along = projection.along, best_edge = *e;
      }
    }
  };
  for (int k = 0;; ++k) {
    // The ring of cells k away from p's cell, within the grid.
    const int c0 = cx - k, c1 = cx + k, r0 = cy - k, r1 = cy + k;
    const int c_first = std::max(c0, 0), c_last = std::min(c1, columns - 1);
    if (k == 0) {
      visit(cx, cy);
    } else {
      for (int c = c_first; c <= c_last; ++c) {
        if (r0 >= 0) visit(c, r0);
        if (r1 < rows) visit(c, r1);
      }
      for (int r = std::max(r0 + 1, 0); r <= std::min(r1 - 1, rows - 1); ++r) {
        if (c0 >= 0) visit(c0, r);
        if (c1 < columns) visit(c1, r);
      }
    }
    // No cell beyond the ring is nearer to p than this.
    double beyond = std::numeric_limits<double>::infinity();
    if (c0 > 0) beyond = std::min(beyond, p.x - (low.x + c0 * size));
    if (c1 < columns - 1) beyond = std::min(beyond, low.x + (c1 + 1) * size - p.x);
    if (r0 > 0) beyond = std::min(beyond, p.y - (low.y + r0 * size));
    if (r1 < rows - 1) beyond = std::min(beyond, low.y + (r1 + 1) * size - p.y);
    if (best <= beyond) break;
    if (best_edge == kNoEdge && beyond >= reach) {
      // p's own cell has no edge: its side is the cell's (outside when p is beyond the grid).
      const bool in_grid = p.x >= low.x && p.x <= low.x + columns * size && p.y >= low.y &&
                           p.y <= low.y + rows * size;
      const int side = in_grid ? empty_cell_side_[grid_.cell(cx, cy)] : 1;
      return {side * beyond, kNoEdge};
    }
  }
  return {side_at_nearest_point(p, best_edge, best_along) * best, best_edge};
}

double OutlineDistance::distance_to_edge(Vec2 p, std::size_t edge) const {
  return point_segment_distance(p, edges_[edge].a, edges_[edge].b);
}

double OutlineDistance::distance_by_scan(Vec2 p) const {
  for (const Region& region : outline_) {
    if (locate_point(region, p) != Location::outside) return 0.0;
  }
  double best = std::numeric_limits<double>::infinity();
  for (const Edge& e : edges_) best = std::min(best, point_segment_distance(p, e.a, e.b));
  return best;
}

}  // namespace hullcook::detail
