#include "pocket_paths.h"

#include "length_inline.h"
#include "triangulate.h"

#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hullcook::detail {

namespace {

// The bridge β = (s, t) of a whole pocket, which every part of it measures against: its direction
// and inward unit normal.
struct Bridge {
  Vec2 s;
  Vec2 along;   // t - s
  Vec2 normal;  // into the pocket

  // The distance from p to the bridge's line [units]: the path of a vertex that sees the bridge.
  double depth(Vec2 p) const {
    const Vec2 d = p - s;
    return d.x * normal.x + d.y * normal.y;
  }
};

// Shortest paths from q[1..m-1] to the segment (q[0], q[m]), a part of bridge's line, inside the
// polygon q (clockwise), into distance[0..m]. Distances to the line are taken from bridge, so
// that a part of a pocket measures as the whole pocket does.
void funnel_paths(const std::vector<Vec2>& q, const Bridge& bridge, double* distance) {
  const int m = static_cast<int>(q.size()) - 1;
  const Vec2 along = bridge.along;
  // The polygon q[0..m] runs clockwise; triangulate it reversed (counter-clockwise). The
  // triangulation sweeps along y, and a pocket's chain runs up and down least along its bridge:
  // a bridge closer to horizontal is turned a quarter (exactly, keeping every orientation) so
  // that the sweep has fewer runs to merge and fewer pieces to cut.
  thread_local std::vector<Vec2> ccw;
  thread_local std::vector<std::array<int, 3>> triangles, across;
  ccw.assign(q.rbegin(), q.rend());
  if (std::abs(along.x) > std::abs(along.y)) {
    for (Vec2& p : ccw) p = {-p.y, p.x};
  }
  triangulate(ccw, triangles, &across);
  for (auto& triangle : triangles) {
    for (int& v : triangle) v = m - v;
  }
  int root = -1;
  for (std::size_t i = 0; i < triangles.size() && root < 0; ++i) {
    const auto& tri = triangles[i];
    const bool has_s = tri[0] == 0 || tri[1] == 0 || tri[2] == 0;
    const bool has_t = tri[0] == m || tri[1] == m || tri[2] == m;
    if (has_s && has_t) root = static_cast<int>(i);
  }
  if (root < 0) return;

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

  // Depth-first over the triangles from the bridge. All funnels live in one buffer: a child's
  // funnel is a prefix or a suffix of its parent's plus the new vertex, written just past that
  // range; the write is undone once the child's subtree is done, so a sibling sees its parent's
  // funnel intact. A child reaches at most one place further out than its parent, so the buffer
  // needs the depth (at most m) on either side.
  struct Step {
    int triangle;  // -1: undo, restoring funnel[write] = value
    int a, b;
    int low, high, apex;  // the funnel is funnel[low..high], its apex at funnel[apex]
    int write, value;     // funnel[write] = value on entry (write -1: nothing)
  };
  thread_local std::vector<int> funnel;
  thread_local std::vector<Step> stack;
  const int centre = m + 2;
  funnel.assign(static_cast<std::size_t>(2 * centre + 3), 0);
  funnel[static_cast<std::size_t>(centre)] = 0;
  funnel[static_cast<std::size_t>(centre + 1)] = kInfinity;
  funnel[static_cast<std::size_t>(centre + 2)] = m;
  stack.clear();
  stack.push_back({root, 0, m, centre, centre + 2, centre + 1, -1, 0});
  auto f = [&](int position) { return funnel[static_cast<std::size_t>(position)]; };
  while (!stack.empty()) {
    const Step step = stack.back();
    stack.pop_back();
    if (step.write >= 0) {
      int& slot = funnel[static_cast<std::size_t>(step.write)];
      if (step.triangle < 0) {
        slot = step.value;
        continue;
      }
      stack.push_back({-1, 0, 0, 0, 0, 0, step.write, slot});
      slot = step.value;
    }
    const auto& tri = triangles[static_cast<std::size_t>(step.triangle)];
    // w is the corner off the entry edge; the triangles across its two other edges come next.
    const int corner = tri[0] != step.a && tri[0] != step.b   ? 0
                       : tri[1] != step.a && tri[1] != step.b ? 1
                                                              : 2;
    const int w = tri[static_cast<std::size_t>(corner)];
    const auto& beyond = across[static_cast<std::size_t>(step.triangle)];
    const int after_w = beyond[static_cast<std::size_t>(corner)];  // across (w, next corner)
    const int before_w = beyond[static_cast<std::size_t>(corner == 0 ? 2 : corner - 1)];
    const bool b_follows_w = tri[static_cast<std::size_t>(corner == 2 ? 0 : corner + 1)] == step.b;
    const Vec2 pw = point(w);
    const int apex = step.apex;
    // Where w's path leaves the funnel: the first left-chain vertex whose outgoing edge w is
    // beyond, else the last right-chain one, else the apex. Each chain is convex, so its test
    // changes value once along it: binary searches.
    int wrap = apex;
    int low = step.low, high = apex;  // first j in [low, apex) with w beyond edge j
    while (low < high) {
      const int middle = low + (high - low) / 2;
      if (turn(f(middle + 1), f(middle), pw) > 0) {
        high = middle;
      } else {
        low = middle + 1;
      }
    }
    if (low < apex) {
      wrap = low;
    } else {
      low = apex + 1, high = step.high + 1;  // first k in (apex, high] with w not beyond edge k
      while (low < high) {
        const int middle = low + (high - low) / 2;
        if (turn(f(middle - 1), f(middle), pw) < 0) {
          low = middle + 1;
        } else {
          high = middle;
        }
      }
      if (low > apex + 1) wrap = low - 1;
    }
    const int predecessor = f(wrap);
    if (predecessor == kInfinity) {
      distance[static_cast<std::size_t>(w)] = bridge.depth(pw);
    } else {
      const Vec2 d = pw - point(predecessor);
      distance[static_cast<std::size_t>(w)] =
          distance[static_cast<std::size_t>(predecessor)] + detail::length(d);
    }
    const int right_triangle = b_follows_w ? after_w : before_w;  // across (w, b)
    const int left_triangle = b_follows_w ? before_w : after_w;   // across (a, w)
    // Right: w, then the funnel from wrap on. Left: the funnel up to wrap, then w.
    if (right_triangle >= 0) {
      stack.push_back(
          {right_triangle, w, step.b, wrap - 1, step.high, std::max(wrap, apex), wrap - 1, w});
    }
    if (left_triangle >= 0) {
      stack.push_back(
          {left_triangle, step.a, w, step.low, wrap + 1, std::min(wrap, apex), wrap + 1, w});
    }
  }
}

}  // namespace

void shortest_paths_to_bridge(const std::vector<Vec2>& q, std::vector<double>& distance) {
  if (q.size() < 3) {
    distance.assign(q.size(), 0.0);
    return;
  }
  const std::size_t m = q.size() - 1;
  // Every entry is written below (the parts and the cuts between them cover 1..m-1): no fill.
  distance.resize(q.size());
  distance[0] = distance[m] = 0.0;
  const Vec2 s = q.front();
  const Vec2 along = q.back() - s;
  const double length = detail::length(along);
  const Bridge bridge{s, along, {-along.y / length, along.x / length}};
  // Where the chain crosses the perpendicular to the bridge through one of its vertices c only at
  // c, the segment from c to its foot on the bridge is a chord of the pocket, and no shortest path
  // crosses it (one that did would do better going straight to the bridge from the crossing). The
  // chords cut the pocket into parts measured on their own: a part whose chain runs forward along
  // the bridge throughout sees the bridge straight from each vertex, and only the others need the
  // funnel. On the neuron this spares the funnel a third of its vertices under H1.
  // Positions along the bridge, u, are rounded: a cut needs a margin that covers their error.
  thread_local std::vector<double> u, before_max;
  u.resize(q.size());
  before_max.resize(q.size());
  double extent = 0.0;
  for (std::size_t i = 0; i <= m; ++i) {
    const Vec2 d = q[i] - s;
    u[i] = d.x * along.x + d.y * along.y;
    extent = std::max({extent, std::abs(d.x), std::abs(d.y)});
  }
  const double margin = 1e-9 * extent * (std::abs(along.x) + std::abs(along.y));
  before_max[0] = u[0];
  for (std::size_t i = 1; i <= m; ++i) before_max[i] = std::max(before_max[i - 1], u[i]);
  thread_local std::vector<Vec2> part;
  thread_local std::vector<double> part_distance;
  auto foot = [&](std::size_t c) { return s + along * (u[c] / (length * length)); };
  // The part from cut `from` to cut `to`.
  auto measure_part = [&](std::size_t from, std::size_t to, bool forward) {
    if (forward) {
      for (std::size_t i = from + 1; i < to; ++i) distance[i] = bridge.depth(q[i]);
      return;
    }
    part.clear();
    if (from > 0) part.push_back(foot(from));
    part.insert(part.end(), q.begin() + std::ptrdiff_t(from), q.begin() + std::ptrdiff_t(to) + 1);
    if (to < m) part.push_back(foot(to));
    part_distance.assign(part.size(), 0.0);
    funnel_paths(part, bridge, part_distance.data());
    const std::size_t offset = from > 0 ? 1 : 0;
    for (std::size_t i = from + 1; i < to; ++i) distance[i] = part_distance[i - from + offset];
  };
  // From t back to s: after_min is the least u after i; cuts close parts as they are found.
  double after_min = u[m];
  std::size_t part_end = m;
  bool forward = u[m] > u[m - 1] + margin;
  for (std::size_t i = m - 1; i > 0; --i) {
    const bool cut = before_max[i - 1] + margin < u[i] && u[i] + margin < after_min &&
                     bridge.depth(q[i]) > margin / length;
    if (cut) {
      measure_part(i, part_end, forward);
      distance[i] = bridge.depth(q[i]);
      part_end = i;
      forward = true;
    }
    after_min = std::min(after_min, u[i]);
    if (!(u[i] > u[i - 1] + margin)) forward = false;
  }
  measure_part(0, part_end, forward);
}

}  // namespace hullcook::detail
