#include "triangulate.h"

#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>

namespace hullcook::detail {

namespace {

// Reflex vertices bucketed in a uniform grid of about one cell per point, for box queries.
// Items can be removed (a cell keeps its live items at its front), so that queries never visit
// stale ones. The storage is reused from one polygon to the next.
class ReflexGrid {
 public:
  void reset(const std::vector<Vec2>& points, const std::vector<int>& items) {
    points_ = &points;
    slot_.assign(points.size(), -1);
    items_.resize(items.size());
    if (items.empty()) return;
    min_x_ = max_x_ = points[static_cast<std::size_t>(items[0])].x;
    min_y_ = max_y_ = points[static_cast<std::size_t>(items[0])].y;
    for (int i : items) {
      const Vec2 p = points[static_cast<std::size_t>(i)];
      min_x_ = std::min(min_x_, p.x), max_x_ = std::max(max_x_, p.x);
      min_y_ = std::min(min_y_, p.y), max_y_ = std::max(max_y_, p.y);
    }
    side_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(items.size()))), 1, 1024);
    scale_x_ = max_x_ > min_x_ ? side_ / (max_x_ - min_x_) : 0.0;
    scale_y_ = max_y_ > min_y_ ? side_ / (max_y_ - min_y_) : 0.0;
    const std::size_t cells = static_cast<std::size_t>(side_ * side_);
    begin_.assign(cells + 1, 0);
    for (int i : items) ++begin_[cell_of(i) + 1];
    for (std::size_t c = 1; c <= cells; ++c) begin_[c] += begin_[c - 1];
    end_.assign(begin_.begin(), begin_.end() - 1);
    for (int i : items) {
      const int slot = end_[cell_of(i)]++;
      items_[static_cast<std::size_t>(slot)] = i;
      slot_[static_cast<std::size_t>(i)] = slot;
    }
  }

  void remove(int item) {
    const int slot = slot_[static_cast<std::size_t>(item)];
    if (slot < 0) return;
    const int last = --end_[cell_of(item)];
    const int moved = items_[static_cast<std::size_t>(last)];
    items_[static_cast<std::size_t>(slot)] = moved;
    slot_[static_cast<std::size_t>(moved)] = slot;
    slot_[static_cast<std::size_t>(item)] = -1;
  }

  // True when hit(item) holds for some live item in a cell the box overlaps.
  template <typename Hit>
  bool any_in_box(double min_x, double max_x, double min_y, double max_y, Hit&& hit) const {
    if (items_.empty() || max_x < min_x_ || min_x > max_x_ || max_y < min_y_ || min_y > max_y_) {
      return false;
    }
    const int x0 = cell_x(min_x), x1 = cell_x(max_x), y0 = cell_y(min_y), y1 = cell_y(max_y);
    for (int y = y0; y <= y1; ++y) {
      const std::size_t row = static_cast<std::size_t>(y * side_);
      for (std::size_t c = row + static_cast<std::size_t>(x0);
           c <= row + static_cast<std::size_t>(x1); ++c) {
        for (int k = begin_[c]; k < end_[c]; ++k) {
          if (hit(items_[static_cast<std::size_t>(k)])) return true;
        }
      }
    }
    return false;
  }

 private:
  std::size_t cell_of(int item) const {
    const Vec2 p = (*points_)[static_cast<std::size_t>(item)];
    return static_cast<std::size_t>(cell_y(p.y) * side_ + cell_x(p.x));
  }
  int cell_x(double x) const {
    return static_cast<int>(std::clamp((x - min_x_) * scale_x_, 0.0, side_ - 1.0));
  }
  int cell_y(double y) const {
    return static_cast<int>(std::clamp((y - min_y_) * scale_y_, 0.0, side_ - 1.0));
  }
  const std::vector<Vec2>* points_ = nullptr;
  double min_x_ = 0.0, max_x_ = 0.0, min_y_ = 0.0, max_y_ = 0.0;
  double scale_x_ = 0.0, scale_y_ = 0.0;
  int side_ = 1;
  std::vector<int> begin_, end_;  // per cell: its live items are items_[begin_, end_)
  std::vector<int> items_;
  std::vector<int> slot_;  // per point: its place in items_, or -1
};

// Working storage of the triangulation, kept per thread: a decomposition triangulates hundreds
// of pockets, most of them small, and allocating for each was a tenth of the time.
struct TriangulationScratch {
  std::vector<int> prev, next, owner, reflex_list;
  std::vector<char> reflex;
  ReflexGrid grid;
};

// Below this many reflex vertices an ear test scans them all: cheaper than building a grid.
constexpr std::size_t kGridFromReflexCount = 24;

}  // namespace

void triangulate_by_ear_clipping(const std::vector<Vec2>& polygon,
                                 std::vector<std::array<int, 3>>& triangles,
                                 std::vector<std::array<int, 3>>* neighbours) {
  thread_local TriangulationScratch scratch;
  const int n = static_cast<int>(polygon.size());
  triangles.clear();
  if (neighbours) neighbours->clear();
  if (n < 3) return;
  triangles.reserve(static_cast<std::size_t>(n - 2));
  // The triangle on the inner side of the remaining boundary's edge i -> next[i] (-1: none yet).
  // A clipped ear (a, i, c) meets its neighbours across the edges a -> i and i -> c; its edge
  // c -> a (index 2) becomes the boundary edge a -> c.
  std::vector<int>& owner = scratch.owner;
  if (neighbours) {
    owner.assign(static_cast<std::size_t>(n), -1);
    neighbours->reserve(static_cast<std::size_t>(n - 2));
  }
  auto add_triangle = [&](int a, int b, int c, bool closes) {
    const int t = static_cast<int>(triangles.size());
    triangles.push_back({a, b, c});
    if (!neighbours) return;
    const int across[3] = {owner[static_cast<std::size_t>(a)], owner[static_cast<std::size_t>(b)],
                           closes ? owner[static_cast<std::size_t>(c)] : -1};
    neighbours->push_back({across[0], across[1], across[2]});
    for (int e = 0; e < 3; ++e) {
      if (across[e] >= 0) (*neighbours)[static_cast<std::size_t>(across[e])][2] = t;
    }
    if (!closes) owner[static_cast<std::size_t>(a)] = t;
  };
  std::vector<int>& prev = scratch.prev;
  std::vector<int>& next = scratch.next;
  prev.resize(static_cast<std::size_t>(n));
  next.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    prev[static_cast<std::size_t>(i)] = i - 1;
    next[static_cast<std::size_t>(i)] = i + 1;
  }
  prev[0] = n - 1;
  next[static_cast<std::size_t>(n - 1)] = 0;
  auto at = [&](int i) { return polygon[static_cast<std::size_t>(i)]; };
  auto P = [&](int i) { return prev[static_cast<std::size_t>(i)]; };
  auto N = [&](int i) { return next[static_cast<std::size_t>(i)]; };
  std::vector<char>& reflex = scratch.reflex;
  std::vector<int>& reflex_list = scratch.reflex_list;
  reflex.assign(static_cast<std::size_t>(n), 0);
  reflex_list.clear();
  for (int i = 0; i < n; ++i) {
    if (detail::fast_orient2d(at(P(i)), at(i), at(N(i))) <= 0.0) {
      reflex[static_cast<std::size_t>(i)] = 1;
      reflex_list.push_back(i);
    }
  }
  // Reflex vertices in a uniform grid: an ear test visits only the cells its triangle's box covers.
  // The set only shrinks (clipping never makes a convex vertex reflex), so the grid is built once
  // and a vertex leaves it when it turns convex or is clipped.
  const bool use_grid = reflex_list.size() >= kGridFromReflexCount;
  ReflexGrid& grid = scratch.grid;
  if (use_grid) grid.reset(polygon, reflex_list);
  auto drop_reflex = [&](int i) {
    reflex[static_cast<std::size_t>(i)] = 0;
    if (use_grid) grid.remove(i);
  };
  auto update_reflex = [&](int i) {
    if (detail::fast_orient2d(at(P(i)), at(i), at(N(i))) > 0.0) drop_reflex(i);
  };
  auto is_ear = [&](int i) {
    const int a = P(i), c = N(i);
    if (detail::fast_orient2d(at(a), at(i), at(c)) <= 0.0) return false;
    const Vec2 pa = at(a), pb = at(i), pc = at(c);
    const double min_x = std::min({pa.x, pb.x, pc.x}), max_x = std::max({pa.x, pb.x, pc.x});
    const double min_y = std::min({pa.y, pb.y, pc.y}), max_y = std::max({pa.y, pb.y, pc.y});
    auto inside = [&](int r) {
      if (r == a || r == i || r == c) return false;
      const Vec2 p = at(r);
      if (p.x < min_x || p.x > max_x || p.y < min_y || p.y > max_y) return false;
      return detail::fast_orient2d(pa, pb, p) >= 0.0 && detail::fast_orient2d(pb, pc, p) >= 0.0 &&
             detail::fast_orient2d(pc, pa, p) >= 0.0;
    };
    if (use_grid) return !grid.any_in_box(min_x, max_x, min_y, max_y, inside);
    for (int r : reflex_list) {
      if (reflex[static_cast<std::size_t>(r)] && inside(r)) return false;
    }
    return true;
  };
  int remaining = n;
  int current = 0;
  int since_last_ear = 0;
  while (remaining > 3) {
    const bool degenerate_fallback = since_last_ear > remaining;
    if (is_ear(current) ||
        (degenerate_fallback &&
         detail::fast_orient2d(at(P(current)), at(current), at(N(current))) >= 0.0) ||
        since_last_ear > 2 * remaining) {
      const int a = P(current), c = N(current);
      add_triangle(a, current, c, false);
      if (reflex[static_cast<std::size_t>(current)]) drop_reflex(current);
      next[static_cast<std::size_t>(a)] = c;
      prev[static_cast<std::size_t>(c)] = a;
      --remaining;
      if (reflex[static_cast<std::size_t>(a)]) update_reflex(a);
      if (reflex[static_cast<std::size_t>(c)]) update_reflex(c);
      current = a;
      since_last_ear = 0;
    } else {
      current = N(current);
      ++since_last_ear;
    }
  }
  add_triangle(P(current), current, N(current), true);
}

namespace {

// The sweep runs from top to bottom; a point is above another when it is higher, or as high and
// to the left (a symbolic rotation, so that no two points are at the same height).
bool is_above(Vec2 a, Vec2 b) { return a.y > b.y || (a.y == b.y && a.x < b.x); }

struct SweepEvent {
  Vec2 point;
  int vertex;
};

// The far side of a triangle's edge, as the stack algorithm knows it when it adds the triangle.
struct Slot {
  int triangle;  // >= 0: that triangle, across its edge `edge`; else kPieceEdge or kLater
  int edge;
};
constexpr Slot kPieceEdge{-1, 0};  // an edge of the monotone piece: a polygon edge or a diagonal
constexpr Slot kLater{-2, 0};      // a diagonal whose other triangle comes later

struct MonotoneScratch {
  std::vector<SweepEvent> events, merged;  // vertices from top to bottom, and merge space
  std::vector<std::size_t> run_ends;
  std::vector<int> status;     // left-boundary edges crossing the sweep line, west to east
  std::vector<int> helper;     // per edge i (i -> i + 1): its helper vertex
  std::vector<char> is_merge;  // per vertex
  std::vector<int> fan_start;  // per vertex: its first entry in fan (CSR), fan_start[n] = end
  std::vector<int> fan;        // per vertex: its neighbours ccw from next to prev
  std::vector<std::pair<int, int>> diagonals;
  std::vector<char> used;  // per fan entry: the half-edge has been walked
  std::vector<int> piece, chain_order, stack;
  std::vector<Slot> stack_slot;     // per stack entry: the far side of its edge to the next entry
  std::vector<char> on_left_chain;  // per vertex of the current piece
  // The sweep's diagonals met by one piece's triangle so far, to link with the other piece's:
  // per lower end, a list of (other end, triangle, edge index, next entry).
  std::vector<int> diagonal_head;
  std::vector<std::array<int, 4>> diagonal_sides;
  std::vector<std::array<int, 3>> own_neighbours;  // when the caller wants none
  std::size_t made = 0;                            // triangles so far
};

// Adds the triangles of the polygon piece (vertex indices in ccw order), monotone with respect
// to is_above, from triangles[scratch.made] on, and their neighbours: the triangle across each
// inner edge, as soon as both sides exist. Returns false if the piece is not monotone, or on a
// third triangle at one diagonal.
bool triangulate_monotone_piece(const std::vector<Vec2>& polygon, const std::vector<int>& piece,
                                MonotoneScratch& scratch,
                                std::vector<std::array<int, 3>>& triangles,
                                std::vector<std::array<int, 3>>& neighbours) {
  const std::size_t k = piece.size();
  const int n = static_cast<int>(polygon.size());
  auto at = [&](int v) { return polygon[static_cast<std::size_t>(v)]; };
  bool linked = true;
  auto link = [&](int t, int e, int other, int other_edge) {
    neighbours[static_cast<std::size_t>(t)][static_cast<std::size_t>(e)] = other;
    neighbours[static_cast<std::size_t>(other)][static_cast<std::size_t>(other_edge)] = t;
  };
  // Edge x-y of the piece, side e of triangle t: a polygon edge has no neighbour; a diagonal of
  // the sweep waits for, or meets, the triangle on its other side.
  auto link_piece_edge = [&](int x, int y, int t, int e) {
    if (y == (x + 1 == n ? 0 : x + 1) || x == (y + 1 == n ? 0 : y + 1)) return;
    const int low = std::min(x, y), high = std::max(x, y);
    std::vector<std::array<int, 4>>& sides = scratch.diagonal_sides;
    int& head = scratch.diagonal_head[static_cast<std::size_t>(low)];
    for (int i = head; i >= 0; i = sides[static_cast<std::size_t>(i)][3]) {
      std::array<int, 4>& side = sides[static_cast<std::size_t>(i)];
      if (side[0] != high) continue;
      if (side[1] < 0) {
        linked = false;  // a third triangle
      } else {
        link(t, e, side[1], side[2]);
        side[1] = -1;
      }
      return;
    }
    sides.push_back({high, t, e, head});
    head = static_cast<int>(sides.size()) - 1;
  };
  auto meet = [&](Slot far, int x, int y, int t, int e) {
    if (far.triangle >= 0) {
      link(t, e, far.triangle, far.edge);
    } else if (far.triangle == kPieceEdge.triangle) {
      link_piece_edge(x, y, t, e);
    }
  };
  // Adds the triangle a, b, c (as a, c, b when turned, so counter-clockwise) whose edges ab, bc
  // and ca have the given far sides. Returns the slot of its edge ca, for the triangle across it.
  auto add_turned = [&](bool turned, int a, int b, int c, Slot ab, Slot bc, Slot ca)
      __attribute__((always_inline)) {
    if (scratch.made == triangles.size()) {  // more than n - 2: not a simple polygon
      linked = false;
      return kLater;
    }
    const int t = static_cast<int>(scratch.made++);
    triangles[static_cast<std::size_t>(t)] =
        turned ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c};
    const int edge_ab = turned ? 2 : 0, edge_ca = turned ? 0 : 2;
    meet(ab, a, b, t, edge_ab);
    meet(bc, b, c, t, 1);
    meet(ca, c, a, t, edge_ca);
    return Slot{t, edge_ca};
  };
  auto add = [&](int a, int b, int c, Slot ab, Slot bc, Slot ca) {
    return add_turned(detail::fast_orient2d(at(a), at(b), at(c)) < 0.0, a, b, c, ab, bc, ca);
  };
  if (k == 3) {
    add(piece[0], piece[1], piece[2], kPieceEdge, kPieceEdge, kPieceEdge);
    return linked;
  }
  std::size_t top = 0, bottom = 0;
  for (std::size_t i = 1; i < k; ++i) {
    if (is_above(at(piece[i]), at(piece[top]))) top = i;
    if (is_above(at(piece[bottom]), at(piece[i]))) bottom = i;
  }
  // Going ccw from the top runs down the left chain (the interior is to its east), then up the
  // right chain. Merge the chains from top to bottom.
  std::vector<int>& sorted = scratch.chain_order;
  std::vector<char>& left = scratch.on_left_chain;
  sorted.resize(k);
  left.resize(k);
  std::size_t merged = 0;
  auto emit = [&](std::size_t i, char on_left) {
    sorted[merged] = piece[i];
    left[merged++] = on_left;
  };
  auto step = [&](std::size_t i, bool forward) {
    return forward ? (i + 1 == k ? 0 : i + 1) : (i == 0 ? k - 1 : i - 1);
  };
  emit(top, 1);
  std::size_t down = step(top, true), up = step(top, false);  // next of each chain
  while (down != bottom || up != bottom) {
    if (down != bottom && (up == bottom || is_above(at(piece[down]), at(piece[up])))) {
      emit(down, 1);
      down = step(down, true);
    } else {
      emit(up, 0);
      up = step(up, false);
    }
  }
  emit(bottom, 1);
  for (std::size_t i = 1; i < k; ++i) {
    if (!is_above(at(sorted[i - 1]), at(sorted[i]))) return false;  // not monotone
  }
  // The stack holds positions in sorted. The vertex at its bottom is joined to the next vertex
  // along the piece's boundary, and each entry to the next by a piece edge or an added diagonal,
  // whose far side stack_slot keeps.
  std::vector<int>& stack = scratch.stack;
  std::vector<Slot>& stack_slot = scratch.stack_slot;
  stack.clear();
  stack.push_back(0);
  stack.push_back(1);
  stack_slot.resize(k);
  stack_slot[0] = kPieceEdge;
  auto at_stack = [&](std::size_t i) { return sorted[static_cast<std::size_t>(stack[i])]; };
  // Joins u to every stack entry; its edges to the first and (when last_is_piece_edge) the last
  // are piece edges. Returns the slot of the last diagonal.
  auto fan_to_stack = [&](int u, bool last_is_piece_edge) {
    Slot carry = kPieceEdge;
    for (std::size_t i = 0; i + 1 < stack.size(); ++i) {
      const bool last = i + 2 == stack.size();
      carry = add(u, at_stack(i), at_stack(i + 1), carry, stack_slot[i],
                  last && last_is_piece_edge ? kPieceEdge : kLater);
    }
    return carry;
  };
  for (std::size_t j = 2; j + 1 < k; ++j) {
    const int u = sorted[j];
    const int top_position = stack.back();
    if (left[j] != left[static_cast<std::size_t>(top_position)]) {
      const Slot joined = fan_to_stack(u, false);
      stack.clear();
      stack.push_back(static_cast<int>(j - 1));
      stack.push_back(static_cast<int>(j));
      stack_slot[0] = joined;
    } else {
      int last = stack.back();
      stack.pop_back();
      Slot carry = kPieceEdge;  // u - last: the edge along u's chain, then the last diagonal
      while (!stack.empty()) {
        const Vec2 s = at(sorted[static_cast<std::size_t>(stack.back())]);
        const Vec2 l = at(sorted[static_cast<std::size_t>(last)]);
        // The diagonal u-s is inside when the chain bulges into the interior at l.
        const double side = detail::fast_orient2d(s, at(u), l);
        if (left[j] ? side >= 0.0 : side <= 0.0) break;
        // u, l, s turn as the side found (exact signs): clockwise on the left chain.
        carry = add_turned(left[j] != 0, u, sorted[static_cast<std::size_t>(last)],
                           sorted[static_cast<std::size_t>(stack.back())], carry,
                           stack_slot[stack.size() - 1], kLater);
        last = stack.back();
        stack.pop_back();
      }
      stack.push_back(last);
      stack_slot[stack.size() - 1] = carry;
      stack.push_back(static_cast<int>(j));
    }
  }
  fan_to_stack(sorted[k - 1], true);
  return linked;
}

// The vertices from top to bottom. A boundary runs up and down in long stretches: the sort
// merges those runs, O(n log r) for r runs, instead of sorting from scratch.
void sort_from_top(const std::vector<Vec2>& polygon, std::vector<SweepEvent>& events,
                   std::vector<SweepEvent>& merged, std::vector<std::size_t>& run_ends) {
  const std::size_t n = polygon.size();
  events.resize(n);
  for (std::size_t i = 0; i < n; ++i) events[i] = {polygon[i], static_cast<int>(i)};
  auto before = [](const SweepEvent& a, const SweepEvent& b) { return is_above(a.point, b.point); };
  run_ends.clear();
  for (std::size_t start = 0; start < n;) {
    std::size_t end = start + 1;
    if (end < n && before(events[end], events[start])) {
      while (end < n && before(events[end], events[end - 1])) ++end;
      std::reverse(events.begin() + std::ptrdiff_t(start), events.begin() + std::ptrdiff_t(end));
    } else {
      while (end < n && !before(events[end], events[end - 1])) ++end;
    }
    run_ends.push_back(end);
    start = end;
  }
  merged.resize(n);
  while (run_ends.size() > 1) {
    std::size_t kept = 0, start = 0;
    for (std::size_t r = 0; r < run_ends.size(); r += 2) {
      const std::size_t middle = run_ends[r];
      const std::size_t end = r + 1 < run_ends.size() ? run_ends[r + 1] : middle;
      std::merge(events.begin() + std::ptrdiff_t(start), events.begin() + std::ptrdiff_t(middle),
                 events.begin() + std::ptrdiff_t(middle), events.begin() + std::ptrdiff_t(end),
                 merged.begin() + std::ptrdiff_t(start), before);
      run_ends[kept++] = end;
      start = end;
    }
    run_ends.resize(kept);
    events.swap(merged);
  }
}

// The sweep of de Berg et al. (Computational Geometry, ch. 3) adds diagonals at split and merge
// vertices; the faces are then monotone pieces. Fills triangles and neighbours, or returns false
// (both unspecified) on input the sweep does not handle: repeated points, or a ring that is not
// simple.
bool sweep_into_monotone_triangles(const std::vector<Vec2>& polygon,
                                   std::vector<std::array<int, 3>>& triangles,
                                   std::vector<std::array<int, 3>>& neighbours,
                                   MonotoneScratch& scratch) {
  const int n = static_cast<int>(polygon.size());
  auto at = [&](int v) { return polygon[static_cast<std::size_t>(v)]; };
  auto next = [&](int v) { return v + 1 == n ? 0 : v + 1; };
  auto prev = [&](int v) { return v == 0 ? n - 1 : v - 1; };
  // The n - 2 triangles of a simple polygon, filled in as they are made.
  triangles.resize(static_cast<std::size_t>(n - 2));
  neighbours.assign(static_cast<std::size_t>(n - 2), {-1, -1, -1});
  scratch.made = 0;
  const auto all_made = [&] { return scratch.made == static_cast<std::size_t>(n - 2); };
  std::vector<int>& piece = scratch.piece;
  // A ring that runs down once and up once is monotone already: no sweep, no sort.
  int turns = 0;
  for (int v = 0, going_down = is_above(at(n - 1), at(0)); v < n; ++v) {
    const bool down = is_above(at(v), at(next(v)));
    turns += down != going_down;
    going_down = down;
  }
  if (turns == 2) {
    piece.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) piece[static_cast<std::size_t>(i)] = i;
    return triangulate_monotone_piece(polygon, piece, scratch, triangles, neighbours) && all_made();
  }
  std::vector<SweepEvent>& events = scratch.events;
  sort_from_top(polygon, events, scratch.merged, scratch.run_ends);
  for (std::size_t i = 1; i < events.size(); ++i) {
    if (events[i - 1].point == events[i].point) return false;
  }
  std::vector<int>& status = scratch.status;
  std::vector<int>& helper = scratch.helper;
  std::vector<char>& is_merge = scratch.is_merge;
  std::vector<std::pair<int, int>>& diagonals = scratch.diagonals;
  status.clear();
  diagonals.clear();
  helper.assign(static_cast<std::size_t>(n), -1);
  is_merge.assign(static_cast<std::size_t>(n), 0);
  // Status edges are left-boundary edges i -> i + 1, which run downward with the interior east.
  // v is east of edge e when it is left of the downward e.
  auto east_of = [&](int v, int e) {
    return detail::fast_orient2d(at(e), at(next(e)), at(v)) > 0.0;
  };
  auto position_west_of = [&](int v) {  // the number of status edges west of v
    return static_cast<std::size_t>(
        std::partition_point(status.begin(), status.end(), [&](int e) { return east_of(v, e); }) -
        status.begin());
  };
  auto insert_edge = [&](int e) {
    status.insert(status.begin() + static_cast<std::ptrdiff_t>(position_west_of(e)), e);
    helper[static_cast<std::size_t>(e)] = e;
  };
  auto remove_edge = [&](int e) {
    const auto found = std::find(status.begin(), status.end(), e);
    if (found == status.end()) return false;
    status.erase(found);
    return true;
  };
  auto edge_west_of = [&](int v) {  // the status edge directly west of v, or -1
    const std::size_t count = position_west_of(v);
    return count == 0 ? -1 : status[count - 1];
  };
  auto connect_merge_helper = [&](int v, int e) {
    const int h = helper[static_cast<std::size_t>(e)];
    if (h >= 0 && is_merge[static_cast<std::size_t>(h)]) diagonals.emplace_back(v, h);
  };
  for (const SweepEvent& event : events) {
    const int v = event.vertex;
    const int before = prev(v), after = next(v);
    const bool before_below = is_above(at(v), at(before));
    const bool after_below = is_above(at(v), at(after));
    const bool convex = detail::fast_orient2d(at(before), at(v), at(after)) > 0.0;
    if (before_below && after_below) {
      if (convex) {  // start
        insert_edge(v);
      } else {  // split
        const int e = edge_west_of(v);
        if (e < 0) return false;
        diagonals.emplace_back(v, helper[static_cast<std::size_t>(e)]);
        helper[static_cast<std::size_t>(e)] = v;
        insert_edge(v);
      }
    } else if (!before_below && !after_below) {
      connect_merge_helper(v, before);
      if (!remove_edge(before)) return false;
      if (!convex) {  // merge
        is_merge[static_cast<std::size_t>(v)] = 1;
        const int e = edge_west_of(v);
        if (e < 0) return false;
        connect_merge_helper(v, e);
        helper[static_cast<std::size_t>(e)] = v;
      }
    } else if (after_below) {  // on the left boundary: the interior is east
      connect_merge_helper(v, before);
      if (!remove_edge(before)) return false;
      insert_edge(v);
    } else {
      const int e = edge_west_of(v);
      if (e < 0) return false;
      connect_merge_helper(v, e);
      helper[static_cast<std::size_t>(e)] = v;
    }
  }
  if (diagonals.empty()) {
    piece.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) piece[static_cast<std::size_t>(i)] = i;
    return triangulate_monotone_piece(polygon, piece, scratch, triangles, neighbours) && all_made();
  }
  scratch.diagonal_head.assign(static_cast<std::size_t>(n), -1);
  scratch.diagonal_sides.clear();
  // Around each vertex, its neighbours ccw from next to prev (the diagonals lie in between), as
  // a compressed table. The pieces are the faces: arriving at v from u, a face goes on to the
  // neighbour just clockwise of u.
  std::vector<int>& fan_start = scratch.fan_start;
  std::vector<int>& fan = scratch.fan;
  fan_start.assign(static_cast<std::size_t>(n) + 1, 2);
  fan_start[0] = 0;
  for (const auto& [a, b] : diagonals) {
    ++fan_start[static_cast<std::size_t>(a) + 1];
    ++fan_start[static_cast<std::size_t>(b) + 1];
  }
  for (int i = 0; i < n; ++i)
    fan_start[static_cast<std::size_t>(i) + 1] += fan_start[static_cast<std::size_t>(i)];
  fan.assign(static_cast<std::size_t>(fan_start[static_cast<std::size_t>(n)]), -1);
  std::vector<int>& fill = scratch.stack;
  fill.assign(fan_start.begin(), fan_start.end() - 1);
  for (int v = 0; v < n; ++v)
    fan[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = next(v);
  for (const auto& [a, b] : diagonals) {
    fan[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
    fan[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
  }
  for (int v = 0; v < n; ++v) {
    fan[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = prev(v);
    const auto first = fan.begin() + fan_start[static_cast<std::size_t>(v)];
    const auto last = fan.begin() + fan_start[static_cast<std::size_t>(v) + 1];
    if (last - first == 2) continue;
    // Angles ccw from the direction to next(v), all within the interior angle.
    const Vec2 origin = at(v), reference = at(next(v));
    auto half = [&](int w) {
      const double side = detail::fast_orient2d(origin, reference, at(w));
      if (side != 0.0) return side > 0.0 ? 0 : 1;
      const Vec2 d = at(w) - origin, r = reference - origin;
      return d.x * r.x + d.y * r.y > 0 ? 0 : 1;
    };
    std::sort(first + 1, last - 1, [&](int a, int b) {
      const int ha = half(a), hb = half(b);
      if (ha != hb) return ha < hb;
      return detail::fast_orient2d(origin, at(a), at(b)) > 0.0;
    });
  }
  auto fan_index = [&](int v, int w) {  // w's entry in v's fan
    for (int i = fan_start[static_cast<std::size_t>(v)];
         i < fan_start[static_cast<std::size_t>(v) + 1]; ++i) {
      if (fan[static_cast<std::size_t>(i)] == w) return i;
    }
    return -1;
  };
  std::vector<char>& used = scratch.used;
  used.assign(fan.size(), 0);
  std::size_t walked = 0;
  for (int v0 = 0; v0 < n; ++v0) {
    // Every half-edge but v -> prev(v) (the outside) bounds one piece on its left.
    for (int i = fan_start[static_cast<std::size_t>(v0)];
         i + 1 < fan_start[static_cast<std::size_t>(v0) + 1]; ++i) {
      if (used[static_cast<std::size_t>(i)]) continue;
      piece.clear();
      int u = v0, entry = i;
      while (!used[static_cast<std::size_t>(entry)]) {
        used[static_cast<std::size_t>(entry)] = 1;
        piece.push_back(u);
        const int w = fan[static_cast<std::size_t>(entry)];
        const int back = fan_index(w, u);
        if (back < 0 || back == fan_start[static_cast<std::size_t>(w)]) return false;
        entry = back - 1;  // clockwise of u around w
        u = w;
        if (piece.size() > static_cast<std::size_t>(n)) return false;
      }
      if (u != v0 || piece.size() < 3) return false;
      walked += piece.size();
      if (!triangulate_monotone_piece(polygon, piece, scratch, triangles, neighbours)) {
        return false;
      }
    }
  }
  return walked == static_cast<std::size_t>(n) + 2 * diagonals.size() && all_made();
}

}  // namespace

bool triangulate_by_sweep(const std::vector<Vec2>& polygon,
                          std::vector<std::array<int, 3>>& triangles,
                          std::vector<std::array<int, 3>>* neighbours) {
  thread_local MonotoneScratch scratch;
  const int n = static_cast<int>(polygon.size());
  triangles.clear();
  if (neighbours) neighbours->clear();
  if (n < 3) return true;
  if (n == 3) {
    triangles.push_back({0, 1, 2});
    if (neighbours) neighbours->push_back({-1, -1, -1});
    return true;
  }
  return sweep_into_monotone_triangles(polygon, triangles,
                                       neighbours ? *neighbours : scratch.own_neighbours, scratch);
}

constexpr std::size_t kEarClippingBelow = 32;

void triangulate(const std::vector<Vec2>& polygon, std::vector<std::array<int, 3>>& triangles,
                 std::vector<std::array<int, 3>>* neighbours) {
  // Small polygons (most pockets, and the parts the shortest paths cut them into) clip faster
  // than the sweep sorts and builds its status: on the neuron's parts of 12 to 31 vertices, a
  // quarter fewer cycles; from 32 on, the sweep is as fast or faster.
  if (polygon.size() < kEarClippingBelow) {
    triangulate_by_ear_clipping(polygon, triangles, neighbours);
    return;
  }
  if (!triangulate_by_sweep(polygon, triangles, neighbours)) {
    triangulate_by_ear_clipping(polygon, triangles, neighbours);
  }
}

}  // namespace hullcook::detail
