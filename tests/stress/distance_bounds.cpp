#include "distance_bounds.h"

#include "edge_index.h"

#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>

namespace hullcook::stress {

ConvexLines::ConvexLines(const Ring& hull) : origin_(hull.empty() ? Vec2{0, 0} : hull.front()) {
  const std::size_t n = hull.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = hull[k] - origin_, b = hull[(k + 1) % n] - origin_;
    const Vec2 edge = b - a;
    const double length = std::hypot(edge.x, edge.y);
    if (!(length > 0)) continue;
    const Vec2 normal{-edge.y / length, edge.x / length};
    normals_.push_back(normal);
    offsets_.push_back(normal.x * a.x + normal.y * a.y);
  }
}

double ConvexLines::depth(Vec2 p) const {
  const Vec2 q = p - origin_;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < normals_.size(); ++k) {
    best = std::min(best, normals_[k].x * q.x + normals_[k].y * q.y - offsets_[k]);
  }
  return best;
}

double ConvexLines::max_depth(Vec2 p, Vec2 q, double limit, Vec2& point) const {
  const Vec2 a = p - origin_, b = q - origin_;
  const std::size_t n = normals_.size();
  std::vector<double> at_p(n), slope(n);
  double bound = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    at_p[k] = normals_[k].x * a.x + normals_[k].y * a.y - offsets_[k];
    const double at_q = normals_[k].x * b.x + normals_[k].y * b.y - offsets_[k];
    slope[k] = at_q - at_p[k];
    // Each line alone bounds the minimum; an affine function is largest at an end.
    bound = std::min(bound, std::max(at_p[k], at_q));
  }
  point = p;
  if (bound <= limit) return bound;
  auto value = [&](double t, std::size_t* active) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
      const double v = at_p[k] + t * slope[k];
      if (v < best) best = v, *active = k;
    }
    return best;
  };
  double low = 0, high = 1;
  std::size_t active = 0;
  for (int iteration = 0; iteration < 64 && high > low; ++iteration) {
    const double middle = (low + high) / 2;
    value(middle, &active);
    if (slope[active] > 0) {
      low = middle;
    } else {
      high = middle;
    }
  }
  double best = -std::numeric_limits<double>::infinity();
  for (double t : {0.0, 1.0, (low + high) / 2}) {
    const double v = value(t, &active);
    if (v > best) best = v, point = p + t * (q - p);
  }
  return best;
}

namespace {

// Triangles examined after the first witness, looking for a farther one.
constexpr std::size_t kSearchAfterWitness = 2000;

struct Segment {
  Vec2 a, b;
};

struct Cell {
  double bound;                         // an upper bound of the distance inside it
  Vec2 corner[3];                       // a triangle inside the domain
  std::vector<std::uint32_t> segments;  // the target segments that may matter inside it

  bool operator<(const Cell& other) const { return bound < other.bound; }
};

// The largest distance to s over the part of the triangle on the closed right side of s's line:
// that part is convex and the distance to a segment is convex, so its vertices (the corners on
// that side and where the triangle's edges cross the line) bound it.
double right_side_bound(const Vec2 (&corner)[3], const Segment& s) {
  double best = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec2 p = corner[i], q = corner[(i + 1) % 3];
    const double at_p = orient2d(s.a, s.b, p), at_q = orient2d(s.a, s.b, q);  // > 0: left
    if (at_p <= 0) best = std::max(best, point_segment_distance(p, s.a, s.b));
    if ((at_p < 0 && at_q > 0) || (at_p > 0 && at_q < 0)) {
      const Vec2 crossing = p + (at_p / (at_p - at_q)) * (q - p);
      best = std::max(best, point_segment_distance(crossing, s.a, s.b));
    }
  }
  return best;
}

}  // namespace

FarthestPoint farthest_from_target(const Ring& domain, const std::vector<Region>& target,
                                   double limit, double resolution, std::size_t budget) {
  std::vector<Segment> segments;
  auto add_ring = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      segments.push_back({ring[i], ring[(i + 1) % ring.size()]});
    }
  };
  for (const Region& region : target) {
    add_ring(region.outer);
    for (const Ring& hole : region.holes) add_ring(hole);
  }
  EdgeIndex index(target);
  FarthestPoint result;
  if (domain.size() < 3 || segments.empty()) return result;
  std::vector<std::uint32_t> all(segments.size());
  for (std::uint32_t i = 0; i < segments.size(); ++i) all[i] = i;
  // Farthest bound first: a witness, if any, is found early and then bettered quickly.
  std::priority_queue<Cell> queue;
  for (std::size_t i = 1; i + 1 < domain.size(); ++i) {
    queue.push(
        {std::numeric_limits<double>::infinity(), {domain[0], domain[i], domain[i + 1]}, all});
  }
  std::size_t cells = 0, stop = budget;
  double farthest_seen = 0;  // the largest distance at a centroid, for a report without proof
  Vec2 farthest_at = domain[0];
  std::vector<double> distance;
  while (!queue.empty()) {
    // Moving out of the top leaves its bound, all that pop() compares.
    Cell cell = std::move(const_cast<Cell&>(queue.top()));
    queue.pop();
    if (++cells > stop) {
      result.proven = false;
      if (result.distance <= limit) result.distance = farthest_seen, result.point = farthest_at;
      return result;
    }
    double bound = result.proven ? limit : result.distance;
    if (cell.bound <= bound) continue;
    const Vec2 c = (cell.corner[0] + cell.corner[1] + cell.corner[2]) / 3.0;
    double radius = 0;
    for (Vec2 v : cell.corner) radius = std::max(radius, std::hypot(v.x - c.x, v.y - c.y));
    distance.resize(cell.segments.size());
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < cell.segments.size(); ++i) {
      const Segment& s = segments[cell.segments[i]];
      distance[i] = point_segment_distance(c, s.a, s.b);
      nearest = std::min(nearest, distance[i]);
    }
    // The distance at c is at most nearest: when that proves the cell, where c lies is moot.
    if (nearest + radius <= bound) continue;
    const bool inside_target = index.covers(c);
    if (inside_target && nearest >= radius) continue;  // the whole cell is in the target
    const double here = inside_target ? 0.0 : nearest;
    if (here > farthest_seen) farthest_seen = here, farthest_at = c;
    if (here > bound) {
      // A witness; go on a little for the farthest one, to a thousandth of its distance.
      if (result.proven) stop = std::min(budget, cells + kSearchAfterWitness);
      result = {false, here, c};
      resolution = std::max(resolution, 1e-3 * here);
      bound = here;
    }
    if (here + radius <= bound || radius <= resolution) continue;
    if (inside_target) {
      // The target lies left of its segments. A point of the cell outside it is reached from c
      // by leaving the target across a segment that meets the cell, so it lies right of that
      // segment's line, within the bound of right_side_bound. Thin slivers between the target and
      // the domain's edge are proven so at any cell size.
      double outside = 0;
      for (std::size_t i = 0; i < cell.segments.size() && outside <= bound; ++i) {
        if (distance[i] <= radius) {
          outside = std::max(outside, right_side_bound(cell.corner, segments[cell.segments[i]]));
        }
      }
      if (outside <= bound) continue;
    }
    bool proven = false;
    for (std::size_t i = 0; i < cell.segments.size() && !proven; ++i) {
      if (distance[i] > bound) continue;
      const Segment& s = segments[cell.segments[i]];
      proven = std::all_of(std::begin(cell.corner), std::end(cell.corner), [&](Vec2 corner) {
        return point_segment_distance(corner, s.a, s.b) <= bound;
      });
    }
    if (proven) continue;
    // A child's nearest segment is within nearest + 2 radius of this centroid, and a segment
    // that can prove a child is within limit + 2 radius of it.
    const double keep = std::max(nearest, bound) + 2 * radius;
    std::vector<std::uint32_t> kept;
    for (std::size_t i = 0; i < cell.segments.size(); ++i) {
      if (distance[i] <= keep) kept.push_back(cell.segments[i]);
    }
    // Halved across its longest edge: a long thin cell (a fan triangle of a long hull, along the
    // outline) needs cells of about the bound's size along its length only, where quartering it
    // made as many across it (a 500 units long piece at tau 0.5 needed over 200,000 cells).
    int longest = 0;
    double longest_length = -1;
    for (int i = 0; i < 3; ++i) {
      const Vec2 edge = cell.corner[(i + 1) % 3] - cell.corner[i];
      const double edge_length = std::hypot(edge.x, edge.y);
      if (edge_length > longest_length) longest = i, longest_length = edge_length;
    }
    const Vec2 a = cell.corner[longest], b = cell.corner[(longest + 1) % 3],
               d = cell.corner[(longest + 2) % 3];
    const Vec2 middle = (a + b) * 0.5;
    const double upper = here + radius;
    queue.push({upper, {a, middle, d}, kept});
    queue.push({upper, {middle, b, d}, std::move(kept)});
  }
  return result;
}

}  // namespace hullcook::stress
