#include "pocket_paths.h"

#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hullcook::detail {

namespace {

// Points bucketed in a uniform grid of about one cell per point (compressed rows), for box queries.
class ReflexGrid {
 public:
  ReflexGrid(const std::vector<Vec2>& points, const std::vector<int>& items) {
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
    start_.assign(static_cast<std::size_t>(side_ * side_ + 1), 0);
    std::vector<int> cell_of(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) {
      const Vec2 p = points[static_cast<std::size_t>(items[k])];
      cell_of[k] = cell_y(p.y) * side_ + cell_x(p.x);
      ++start_[static_cast<std::size_t>(cell_of[k]) + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(items.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < items.size(); ++k) {
      items_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_of[k])]++)] = items[k];
    }
  }

  // True when hit(item) holds for some item in a cell overlapping the box.
  template <typename Hit>
  bool any_in_box(double min_x, double max_x, double min_y, double max_y, Hit&& hit) const {
    if (items_.empty() || max_x < min_x_ || min_x > max_x_ || max_y < min_y_ || min_y > max_y_) {
      return false;
    }
    const int x0 = cell_x(min_x), x1 = cell_x(max_x), y0 = cell_y(min_y), y1 = cell_y(max_y);
    for (int y = y0; y <= y1; ++y) {
      const std::size_t row = static_cast<std::size_t>(y * side_);
      const int begin = start_[row + static_cast<std::size_t>(x0)];
      const int end = start_[row + static_cast<std::size_t>(x1) + 1];
      for (int k = begin; k < end; ++k) {
        if (hit(items_[static_cast<std::size_t>(k)])) return true;
      }
    }
    return false;
  }

 private:
  int cell_x(double x) const {
    return static_cast<int>(std::clamp((x - min_x_) * scale_x_, 0.0, side_ - 1.0));
  }
  int cell_y(double y) const {
    return static_cast<int>(std::clamp((y - min_y_) * scale_y_, 0.0, side_ - 1.0));
  }
  double min_x_ = 0.0, max_x_ = 0.0, min_y_ = 0.0, max_y_ = 0.0;
  double scale_x_ = 0.0, scale_y_ = 0.0;
  int side_ = 1;
  std::vector<int> start_;
  std::vector<int> items_;
};

}  // namespace

std::vector<std::array<int, 3>> triangulate(const std::vector<Vec2>& polygon,
                                            std::vector<std::array<int, 3>>* neighbours) {
  const int n = static_cast<int>(polygon.size());
  std::vector<std::array<int, 3>> triangles;
  if (neighbours) neighbours->clear();
  if (n < 3) return triangles;
  triangles.reserve(static_cast<std::size_t>(n - 2));
  // The triangle on the inner side of the remaining boundary's edge i -> next[i] (-1: none yet).
  // A clipped ear (a, i, c) meets its neighbours across the edges a -> i and i -> c; its edge
  // c -> a (index 2) becomes the boundary edge a -> c.
  std::vector<int> owner;
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
  std::vector<int> prev(static_cast<std::size_t>(n)), next(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    prev[static_cast<std::size_t>(i)] = (i + n - 1) % n;
    next[static_cast<std::size_t>(i)] = (i + 1) % n;
  }
  auto at = [&](int i) { return polygon[static_cast<std::size_t>(i)]; };
  auto P = [&](int i) { return prev[static_cast<std::size_t>(i)]; };
  auto N = [&](int i) { return next[static_cast<std::size_t>(i)]; };
  std::vector<char> reflex(static_cast<std::size_t>(n), 0), removed(static_cast<std::size_t>(n), 0);
  std::vector<int> reflex_list;
  auto update_reflex = [&](int i) {
    const bool is_reflex = detail::fast_orientation(at(P(i)), at(i), at(N(i))) <= 0;
    if (is_reflex && !reflex[static_cast<std::size_t>(i)]) reflex_list.push_back(i);
    reflex[static_cast<std::size_t>(i)] = is_reflex;
  };
  for (int i = 0; i < n; ++i) update_reflex(i);
  // Reflex vertices in a uniform grid: an ear test visits only the cells its triangle's box
  // covers. The set only shrinks (clipping never makes a convex vertex reflex), so the grid is
  // built once and stale entries are skipped.
  const ReflexGrid grid(polygon, reflex_list);
  auto is_ear = [&](int i) {
    const int a = P(i), c = N(i);
    if (detail::fast_orientation(at(a), at(i), at(c)) <= 0) return false;
    const Vec2 pa = at(a), pb = at(i), pc = at(c);
    const double min_x = std::min({pa.x, pb.x, pc.x}), max_x = std::max({pa.x, pb.x, pc.x});
    const double min_y = std::min({pa.y, pb.y, pc.y}), max_y = std::max({pa.y, pb.y, pc.y});
    return !grid.any_in_box(min_x, max_x, min_y, max_y, [&](int r) {
      if (!reflex[static_cast<std::size_t>(r)] || removed[static_cast<std::size_t>(r)])
        return false;
      if (r == a || r == i || r == c) return false;
      const Vec2 p = at(r);
      if (p.x < min_x || p.x > max_x || p.y < min_y || p.y > max_y) return false;
      return detail::fast_orientation(pa, pb, p) >= 0 && detail::fast_orientation(pb, pc, p) >= 0 &&
             detail::fast_orientation(pc, pa, p) >= 0;
    });
  };
  int remaining = n;
  int current = 0;
  int since_last_ear = 0;
  while (remaining > 3) {
    const bool degenerate_fallback = since_last_ear > remaining;
    if (is_ear(current) ||
        (degenerate_fallback &&
         detail::fast_orientation(at(P(current)), at(current), at(N(current))) >= 0) ||
        since_last_ear > 2 * remaining) {
      const int a = P(current), c = N(current);
      add_triangle(a, current, c, false);
      removed[static_cast<std::size_t>(current)] = 1;
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
  return triangles;
}

std::vector<double> shortest_paths_to_bridge(const std::vector<Vec2>& q) {
  const int m = static_cast<int>(q.size()) - 1;
  std::vector<double> distance(q.size(), 0.0);
  if (m < 2) return distance;
  const Vec2 s = q.front();
  const Vec2 t = q.back();
  const Vec2 along = t - s;
  const double length = std::hypot(along.x, along.y);
  const Vec2 normal{-along.y / length, along.x / length};  // into the pocket

  // The pocket polygon q[0..m] runs clockwise; triangulate it reversed (counter-clockwise).
  std::vector<Vec2> ccw(q.rbegin(), q.rend());
  std::vector<std::array<int, 3>> across;
  std::vector<std::array<int, 3>> triangles = triangulate(ccw, &across);
  for (auto& triangle : triangles) {
    for (int& v : triangle) v = m - v;
  }
  auto neighbour = [&](int triangle, int u, int v) {
    const auto& tri = triangles[static_cast<std::size_t>(triangle)];
    for (int e = 0; e < 3; ++e) {
      const int x = tri[static_cast<std::size_t>(e)],
                y = tri[static_cast<std::size_t>((e + 1) % 3)];
      if ((x == u && y == v) || (x == v && y == u)) {
        return across[static_cast<std::size_t>(triangle)][static_cast<std::size_t>(e)];
      }
    }
    return -1;
  };
  int root = -1;
  for (std::size_t i = 0; i < triangles.size() && root < 0; ++i) {
    const auto& tri = triangles[i];
    const bool has_s = tri[0] == 0 || tri[1] == 0 || tri[2] == 0;
    const bool has_t = tri[0] == m || tri[1] == m || tri[2] == m;
    if (has_s && has_t) root = static_cast<int>(i);
  }
  if (root < 0) return distance;

  constexpr int kInfinity = -1;  // the bridge seen as a source at infinity below it
  auto point = [&](int v) { return q[static_cast<std::size_t>(v)]; };
  // orient(F[j+1], F[j], w) with F[j+1] possibly the source at infinity.
  auto turn = [&](int from, int via, Vec2 w) -> double {
    if (from == kInfinity) {
      const Vec2 d = point(via) - w;
      return d.x * along.x + d.y * along.y;
    }
    return detail::fast_orient2d(point(from), point(via), w);
  };

  struct Task {
    int triangle;
    int a, b;
    std::vector<int> funnel;
    int apex;
  };
  std::vector<Task> stack;
  stack.push_back({root, 0, m, {0, kInfinity, m}, 1});
  while (!stack.empty()) {
    Task task = std::move(stack.back());
    stack.pop_back();
    const auto& tri = triangles[static_cast<std::size_t>(task.triangle)];
    int w = -1;
    for (int v : tri) {
      if (v != task.a && v != task.b) w = v;
    }
    const Vec2 pw = point(w);
    std::vector<int>& f = task.funnel;
    const int apex = task.apex;
    const int size = static_cast<int>(f.size());
    int wrap = -1;
    for (int j = 0; j < apex; ++j) {
      if (turn(f[static_cast<std::size_t>(j + 1)], f[static_cast<std::size_t>(j)], pw) > 0) {
        wrap = j;
        break;
      }
    }
    if (wrap < 0) {
      for (int k = size - 1; k > apex; --k) {
        if (turn(f[static_cast<std::size_t>(k - 1)], f[static_cast<std::size_t>(k)], pw) < 0) {
          wrap = k;
          break;
        }
      }
    }
    if (wrap < 0) wrap = apex;
    const int predecessor = f[static_cast<std::size_t>(wrap)];
    if (predecessor == kInfinity) {
      const Vec2 d = pw - s;
      distance[static_cast<std::size_t>(w)] = d.x * normal.x + d.y * normal.y;
    } else {
      const Vec2 d = pw - point(predecessor);
      distance[static_cast<std::size_t>(w)] =
          distance[static_cast<std::size_t>(predecessor)] + std::hypot(d.x, d.y);
    }
    const int right_triangle = neighbour(task.triangle, w, task.b);
    const int left_triangle = neighbour(task.triangle, task.a, w);
    if (right_triangle >= 0) {
      std::vector<int> child;
      child.reserve(static_cast<std::size_t>(size - wrap + 1));
      child.push_back(w);
      child.insert(child.end(), f.begin() + wrap, f.end());
      stack.push_back(
          {right_triangle, w, task.b, std::move(child), std::max(wrap, apex) - wrap + 1});
    }
    if (left_triangle >= 0) {
      // The left funnel is a prefix of this one: reuse its storage.
      f.resize(static_cast<std::size_t>(wrap + 1));
      f.push_back(w);
      stack.push_back({left_triangle, task.a, w, std::move(f), std::min(wrap, apex)});
    }
  }
  return distance;
}

}  // namespace hullcook::detail
