// The cut that always exists. Between two consecutive heights at which the region has vertices (a
// slab), no vertex lies and no two edges meet, so every horizontal line in the slab crosses the
// same edges in the same order, and the region's part of the slab between two consecutive
// crossings is a trapezoid whose two sides lie on edges. The trapezoid beside a hole's first (or
// last) crossing lies between the hole and another ring; cutting it out along its top and bottom
// joins the hole to that ring: to ∂P0 (the hole opens) or to another hole (the two merge). The
// cuts end on the edges at new vertices, or at the edges' own vertices where the slab's bounds
// allow; no cut grazes a vertex.
#include "cut.h"
#include "sight.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace hullcook::detail {
namespace {

// Slabs tried per direction, the highest first: each costs a pass over the edges.
constexpr std::size_t kSlabsTried = 8;

struct Crossing {
  double x;
  int ring;  // 0 outer, h + 1 hole h
  std::size_t edge;
  bool operator<(const Crossing& c) const {
    return x != c.x ? x < c.x : ring != c.ring ? ring < c.ring : edge < c.edge;
  }
};

const Ring& ring_of(const Region& region, int ring) {
  return ring == 0 ? region.outer : region.holes[static_cast<std::size_t>(ring - 1)];
}

// The point of edge a-b at height y (between the ends' heights): an end itself when at its height.
Vec2 point_at_height(Vec2 a, Vec2 b, double y) {
  if (y == a.y) return a;
  if (y == b.y) return b;
  const double x = a.x + (y - a.y) * ((b.x - a.x) / (b.y - a.y));
  return {std::clamp(x, std::min(a.x, b.x), std::max(a.x, b.x)), y};
}

// The same, moved by whole ulps off the edge's outer side where rounding put it there: a new vertex
// on the edge a-b of a ring (whose region lies left of a-b) lies in the region or on its boundary,
// exactly, so that the pieces never reach outside the region.
Vec2 vertex_at_height(Vec2 a, Vec2 b, double y) {
  Vec2 p = point_at_height(a, b, y);
  // Left of a downward edge is +x, of an upward one -x.
  const double inward = a.y > b.y ? std::numeric_limits<double>::infinity()
                                  : -std::numeric_limits<double>::infinity();
  for (int step = 0; step < 8 && orientation(a, b, p) < 0; ++step)
    p.x = std::nextafter(p.x, inward);
  return p;
}

struct SlabCut {
  double quality = 0.0;  // the trapezoid's smaller extent [units]: its height or its width
  double area = 0.0;
  std::pair<Region, Region> pieces;  // the trapezoid, then the rest
};

// The slab cuts of hole h in a region, along horizontal lines; the best found is kept in best.
class SlabCutter {
 public:
  SlabCutter(const Region& region, std::size_t h) : region_(region), hole_ring_(int(h + 1)) {
    double largest = 0.0;
    for_each_vertex([&](Vec2 p) {
      levels_.push_back(p.y);
      largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    });
    std::sort(levels_.begin(), levels_.end());
    levels_.erase(std::unique(levels_.begin(), levels_.end()), levels_.end());
    // Crossings closer than this could be misordered by the rounding of their computation.
    separation_ = 1e-12 * largest;
  }

  void cut(std::optional<SlabCut>& best) {
    const Ring& hole = ring_of(region_, hole_ring_);
    double low = hole[0].y, high = hole[0].y;
    for (Vec2 p : hole) low = std::min(low, p.y), high = std::max(high, p.y);
    std::vector<std::size_t> slabs;
    const auto first = std::lower_bound(levels_.begin(), levels_.end(), low) - levels_.begin();
    for (std::size_t k = static_cast<std::size_t>(first); k + 1 < levels_.size(); ++k) {
      if (levels_[k + 1] > high) break;
      slabs.push_back(k);
    }
    std::stable_sort(slabs.begin(), slabs.end(), [&](std::size_t a, std::size_t b) {
      return levels_[a + 1] - levels_[a] > levels_[b + 1] - levels_[b];
    });
    if (slabs.size() > kSlabsTried) slabs.resize(kSlabsTried);
    for (std::size_t k : slabs) cut_slab(levels_[k], levels_[k + 1], best);
  }

 private:
  template <typename Visit>
  void for_each_vertex(Visit&& visit) const {
    for (Vec2 p : region_.outer) visit(p);
    for (const Ring& hole : region_.holes) {
      for (Vec2 p : hole) visit(p);
    }
  }

  void cut_slab(double bottom, double top, std::optional<SlabCut>& best) {
    const double middle = bottom + (top - bottom) / 2;
    if (!(bottom < middle && middle < top)) return;
    crossings_.clear();
    for (int r = 0; r <= static_cast<int>(region_.holes.size()); ++r) {
      const Ring& ring = ring_of(region_, r);
      for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const Vec2 a = ring[i], b = ring[i + 1 == n ? 0 : i + 1];
        if ((a.y < middle) == (b.y < middle)) continue;
        crossings_.push_back({point_at_height(a, b, middle).x, r, i});
      }
    }
    std::sort(crossings_.begin(), crossings_.end());
    std::size_t first = crossings_.size(), last = 0;
    for (std::size_t k = 0; k < crossings_.size(); ++k) {
      if (crossings_[k].ring != hole_ring_) continue;
      first = std::min(first, k), last = k;
    }
    if (first == crossings_.size()) return;
    // The region lies left of the hole's first crossing and right of its last.
    if (first > 0) cut_interval(first - 1, bottom, top, best);
    if (last + 1 < crossings_.size()) cut_interval(last, bottom, top, best);
  }

  // The trapezoid between crossings j and j + 1, from bottom to top.
  void cut_interval(std::size_t j, double bottom, double top, std::optional<SlabCut>& best) {
    for (std::size_t k = j == 0 ? 0 : j - 1; k + 1 < crossings_.size() && k <= j + 1; ++k) {
      if (!(crossings_[k + 1].x - crossings_[k].x > separation_)) return;
    }
    const Crossing& left = crossings_[j];
    const Crossing& right = crossings_[j + 1];
    const Ring& left_ring = ring_of(region_, left.ring);
    const Ring& right_ring = ring_of(region_, right.ring);
    const std::size_t a = left.edge, b = a + 1 == left_ring.size() ? 0 : a + 1;
    const std::size_t c = right.edge, d = c + 1 == right_ring.size() ? 0 : c + 1;
    // The region lies left of its rings' edges: the left edge runs down, the right one up.
    if (!(left_ring[a].y > left_ring[b].y && right_ring[c].y < right_ring[d].y)) return;
    // A cut along a slab's bound must not pass through a vertex there; else a quarter in.
    const double quarter = (top - bottom) / 4;
    auto clear = [&](double y) {
      return clear_at(y, left_ring[a], left_ring[b], right_ring[c], right_ring[d]);
    };
    const double low = clear(bottom) ? bottom : bottom + quarter;
    const double high = clear(top) ? top : top - quarter;
    if (!(low < high) || !clear(low) || !clear(high)) return;
    const Vec2 left_low = vertex_at_height(left_ring[a], left_ring[b], low);
    const Vec2 left_high = vertex_at_height(left_ring[a], left_ring[b], high);
    const Vec2 right_low = vertex_at_height(right_ring[c], right_ring[d], low);
    const Vec2 right_high = vertex_at_height(right_ring[c], right_ring[d], high);
    const double width = std::min(right_low.x - left_low.x, right_high.x - left_high.x);
    if (!(width > separation_)) return;
    const double quality = std::min(width, high - low);
    Ring trapezoid{left_low, right_low, right_high, left_high};
    const double area = signed_area(trapezoid);
    if (best && (quality < best->quality || (quality == best->quality && area <= best->area))) {
      return;
    }
    // The two rings joined along the cuts: the left ring from the edge's lower end round to its
    // upper end, across the top cut, the right ring from its edge's upper end round to its lower
    // end, and back across the bottom cut.
    Ring joined;
    auto append_ring = [&](const Ring& ring, std::size_t from) {
      for (std::size_t k = 0, n = ring.size(); k < n; ++k) joined.push_back(ring[(from + k) % n]);
    };
    append_ring(left_ring, b);
    joined.push_back(left_high);
    joined.push_back(right_high);
    append_ring(right_ring, d);
    joined.push_back(right_low);
    joined.push_back(left_low);
    remove_degenerate_vertices_in_place(joined);
    remove_degenerate_vertices_in_place(trapezoid);
    if (trapezoid.size() < 3 || joined.size() < 3 || !(area > 0.0)) return;
    const int other = left.ring == hole_ring_ ? right.ring : left.ring;
    SlabCut found{quality, area, {}};
    Region& rest = found.pieces.second;
    if (other == 0) {
      if (!(signed_area(joined) > 0.0)) return;
      rest.outer = std::move(joined);
    } else {
      if (!(signed_area(joined) < 0.0)) return;
      rest.outer = region_.outer;
    }
    for (int r = 1; r <= static_cast<int>(region_.holes.size()); ++r) {
      if (r != hole_ring_ && r != other) rest.holes.push_back(ring_of(region_, r));
    }
    if (other != 0) rest.holes.push_back(std::move(joined));
    // The pieces partition the region (up to the new vertices' rounding).
    const double whole = region_area(region_);
    if (!(std::abs(region_area(rest) + area - whole) <= 1e-9 * whole)) return;
    found.pieces.first.outer = std::move(trapezoid);
    best = std::move(found);
  }

  // The cut at height y between the two edges neither passes through nor grazes a vertex (see
  // Graze), and its ends are the edges' own vertices or new ones clear of them (a new vertex
  // within rounding of an old one would leave a sliver).
  bool clear_at(double y, Vec2 a, Vec2 b, Vec2 c, Vec2 d) const {
    const Vec2 from = vertex_at_height(a, b, y), to = vertex_at_height(c, d, y);
    const Graze cut(from, to);
    const double apart = 2.0 * sliver_width(to.x - from.x);
    auto clear_of_ends = [&](Vec2 end, Vec2 p, Vec2 q) {
      return end == p || end == q || (distance(end, p) > apart && distance(end, q) > apart);
    };
    if (!clear_of_ends(from, a, b) || !clear_of_ends(to, c, d)) return false;
    bool clear = true;
    for_each_vertex([&](Vec2 p) {
      if (p != from && p != to && cut.by(p)) clear = false;
    });
    return clear;
  }

  const Region& region_;
  const int hole_ring_;
  std::vector<double> levels_;  // every vertex height, ascending, once
  double separation_ = 0.0;
  std::vector<Crossing> crossings_;
};

// The region mirrored across the diagonal (x and y swapped) with its rings reversed, so that they
// keep their orientation: the vertical slabs of a region are the horizontal ones of its mirror.
Region mirrored(const Region& region) {
  auto mirror = [](const Ring& ring) {
    Ring out(ring.rbegin(), ring.rend());
    for (Vec2& p : out) std::swap(p.x, p.y);
    return out;
  };
  Region out{mirror(region.outer), {}};
  for (const Ring& hole : region.holes) out.holes.push_back(mirror(hole));
  return out;
}

}  // namespace

std::optional<std::pair<Region, Region>> cut_across_slab(const Region& region, std::size_t h) {
  std::optional<SlabCut> across, along;
  SlabCutter(region, h).cut(across);
  const Region mirror = mirrored(region);
  SlabCutter(mirror, h).cut(along);
  if (along && (!across || along->quality > across->quality ||
                (along->quality == across->quality && along->area > across->area))) {
    std::pair<Region, Region> pieces{mirrored(along->pieces.first), mirrored(along->pieces.second)};
    return pieces;
  }
  if (across) return std::move(across->pieces);
  return std::nullopt;
}

}  // namespace hullcook::detail
