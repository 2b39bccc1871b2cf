// Internal: which diagonals a region has. A cut of Algorithm 4.2 must be a diagonal: inside the
// region at both ends and meeting no edge between them.
#pragma once

#include "decomposition_types.h"
#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

namespace hullcook::detail {

// A vertex of the region: ring 0 is the outer boundary, ring h + 1 is hole h.
struct VertexRef {
  int ring;
  std::size_t index;
};

// A cut a-b grazes a vertex that lies within twice the sliver width of the open segment,
// 2 sliver_width(|ab|) (see is_sliver in cut.h): cut there, it would leave that vertex on a
// spike of next to no area (near-collinear vertices of different rings, issue 16).
struct Graze {
  Graze(Vec2 from, Vec2 to) : a(from), b(to), along(to - from) {
    squared = along.x * along.x + along.y * along.y;
    const double span = std::sqrt(squared);
    const double width = 2.0 * sliver_width(span);
    grazing = width * span;
    // The segment's box, widened so that it holds the vertices that graze it.
    const double reach = width;
    at_an_end = width * width;
    min_x = std::min(a.x, b.x) - reach, max_x = std::max(a.x, b.x) + reach;
    min_y = std::min(a.y, b.y) - reach, max_y = std::max(a.y, b.y) + reach;
  }
  // c is not an end of the segment. A vertex within the width of an end is at that end, to this
  // resolution, and passing it leaves no sliver: every cut from an end of an edge a few ulps long
  // passed its other end, and the notch was cut along a long edge instead (the fuzzer's
  // rectangle of hexagons, whose needle came out a sliver piece).
  bool by(Vec2 c) const {
    const Vec2 offset = c - a;
    const double projection = offset.x * along.x + offset.y * along.y;
    if (!(projection > 0.0 && projection < squared &&
          std::abs(along.x * offset.y - along.y * offset.x) <= grazing)) {
      return false;
    }
    const Vec2 from_b = c - b;
    return offset.x * offset.x + offset.y * offset.y > at_an_end &&
           from_b.x * from_b.x + from_b.y * from_b.y > at_an_end;
  }
  Vec2 a, b, along;
  double squared, grazing, at_an_end, min_x, max_x, min_y, max_y;
};

class RegionView {
 public:
  explicit RegionView(const Region& region) : region_(region) {}
  const Ring& ring(int r) const {
    return r == 0 ? region_.outer : region_.holes[static_cast<std::size_t>(r - 1)];
  }
  Vec2 at(VertexRef v) const { return ring(v.ring)[v.index]; }
  Vec2 prev(VertexRef v) const {
    const Ring& r = ring(v.ring);
    return r[prev_index(v.index, r.size())];
  }
  Vec2 next(VertexRef v) const {
    const Ring& r = ring(v.ring);
    return r[next_index(v.index, r.size())];
  }
  int ring_count() const { return 1 + static_cast<int>(region_.holes.size()); }

  // The interior angle at a vertex.
  struct Cone {
    Vec2 apex, before, after;
    bool convex;
  };
  Cone cone(VertexRef v) const {
    const Vec2 a = at(v), before = prev(v), after = next(v);
    return {a, before, after, detail::fast_orient2d(a, after, before) >= 0.0};
  }
  // The open segment from the apex toward target leaves it into the interior (O'Rourke's InCone).
  static bool in_cone(const Cone& cone, Vec2 target) {
    const Vec2 a = cone.apex;
    if (cone.convex) {
      return detail::fast_orient2d(a, target, cone.before) > 0.0 &&
             detail::fast_orient2d(target, a, cone.after) > 0.0;
    }
    return !(detail::fast_orient2d(a, target, cone.after) >= 0.0 &&
             detail::fast_orient2d(target, a, cone.before) >= 0.0);
  }
  bool in_cone(VertexRef v, Vec2 target) const { return in_cone(cone(v), target); }

  // u-v is a diagonal: inside at both ends and meeting no other edge, not even at a vertex.
  bool is_diagonal(VertexRef u, VertexRef v) {
    const Vec2 a = at(u), b = at(v);
    // The searches test many diagonals from one vertex.
    if (cone_vertex_.ring != u.ring || cone_vertex_.index != u.index) {
      cone_vertex_ = u;
      cone_of_u_ = cone(u);
    }
    if (a == b || !in_cone(cone_of_u_, b) || !in_cone(v, a)) return false;
    const Sight sight{
        u, v, a, b, std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
    // The edge that blocked the previous candidate often blocks this one too.
    if (last_blocker_.ring >= 0 && blocks(sight, last_blocker_.ring, last_blocker_.index)) {
      return false;
    }
    if (expects_many_tests_) return is_clear_by_index(sight);
    for (int r = 0; r < ring_count(); ++r) {
      for (std::size_t i = 0; i < ring(r).size(); ++i) {
        if (blocks(sight, r, i)) {
          last_blocker_ = {r, static_cast<std::uint32_t>(i)};
          return false;
        }
      }
    }
    return true;
  }

  // An edge of the region, but those at u, that meets the segment from u to target (any point),
  // or none; the search starts at u's end. Builds the grid of edges on first use.
  std::optional<std::pair<Vec2, Vec2>> edge_across(VertexRef u, Vec2 target) {
    if (edge_start_.empty()) index_edges();
    const Vec2 a = at(u);
    const Sight sight{u,
                      {-1, 0},
                      a,
                      target,
                      std::min(a.x, target.x),
                      std::max(a.x, target.x),
                      std::min(a.y, target.y),
                      std::max(a.y, target.y)};
    const std::optional<EdgeRef> edge = grid_blocker(sight);
    if (!edge) return std::nullopt;
    const Ring& points = ring(edge->ring);
    const std::size_t i = edge->index;
    return std::pair{points[i], points[i + 1 == points.size() ? 0 : i + 1]};
  }

  // For views that test many diagonals from a few vertices: caches blockers by direction, and
  // scans the edges until scans are frequent enough to pay for a grid.
  void expect_many_tests() { expects_many_tests_ = true; }

  // Whether the segment a-b grazes a vertex other than its ends (see Graze).
  bool grazes_a_vertex(Vec2 a, Vec2 b) {
    if (chunk_boxes_.empty()) box_chunks();
    const Graze graze(a, b);
    const ChunkBox* box = chunk_boxes_.data();
    for (int r = 0; r < ring_count(); ++r) {
      const Ring& points = ring(r);
      for (std::size_t first = 0; first < points.size(); first += kEdgesPerChunk, ++box) {
        if (box->max_x < graze.min_x || box->min_x > graze.max_x || box->max_y < graze.min_y ||
            box->min_y > graze.max_y) {
          continue;
        }
        const std::size_t last = std::min(first + kEdgesPerChunk, points.size());
        for (std::size_t i = first; i < last; ++i) {
          if (points[i] != a && points[i] != b && graze.by(points[i])) return true;
        }
      }
    }
    return false;
  }

 private:
  // Buckets every edge in a uniform grid.
  void index_edges() {
    std::size_t count = 0;
    for (int r = 0; r < ring_count(); ++r) count += ring(r).size();
    side_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(count))), 1, 512);
    min_x_ = max_x_ = region_.outer[0].x;
    min_y_ = max_y_ = region_.outer[0].y;
    for (Vec2 p : region_.outer) {
      min_x_ = std::min(min_x_, p.x), max_x_ = std::max(max_x_, p.x);
      min_y_ = std::min(min_y_, p.y), max_y_ = std::max(max_y_, p.y);
    }
    scale_x_ = max_x_ > min_x_ ? side_ / (max_x_ - min_x_) : 0.0;
    scale_y_ = max_y_ > min_y_ ? side_ / (max_y_ - min_y_) : 0.0;
    edge_start_.assign(static_cast<std::size_t>(side_ * side_ + 1), 0);
    auto cell_index = [&](int x, int y) { return static_cast<std::size_t>(y * side_ + x); };
    // Each edge's cell range, computed once for both the count and the fill.
    struct CellSpan {
      int x0, x1, y0, y1;
    };
    std::vector<CellSpan> spans;
    spans.reserve(count);
    for (int r = 0; r < ring_count(); ++r) {
      const Ring& points = ring(r);
      // The cells are monotone in the coordinates: an edge spans its end points' cells, each
      // computed once.
      const int first_x = cell_x(points[0].x), first_y = cell_y(points[0].y);
      int x = first_x, y = first_y;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const bool last = i + 1 == points.size();
        const int next_x = last ? first_x : cell_x(points[i + 1].x);
        const int next_y = last ? first_y : cell_y(points[i + 1].y);
        const CellSpan span{std::min(x, next_x), std::max(x, next_x), std::min(y, next_y),
                            std::max(y, next_y)};
        spans.push_back(span);
        for (int row = span.y0; row <= span.y1; ++row) {
          for (int column = span.x0; column <= span.x1; ++column) {
            ++edge_start_[cell_index(column, row) + 1];
          }
        }
        x = next_x, y = next_y;
      }
    }
    for (std::size_t c = 1; c < edge_start_.size(); ++c) edge_start_[c] += edge_start_[c - 1];
    edges_.resize(static_cast<std::size_t>(edge_start_.back()));
    std::vector<int> fill(edge_start_.begin(), edge_start_.end() - 1);
    const CellSpan* span = spans.data();
    for (int r = 0; r < ring_count(); ++r) {
      for (std::size_t i = 0; i < ring(r).size(); ++i, ++span) {
        for (int y = span->y0; y <= span->y1; ++y) {
          for (int x = span->x0; x <= span->x1; ++x) {
            edges_[static_cast<std::size_t>(fill[cell_index(x, y)]++)] = {
                r, static_cast<std::uint32_t>(i)};
          }
        }
      }
    }
  }

  struct EdgeRef {  // 8 bytes: the grid holds a few per edge
    int ring;
    std::uint32_t index;
  };
  // A tested diagonal a-b from u to v, with its box.
  struct Sight {
    VertexRef u, v;
    Vec2 a, b;
    double min_x, max_x, min_y, max_y;
  };
  // Edge i of ring r meets the sight line (edges at its ends do not count).
  [[gnu::always_inline]] bool blocks(const Sight& sight, int r, std::size_t i) const {
    const Ring& points = ring(r);
    const std::size_t j = i + 1 == points.size() ? 0 : i + 1;
    const Vec2 c = points[i], d = points[j];
    if (std::max(c.x, d.x) < sight.min_x || std::min(c.x, d.x) > sight.max_x ||
        std::max(c.y, d.y) < sight.min_y || std::min(c.y, d.y) > sight.max_y) {
      return false;
    }
    auto is = [&](VertexRef w, std::size_t k) { return w.ring == r && w.index == k; };
    if (is(sight.u, i) || is(sight.u, j) || is(sight.v, i) || is(sight.v, j)) return false;
    return segments_intersect(sight.a, sight.b, c, d);
  }

  // is_diagonal's search for a blocking edge in views that expect many tests. Out of line: it
  // would weigh on the inlining of the plain views' scan.
  [[gnu::noinline]] bool is_clear_by_index(const Sight& sight) {
    const Vec2 a = sight.a, b = sight.b;
    const double min_x = sight.min_x, max_x = sight.max_x;
    const double min_y = sight.min_y, max_y = sight.max_y;
    // Sight lines from one vertex in one direction are mostly blocked by the same few edges.
    if (sight_origin_.ring != sight.u.ring || sight_origin_.index != sight.u.index) {
      for (std::vector<EdgeRef>& sector : blockers_by_sector_) sector.clear();
      sight_origin_ = sight.u;
      misses_from_origin_ = 0;
    }
    const std::size_t sector = sector_of(b - a);
    for (const EdgeRef edge : blockers_by_sector_[sector]) {
      if (blocks(sight, edge.ring, edge.index)) {
        last_blocker_ = edge;
        return false;
      }
    }
    // The edges that blocked the sight lines of earlier origins (often the neighbours on the
    // same hole) likely block these too: they are filed as seen from this origin before its
    // second search for a blocker (the first is often the clear sight line of a search that
    // succeeds at once).
    if (++misses_from_origin_ == 2) {
      const std::size_t filed = blockers_by_sector_[sector].size();
      for (const EdgeRef edge : blockers_found_) file_blocker(a, edge);
      const std::vector<EdgeRef>& in_sector = blockers_by_sector_[sector];
      for (std::size_t k = filed; k < in_sector.size(); ++k) {
        if (blocks(sight, in_sector[k].ring, in_sector[k].index)) {
          last_blocker_ = in_sector[k];
          return false;
        }
      }
    }
    if (edge_start_.empty() && ++scans_ > kScansBeforeGrid) index_edges();
    if (edge_start_.empty()) {
      if (chunk_boxes_.empty()) box_chunks();
      const ChunkBox* box = chunk_boxes_.data();
      for (int r = 0; r < ring_count(); ++r) {
        const Ring& points = ring(r);
        const std::size_t n = points.size();
        for (std::size_t first = 0; first < n; first += kEdgesPerChunk, ++box) {
          if (box->max_x < min_x || box->min_x > max_x || box->max_y < min_y ||
              box->min_y > max_y) {
            continue;
          }
          // Each edge's end is the next edge's start: one point loaded per edge.
          const std::size_t last = std::min(first + kEdgesPerChunk, n);
          Vec2 c = points[first];
          for (std::size_t i = first; i < last; ++i) {
            const Vec2 d = points[i + 1 == n ? 0 : i + 1];
            const bool apart = (c.x < min_x && d.x < min_x) || (c.x > max_x && d.x > max_x) ||
                               (c.y < min_y && d.y < min_y) || (c.y > max_y && d.y > max_y);
            c = d;
            if (apart || !blocks(sight, r, i)) continue;
            last_blocker_ = {r, static_cast<std::uint32_t>(i)};
            remember_blocker(a, last_blocker_);
            return false;
          }
        }
      }
      return true;
    }
    if (const std::optional<EdgeRef> edge = grid_blocker(sight)) {
      last_blocker_ = *edge;
      remember_blocker(a, *edge);
      return false;
    }
    return true;
  }

  // The indexed search for an edge that blocks the sight line, from a's cells toward b's.
  std::optional<EdgeRef> grid_blocker(const Sight& sight) const {
    const Vec2 a = sight.a, b = sight.b;
    const double min_x = sight.min_x, max_x = sight.max_x;
    const double min_y = sight.min_y, max_y = sight.max_y;
    // An edge meeting ab at X is stored in X's cell (cells are a monotone function of the
    // coordinates). Each row is scanned over ab's extent in it, widened by half a row and one
    // cell so that rounding cannot leave X's cell out.
    // The cells are visited from a toward b: a hole's candidates are mostly blocked by the
    // holes around it, near a, and the set of cells (so the answer) does not depend on the order.
    const int y0 = cell_y(min_y), y1 = cell_y(max_y);
    const bool rows_down = a.y > b.y, columns_left = a.x > b.x;
    for (int row = 0; row <= y1 - y0; ++row) {
      const int y = rows_down ? y1 - row : y0 + row;
      int x0 = cell_x(min_x), x1 = cell_x(max_x);
      if (y0 < y1 && a.y != b.y) {
        const double low = min_y_ + (y - 0.5) / scale_y_, high = min_y_ + (y + 1.5) / scale_y_;
        auto x_at = [&](double line) {
          const double t = std::clamp((line - a.y) / (b.y - a.y), 0.0, 1.0);
          return a.x + t * (b.x - a.x);
        };
        const double u = x_at(low), w = x_at(high);
        x0 = std::max(x0, cell_x(std::min(u, w)) - 1);
        x1 = std::min(x1, cell_x(std::max(u, w)) + 1);
      }
      for (int column = 0; column <= x1 - x0; ++column) {
        const int x = columns_left ? x1 - column : x0 + column;
        const std::size_t cell = static_cast<std::size_t>(y * side_ + x);
        for (int k = edge_start_[cell]; k < edge_start_[cell + 1]; ++k) {
          const EdgeRef edge = edges_[static_cast<std::size_t>(k)];
          if (blocks(sight, edge.ring, edge.index)) return edge;
        }
      }
    }
    return std::nullopt;
  }

  // The box of every kEdgesPerChunk consecutive edges of each ring, in ring order: a scan for a
  // blocker skips the chunks whose box misses the sight line's.
  static constexpr std::size_t kEdgesPerChunk = 16;
  struct ChunkBox {
    double min_x, max_x, min_y, max_y;
  };
  void box_chunks() {
    for (int r = 0; r < ring_count(); ++r) {
      const Ring& points = ring(r);
      const std::size_t n = points.size();
      for (std::size_t first = 0; first < n; first += kEdgesPerChunk) {
        const std::size_t last = std::min(first + kEdgesPerChunk, n);  // end of the last edge
        const Vec2 end = points[last == n ? 0 : last];
        ChunkBox box{end.x, end.x, end.y, end.y};
        for (std::size_t i = first; i < last; ++i) {
          const Vec2 point = points[i];
          box.min_x = std::min(box.min_x, point.x), box.max_x = std::max(box.max_x, point.x);
          box.min_y = std::min(box.min_y, point.y), box.max_y = std::max(box.max_y, point.y);
        }
        chunk_boxes_.push_back(box);
      }
    }
  }

  // Sectors of directions around a vertex, cut by a pseudo-angle (monotone in the angle, without
  // trigonometry). Their bounds need not be exact: a cached edge is always tested again.
  static constexpr int kSectors = 64;
  static std::size_t sector_of(Vec2 direction) {
    const double sum = std::abs(direction.x) + std::abs(direction.y);
    if (!(sum > 0.0)) return 0;
    const double turn = direction.y / sum;  // in [-1, 1]; with the sign of x, the quadrant
    const double pseudo_angle = direction.x >= 0.0 ? 1.0 + turn : 3.0 - turn;  // in [0, 4]
    const int sector = static_cast<int>(pseudo_angle * (kSectors / 4.0));
    return static_cast<std::size_t>(std::clamp(sector, 0, kSectors - 1));
  }
  // Files an edge that blocked a sight line from origin under every sector its ends span: a
  // segment from origin crossing the edge points between them (the edge spans less than a half
  // turn, so the shorter way round).
  void remember_blocker(Vec2 origin, EdgeRef edge) const {
    if (blockers_found_.size() < kBlockersKept) blockers_found_.push_back(edge);
    file_blocker(origin, edge);
  }
  void file_blocker(Vec2 origin, EdgeRef edge) const {
    const Ring& points = ring(edge.ring);
    const Vec2 c = points[edge.index] - origin;
    const Vec2 d = points[edge.index + 1 == points.size() ? 0 : edge.index + 1] - origin;
    std::size_t from = sector_of(c), to = sector_of(d);
    if (c.x * d.y - c.y * d.x < 0.0) std::swap(from, to);
    for (std::size_t s = from;; s = (s + 1) % kSectors) {
      blockers_by_sector_[s].push_back(edge);
      if (s == to) break;
    }
  }
  int cell_x(double x) const {
    return static_cast<int>(std::clamp((x - min_x_) * scale_x_, 0.0, side_ - 1.0));
  }
  int cell_y(double y) const {
    return static_cast<int>(std::clamp((y - min_y_) * scale_y_, 0.0, side_ - 1.0));
  }
  const Region& region_;
  int side_ = 1;
  double min_x_ = 0.0, max_x_ = 0.0, min_y_ = 0.0, max_y_ = 0.0, scale_x_ = 0.0, scale_y_ = 0.0;
  std::vector<int> edge_start_;  // per cell, its first entry in edges_ (empty: not indexed)
  std::vector<EdgeRef> edges_;
  std::vector<ChunkBox> chunk_boxes_;  // empty: not boxed yet
  bool expects_many_tests_ = false;
  // A chunked scan costs about a thirtieth of building the grid, and most hole resolutions need
  // a handful of scans (on the neuron, 4 instead of 32 here built grids that cost 4 % of SL).
  static constexpr int kScansBeforeGrid = 32;
  int scans_ = 0;
  mutable EdgeRef last_blocker_{-1, 0};
  mutable VertexRef cone_vertex_{-1, 0};  // whose cone cone_of_u_ is
  mutable Cone cone_of_u_{};
  mutable VertexRef sight_origin_{-1, 0};  // where the sight lines of blockers_by_sector_ start
  mutable std::array<std::vector<EdgeRef>, kSectors> blockers_by_sector_;
  static constexpr std::size_t kBlockersKept = 256;
  mutable int misses_from_origin_ = 0;           // of blockers_by_sector_, from sight_origin_
  mutable std::vector<EdgeRef> blockers_found_;  // first kBlockersKept found, from any origin
};

}  // namespace hullcook::detail
