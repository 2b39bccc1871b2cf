#include "pocket_paths.h"

#include "triangulate.h"

#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hullcook::detail {

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
  thread_local std::vector<Vec2> ccw;
  thread_local std::vector<std::array<int, 3>> triangles, across;
  ccw.assign(q.rbegin(), q.rend());
  triangulate(ccw, triangles, &across);
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
