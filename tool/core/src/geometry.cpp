#include "hullcook/core/geometry.h"

#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace hullcook {

double signed_area(const Ring& ring) {
  if (ring.size() < 3) return 0.0;
  // Relative to the first vertex, so that far-from-origin coordinates keep their precision.
  const Vec2 origin = ring.front();
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const Vec2 a = ring[i] - origin;
    const Vec2 b = ring[i + 1] - origin;
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

double region_area(const Region& region) {
  double area = std::abs(signed_area(region.outer));
  for (const Ring& hole : region.holes) area -= std::abs(signed_area(hole));
  return area;
}

double convex_thickness(const Ring& ring) {
  const std::size_t n = ring.size();
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n && n >= 3; ++i) {
    const Vec2 a = ring[i], along = ring[(i + 1) % n] - a;
    const double length = std::hypot(along.x, along.y);
    if (!(length > 0.0)) continue;
    const Vec2 unit = along / length;
    double low = 0.0, high = 0.0;
    for (const Vec2& p : ring) {
      const double across = unit.x * (p.y - a.y) - unit.y * (p.x - a.x);
      low = std::min(low, across), high = std::max(high, across);
    }
    least = std::min(least, high - low);
  }
  return std::isfinite(least) ? least : 0.0;
}

namespace {

// Akl-Toussaint: the extreme points in eight directions span a convex polygon inside the hull; a
// point strictly inside it is neither a hull vertex nor on the hull's boundary, so dropping it
// before the sort leaves the result unchanged.
std::vector<std::size_t> hull_candidates(const Ring& points) {
  std::vector<std::size_t> candidates;
  candidates.reserve(points.size());
  constexpr std::size_t kDirections = 8;
  // Counter-clockwise from the lowest x: -x, -x-y, -y, x-y, x, x+y, y, y-x.
  constexpr double kDirection[kDirections][2] = {{-1, 0}, {-1, -1}, {0, -1}, {1, -1},
                                                 {1, 0},  {1, 1},   {0, 1},  {-1, 1}};
  std::size_t extreme[kDirections] = {};
  double best[kDirections];
  for (std::size_t d = 0; d < kDirections; ++d) {
    best[d] = -std::numeric_limits<double>::infinity();
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t d = 0; d < kDirections; ++d) {
      const double value = kDirection[d][0] * points[i].x + kDirection[d][1] * points[i].y;
      if (value > best[d]) best[d] = value, extreme[d] = i;
    }
  }
  Ring inner;
  for (std::size_t d = 0; d < kDirections; ++d) {
    const Vec2 p = points[extreme[d]];
    if (inner.empty() || (p != inner.back() && p != inner.front())) inner.push_back(p);
  }
  const std::size_t sides = inner.size();
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool strictly_inside = sides >= 3;
    for (std::size_t k = 0; k < sides && strictly_inside; ++k) {
      strictly_inside = detail::fast_orient2d(inner[k], inner[(k + 1) % sides], points[i]) > 0.0;
    }
    if (!strictly_inside) candidates.push_back(i);
  }
  return candidates;
}

}  // namespace

std::vector<std::size_t> convex_hull_indices(const Ring& points) {
  std::vector<std::size_t> order;
  if (points.size() >= 64) {
    order = hull_candidates(points);
  } else {
    order.resize(points.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].x != points[b].x) return points[a].x < points[b].x;
    if (points[a].y != points[b].y) return points[a].y < points[b].y;
    return a < b;
  });
  order.erase(std::unique(order.begin(), order.end(),
                          [&](std::size_t a, std::size_t b) { return points[a] == points[b]; }),
              order.end());
  if (order.size() < 3) return order;
  std::vector<std::size_t> hull(2 * order.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    while (k >= 2 && detail::fast_orient2d(points[hull[k - 2]], points[hull[k - 1]],
                                           points[order[i]]) <= 0.0) {
      --k;
    }
    hull[k++] = order[i];
  }
  for (std::size_t i = order.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && detail::fast_orient2d(points[hull[k - 2]], points[hull[k - 1]],
                                               points[order[i]]) <= 0.0) {
      --k;
    }
    hull[k++] = order[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::vector<std::size_t> simple_polygon_hull_indices(const Ring& ring) {
  return simple_polygon_hull_indices(ring, ring.size());
}

namespace {

// Steps of Melkman's scan over the ring's vertices first + k for k in [k, k_end), on the deque
// [bottom, top]: the hull of the chain so far, counter-clockwise from bottom to top, with the last
// added vertex at both ends.
// The filtered steps decide every orientation by the static error bound in force (see
// CoordinateBound) and stop, returning false with the state as it was before vertex k, at the
// first one too close to call: without a call to the exact predicate in their loop, their points
// stay in registers. The exact steps decide all. Both take the same decisions.
template <bool kFiltered>
bool melkman_steps(const Ring& ring, std::size_t first, std::vector<std::size_t>& deque,
                   std::size_t& bottom_io, std::size_t& top_io, std::size_t& k_io,
                   std::size_t k_end) {
  const std::size_t n = ring.size();
  const double bound = detail::static_orient_error_bound;
  // Sets left to whether c lies strictly left of a->b; false: too close to call (filtered only).
  auto decide_left = [bound](Vec2 a, Vec2 b, Vec2 c, bool& left) {
    if constexpr (kFiltered) {
      const double determinant = detail::rounded_orient2d(a, b, c);
      left = determinant > 0.0;
      return std::abs(determinant) > bound;
    } else {
      left = detail::fast_orient2d(a, b, c) > 0.0;
      return true;
    }
  };
  std::size_t bottom = bottom_io, top = top_io, k = k_io;
  // The two edges at the last added vertex, whose sides decide whether a vertex is inside.
  Vec2 bottom_from = ring[deque[bottom]], bottom_to = ring[deque[bottom + 1]];
  Vec2 top_from = ring[deque[top - 1]], top_to = ring[deque[top]];
  auto stop = [&] {
    bottom_io = bottom, top_io = top, k_io = k;
    return false;
  };
  for (std::size_t index = first + k < n ? first + k : first + k - n; k < k_end;
       ++k, index = index + 1 == n ? 0 : index + 1) {
    const Vec2 p = ring[index];
    // The tests against the edges at the last added vertex are also the first tests of the pops
    // below (the bottom's pops never reach the top's edge: p cannot see every hull edge).
    bool left_of_bottom, left_of_top;
    if (!decide_left(bottom_from, bottom_to, p, left_of_bottom)) return stop();
    if (!decide_left(top_from, top_to, p, left_of_top)) return stop();
    if (left_of_bottom && left_of_top) continue;
    std::size_t new_bottom = bottom, new_top = top;
    if (!left_of_bottom) {
      ++new_bottom;
      for (bool left = false;; ++new_bottom) {
        if (!decide_left(ring[deque[new_bottom]], ring[deque[new_bottom + 1]], p, left)) {
          return stop();
        }
        if (left) break;
      }
    }
    // The bottom's new slot, restored if the top's pops stop.
    const std::size_t slot = new_bottom - 1;
    const std::size_t overwritten = deque[slot];
    deque[slot] = index;
    if (!left_of_top) {
      --new_top;
      for (bool left = false;; --new_top) {
        if (!decide_left(ring[deque[new_top - 1]], ring[deque[new_top]], p, left)) {
          deque[slot] = overwritten;
          return stop();
        }
        if (left) break;
      }
    }
    deque[++new_top] = index;
    bottom = slot, top = new_top;
    bottom_from = p, bottom_to = ring[deque[bottom + 1]];
    top_from = ring[deque[top - 1]], top_to = p;
  }
  bottom_io = bottom, top_io = top, k_io = k;
  return true;
}

}  // namespace

void simple_polygon_hull_indices(const Ring& ring, std::size_t first,
                                 std::vector<std::size_t>& hull) {
  const std::size_t n = ring.size();
  if (n < 4) {
    hull = convex_hull_indices(ring);
    return;
  }
  if (first >= n) {
    // Start at the lowest-x (then lowest-y) vertex: a hull vertex.
    first = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (ring[i].x < ring[first].x || (ring[i].x == ring[first].x && ring[i].y < ring[first].y)) {
        first = i;
      }
    }
  }
  auto vertex = [&](std::size_t k) { return first + k < n ? first + k : first + k - n; };
  auto point = [&](std::size_t index) { return ring[index]; };
  const int start_turn =
      detail::fast_orientation(ring[vertex(0)], ring[vertex(1)], ring[vertex(2)]);
  if (start_turn == 0) {
    hull = convex_hull_indices(ring);
    return;
  }
  // Kept per thread: decompositions take the hull of every component, and a fresh buffer of
  // this size is an mmap and munmap for large rings.
  thread_local std::vector<std::size_t> deque;
  if (deque.size() < 2 * n + 1) deque.resize(2 * n + 1);
  std::size_t bottom = n, top = n + 3;
  deque[bottom] = deque[top] = vertex(2);
  deque[bottom + 1] = start_turn > 0 ? vertex(0) : vertex(1);
  deque[bottom + 2] = start_turn > 0 ? vertex(1) : vertex(0);
  std::size_t k = 3;
  if (detail::static_orient_error_bound == std::numeric_limits<double>::infinity()) {
    melkman_steps<false>(ring, first, deque, bottom, top, k, n);  // no bound to filter with
  } else {
    // Filtered steps; a vertex they cannot decide is taken by an exact step.
    while (!melkman_steps<true>(ring, first, deque, bottom, top, k, n)) {
      melkman_steps<false>(ring, first, deque, bottom, top, k, k + 1);
    }
  }
  // Drop any vertex left collinear (a chain may double back along a hull edge), keeping the
  // counter-clockwise order.
  hull.clear();
  for (std::size_t k = bottom; k < top; ++k) {
    const std::size_t index = deque[k];
    while (hull.size() >= 2 && detail::fast_orient2d(point(hull[hull.size() - 2]),
                                                     point(hull.back()), point(index)) <= 0.0) {
      hull.pop_back();
    }
    hull.push_back(index);
  }
  bool changed = true;
  while (changed && hull.size() >= 3) {
    changed = false;
    const std::size_t h = hull.size();
    if (detail::fast_orient2d(point(hull[h - 2]), point(hull[h - 1]), point(hull[0])) <= 0.0) {
      hull.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(point(hull[h - 1]), point(hull[0]), point(hull[1])) <= 0.0) {
      hull.erase(hull.begin());
      changed = true;
    }
  }
  if (hull.size() < 3) {
    hull = convex_hull_indices(ring);
    return;
  }
  const auto lowest = std::min_element(hull.begin(), hull.end(), [&](std::size_t a, std::size_t b) {
    return ring[a].x != ring[b].x ? ring[a].x < ring[b].x : ring[a].y < ring[b].y;
  });
  std::rotate(hull.begin(), lowest, hull.end());
}

std::vector<std::size_t> simple_polygon_hull_indices(const Ring& ring, std::size_t hull_vertex) {
  std::vector<std::size_t> hull;
  simple_polygon_hull_indices(ring, hull_vertex, hull);
  return hull;
}

Ring convex_hull(const Ring& points) {
  Ring hull;
  for (std::size_t index : convex_hull_indices(points)) hull.push_back(points[index]);
  return hull;
}

bool is_strictly_convex_ccw(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  int x_changes = 0, y_changes = 0, last_x = 0, last_y = 0, first_x = 0, first_y = 0;
  auto note = [](double delta, int& last, int& first, int& changes) {
    const int sign = (delta > 0) - (delta < 0);
    if (sign == 0) return;
    if (last != 0 && sign != last) ++changes;
    if (first == 0) first = sign;
    last = sign;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % n], c = ring[(i + 2) % n];
    if (orientation(a, b, c) <= 0) return false;
    note(b.x - a.x, last_x, first_x, x_changes);
    note(b.y - a.y, last_y, first_y, y_changes);
  }
  // The change from the last edge back to the first.
  if (last_x != 0 && first_x != last_x) ++x_changes;
  if (last_y != 0 && first_y != last_y) ++y_changes;
  return x_changes <= 2 && y_changes <= 2;
}

int ring_orientation(const Ring& ring) {
  // The lowest (then leftmost) vertex is a vertex of the convex hull, so the ring turns there the
  // way it runs. The sign of the floating-point area is not enough: a sliver's area rounds to zero
  // or to the wrong sign (issue 3's fuzzing: a clockwise triangle was taken for a
  // counter-clockwise one, and a valid sliver piece was refused for zero area).
  if (ring.size() < 3) return 0;
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < ring.size(); ++i) {
    if (ring[i].y < ring[lowest].y || (ring[i].y == ring[lowest].y && ring[i].x < ring[lowest].x)) {
      lowest = i;
    }
  }
  const std::size_t n = ring.size();
  return orientation(ring[(lowest + n - 1) % n], ring[lowest], ring[(lowest + 1) % n]);
}

namespace {

// Whether edge a-b decides p's location (on it: the boundary), or flips the crossing count of a
// ray from p towards +x (half-open rule on y; the side test is exact).
enum class EdgeVerdict { none, boundary, crosses };
EdgeVerdict edge_verdict(Vec2 a, Vec2 b, Vec2 p) {
  if (on_segment(a, b, p)) return EdgeVerdict::boundary;
  if ((a.y > p.y) != (b.y > p.y)) {
    const double side = detail::fast_orient2d(a, b, p);
    if ((b.y > a.y) ? side > 0.0 : side < 0.0) return EdgeVerdict::crosses;
  }
  return EdgeVerdict::none;
}

}  // namespace

Location locate_point(const Ring& ring, Vec2 p) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const EdgeVerdict verdict = edge_verdict(ring[j], ring[i], p);
    if (verdict == EdgeVerdict::boundary) return Location::boundary;
    inside ^= verdict == EdgeVerdict::crosses;
  }
  return inside ? Location::inside : Location::outside;
}

namespace {

// Edges filed per band, at most this many times the edge count (a comb's teeth span every band).
constexpr std::size_t kFilingsPerEdge = 8;

}  // namespace

RingLocator::RingLocator(const Ring& ring) : ring_(ring) {
  const std::size_t n = ring.size();
  if (n < 16 || n > std::numeric_limits<std::uint32_t>::max()) return;
  double high_y = -std::numeric_limits<double>::infinity();
  low_y_ = std::numeric_limits<double>::infinity();
  for (Vec2 v : ring) low_y_ = std::min(low_y_, v.y), high_y = std::max(high_y, v.y);
  if (!(std::isfinite(low_y_) && std::isfinite(high_y) && high_y > low_y_)) return;
  // Fewer, taller bands while the edges' filings exceed their budget.
  for (std::size_t bands = n; bands >= 4; bands /= 4) {
    band_height_ = (high_y - low_y_) / static_cast<double>(bands);
    if (!(band_height_ > 0.0) || !std::isfinite(band_height_)) break;
    bands_ = bands;
    std::size_t filings = 0;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      filings +=
          band_of(std::max(ring[i].y, ring[j].y)) - band_of(std::min(ring[i].y, ring[j].y)) + 1;
    }
    if (filings <= kFilingsPerEdge * n) {
      edges_.build(bands, [&](auto&& add) {
        for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
          const std::size_t last = band_of(std::max(ring[i].y, ring[j].y));
          for (std::size_t b = band_of(std::min(ring[i].y, ring[j].y)); b <= last; ++b) {
            add(b, static_cast<std::uint32_t>(i));
          }
        }
      });
      return;
    }
  }
  bands_ = 0;  // a plain scan
}

// Monotone in y (a difference, a division by a positive constant and a floor, each monotone):
// an edge whose y range holds p.y is filed in p.y's band.
std::size_t RingLocator::band_of(double y) const {
  const double band = std::floor((y - low_y_) / band_height_);
  if (!(band > 0.0)) return 0;
  return std::min(static_cast<std::size_t>(std::min(band, 1e18)), bands_ - 1);
}

Location RingLocator::locate(Vec2 p) const {
  if (bands_ == 0) return locate_point(ring_, p);
  // Only an edge whose closed y range holds p.y can hold p or flip the count, and it is filed in
  // p.y's band; a p above or below every vertex (or NaN) meets none and is outside, as
  // locate_point finds it.
  const std::size_t n = ring_.size();
  const std::size_t band = band_of(p.y);
  bool inside = false;
  for (const std::uint32_t* k = edges_.begin(band); k != edges_.end(band); ++k) {
    const std::size_t i = *k;
    const EdgeVerdict verdict = edge_verdict(ring_[i == 0 ? n - 1 : i - 1], ring_[i], p);
    if (verdict == EdgeVerdict::boundary) return Location::boundary;
    inside ^= verdict == EdgeVerdict::crosses;
  }
  return inside ? Location::inside : Location::outside;
}

Location locate_point(const Region& region, Vec2 p) {
  Location where = locate_point(region.outer, p);
  if (where != Location::inside) return where;
  for (const Ring& hole : region.holes) {
    const Location in_hole = locate_point(hole, p);
    if (in_hole == Location::boundary) return Location::boundary;
    if (in_hole == Location::inside) return Location::outside;
  }
  return Location::inside;
}

SegmentProjection project_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = ab.x * ab.x + ab.y * ab.y;
  double t = length2 > 0.0 ? ((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec2 d = p - (a + ab * t);
  return {t, std::sqrt(d.x * d.x + d.y * d.y)};
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  return std::sqrt(point_segment_distance_squared(p, a, b));
}

namespace {

double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

Circle circle_of_two(Vec2 a, Vec2 b) { return {(a + b) * 0.5, distance(a, b) * 0.5}; }

Circle circle_of_three(Vec2 a, Vec2 b, Vec2 c) {
  // The centre's formula multiplies three coordinate differences: beyond about 1e100 that
  // overflows, below about 1e-100 it underflows (R became inf or 0, and τ = 1% of R with it). It
  // is evaluated on the differences scaled by a power of two to near 1, which is exact: within the
  // range where nothing overflowed or underflowed, every value is bit for bit what it was.
  const Vec2 unscaled_ab = b - a, unscaled_ac = c - a;
  const double largest = std::max({std::abs(unscaled_ab.x), std::abs(unscaled_ab.y),
                                   std::abs(unscaled_ac.x), std::abs(unscaled_ac.y)});
  if (!(largest > 0.0) || !std::isfinite(largest)) return circle_of_two(a, b);
  const int exponent = std::ilogb(largest);
  const Vec2 ab{std::ldexp(unscaled_ab.x, -exponent), std::ldexp(unscaled_ab.y, -exponent)};
  const Vec2 ac{std::ldexp(unscaled_ac.x, -exponent), std::ldexp(unscaled_ac.y, -exponent)};
  const double d = 2.0 * (ab.x * ac.y - ab.y * ac.x);
  if (d == 0.0) {
    // Collinear: the circle on the two farthest points.
    Circle best = circle_of_two(a, b);
    for (Circle candidate : {circle_of_two(a, c), circle_of_two(b, c)}) {
      if (candidate.radius > best.radius) best = candidate;
    }
    return best;
  }
  const double ab2 = ab.x * ab.x + ab.y * ab.y;
  const double ac2 = ac.x * ac.x + ac.y * ac.y;
  const Vec2 offset{std::ldexp((ac.y * ab2 - ab.y * ac2) / d, exponent),
                    std::ldexp((ab.x * ac2 - ac.x * ab2) / d, exponent)};
  return {a + offset, std::hypot(offset.x, offset.y)};
}

bool contains(const Circle& circle, Vec2 p) {
  // Relative slack: the circle's own rounding must not restart the search forever.
  return distance(circle.center, p) <= circle.radius * (1.0 + 1e-12) + 1e-300;
}

}  // namespace

Circle minimum_enclosing_circle(const Ring& input) {
  if (input.empty()) return {};
  Ring points = convex_hull(input);
  // A fixed-seed Fisher-Yates shuffle with a 64-bit LCG: deterministic on every platform.
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (std::size_t i = points.size(); i > 1; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(points[i - 1], points[(state >> 33) % i]);
  }
  Circle circle{points[0], 0.0};
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (contains(circle, points[i])) continue;
    circle = {points[i], 0.0};
    for (std::size_t j = 0; j < i; ++j) {
      if (contains(circle, points[j])) continue;
      circle = circle_of_two(points[i], points[j]);
      for (std::size_t k = 0; k < j; ++k) {
        if (!contains(circle, points[k])) circle = circle_of_three(points[i], points[j], points[k]);
      }
    }
  }
  return circle;
}

double enclosing_radius(const std::vector<Region>& regions) {
  Ring points;
  for (const Region& region : regions) {
    points.insert(points.end(), region.outer.begin(), region.outer.end());
  }
  return minimum_enclosing_circle(points).radius;
}

}  // namespace hullcook
