// HullFitter's reduction of a hull to at most max_verts vertices: the fewest of its edge lines
// whose polygon stays within the bound of the outline (see reduce_vertex_count).
#include "hull_fitter.h"

#include "hullcook/core/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace hullcook {

namespace {

// Where the lines of hull edges i and j meet; t: how far along edge i, in its lengths.
Vec2 line_apex(const Ring& hull, std::size_t i, std::size_t j, double* t_out = nullptr) {
  const std::size_t m = hull.size();
  Vec2 a = hull[i], b = hull[(i + 1) % m], c = hull[j], d = hull[(j + 1) % m];
  Vec2 first = b - a, second = d - c;
  double t = cross(c - a, second) / cross(first, second);
  if (t_out) *t_out = t;
  return a + first * t;
}

}  // namespace

// Keeps as few of the hull's edge lines as possible (at most max_verts) so that the polygon
// they bound stays within bound of the outline. From every starting edge, each kept line is
// followed by the farthest line whose meeting point with it is still within bound: greedy
// farthest reach is optimal along a chain, and trying every start closes the cycle. The
// polygons are then proven (area and component depths) smallest first.
std::optional<Ring> HullFitter::reduce_vertex_count(const Ring& hull) {
  inferring_ = false;
  if (!may_close_within_max_verts(hull)) return std::nullopt;
  // Inferred reaches give the exact scans' polygons wherever the argument holds, and the polygon
  // kept has its apexes checked (a pocket under a bridging hull edge, or rounding without a weld,
  // can break the argument: the polygon kept may then differ, but is valid; a search that keeps
  // none is not repeated exactly, so such a piece may be cut where the exact scans reduce it). A
  // rough disc's cap of 2,500 vertices took 100 ms to fit, nearly all of it in the scans of its
  // hull's 250 lines, each reaching about 30 on.
  if (infer_reaches_) {
    inferring_ = true;
    inferred_ = false;
    bool refuted = false;
    std::optional<Ring> polygon = reduce_by_chains(hull, &refuted);
    inferring_ = false;
    if (!refuted) return polygon;
    // An inferred apex failed its check: the exact scans decide, from the start.
    reach_known_.assign(hull.size(), 1);
    beyond_after_known_.assign(hull.size(), 0);
  }
  return reduce_by_chains(hull, nullptr);
}

std::optional<Ring> HullFitter::reduce_by_chains(const Ring& hull, bool* refuted) {
  const std::size_t m = hull.size();
  // The chains that close, one after the other in closed_, each a span of it (a vector per chain
  // was a tenth of the allocations of a cook).
  closed_.clear();
  closed_spans_.clear();
  // One scratch chain for every start: most starts do not close within max_verts.
  std::vector<std::size_t>& chain = chain_;
  for (std::size_t start = 0; start < m; ++start) {
    chain.assign(1, start);
    std::size_t current = start;
    bool is_closed = false;
    while (chain.size() <= limits_.max_verts) {
      const std::size_t farthest = current + reach_from(hull, current % m, start + m - current);
      if (farthest == start + m) {
        is_closed = true;
        break;
      }
      chain.push_back(farthest);
      current = farthest;
    }
    if (!is_closed || chain.size() > limits_.max_verts || chain.size() < 3) continue;
    for (std::size_t& k : chain) k %= m;
    // The same polygon comes from several starts: each starts at its least index, to compare.
    std::rotate(chain.begin(), std::min_element(chain.begin(), chain.end()), chain.end());
    closed_spans_.push_back({closed_.size(), chain.size()});
    closed_.insert(closed_.end(), chain.begin(), chain.end());
  }
  // Each polygon is tried once, fewest vertices first.
  std::stable_sort(closed_spans_.begin(), closed_spans_.end(),
                   [](const auto& a, const auto& b) { return a.second < b.second; });
  auto same = [&](const std::pair<std::size_t, std::size_t>& a,
                  const std::pair<std::size_t, std::size_t>& b) {
    return a.second == b.second &&
           std::equal(closed_.begin() + a.first, closed_.begin() + a.first + a.second,
                      closed_.begin() + b.first);
  };
  for (std::size_t c = 0; c < closed_spans_.size(); ++c) {
    if (std::any_of(closed_spans_.begin(), closed_spans_.begin() + c,
                    [&](const auto& seen) { return same(seen, closed_spans_[c]); })) {
      continue;
    }
    const std::size_t* kept = closed_.data() + closed_spans_[c].first;
    const std::size_t size = closed_spans_[c].second;
    Ring polygon;
    polygon.reserve(size);
    for (std::size_t k = 0; k < size; ++k) {
      std::size_t i = kept[k], j = kept[(k + 1) % size];
      polygon.push_back((i + 1) % m == j ? hull[j] : line_apex(hull, i, j));
    }
    // The new edges are the stretches apex_within checked.
    if (holds_component(polygon) && (edges_suffice_ || growth_within(polygon, hull))) {
      if (inferring_ && inferred_) {
        for (std::size_t k = 0; k < size; ++k) {
          const std::size_t i = kept[k], j = kept[(k + 1) % size];
          if ((i + 1) % m != j && !apex_within(hull, i, j)) {
            *refuted = true;
            return std::nullopt;
          }
        }
      }
      return polygon;
    }
  }
  return std::nullopt;
}

// The greedy chain from edge 0, one line past max_verts: a chain of k lines from any start
// means one of at most k + 1 from edge 0 (its lines stay ahead of that chain's, and one more
// wraps round). When that one needs more, no start closes within max_verts. The argument takes
// two lines that meet within bound to stay so when either moves towards the other, as the scans
// already take it for the later one (they stop at the first line beyond); a component pocket
// that breaks it can only make the piece halved where it could have been reduced. Rounding
// could break it among nearly parallel lines: the hull is mended first (no turn below a tenth of
// the weld remains), and without a weld the bound is used only where every edge and turn is
// above a millionth of the hull's size. Also prepares the scans for reduce_vertex_count.
bool HullFitter::may_close_within_max_verts(const Ring& hull) {
  const std::size_t m = hull.size();
  // What is known of the lines after each edge line: a prefix of them (the scans stop at the
  // first beyond), so O(m) memory where an m x m table took 64 MB for a 2000-vertex hull.
  reach_known_.assign(m, 1);
  beyond_after_known_.assign(m, 0);
  // The hull holds the component but for rounding (holds_component lets a vertex lie outside by
  // 1e-12 of the hull's size): clearly_beyond allows twice that.
  outside_by_rounding_ = 2e-12 * largest_coordinate(hull);
  corner_reach_.resize(m);
  for (std::size_t k = 0; k < m; ++k) corner_reach_[k] = reach_.distance(hull[k], bound_);
  // Without a weld, edges or turns too small for their lines' meeting points to be computed
  // reliably may remain, where the argument can fail in rounding: then every start is tried.
  if (!(limits_.weld > 0)) {
    const double least = 1e-6 * largest_coordinate(hull);
    for (std::size_t k = 0; k < m; ++k) {
      if (!(glm::length(hull[(k + 1) % m] - hull[k]) >= least && turn_height(hull, k) >= least)) {
        return true;
      }
    }
  }
  std::size_t current = 0, lines = 1;
  while (lines <= limits_.max_verts + 1) {
    current += reach_from(hull, current, m - current);
    if (current == m) return true;
    ++lines;
  }
  return false;
}

// How many lines on from edge line i (at most limit) the scan reaches: the largest d <= limit
// such that the lines i + 2 ... i + d each meet line i within bound (1 when none does).
std::size_t HullFitter::reach_from(const Ring& hull, std::size_t i, std::size_t limit) {
  const std::size_t m = hull.size();
  std::size_t& known = reach_known_[i];
  // The lines that the nearest scan before line i reaches past it meet line i within bound too,
  // by the argument of may_close_within_max_verts: a line moved towards another meets it nearer.
  if (inferring_ && known == 1 && !beyond_after_known_[i]) {
    for (std::size_t back = 1; back < std::min<std::size_t>(m, 64); ++back) {
      const std::size_t k = (i + m - back) % m;
      if (reach_known_[k] == 1 && !beyond_after_known_[k]) continue;  // not scanned
      if (reach_known_[k] > back + 1) {
        known = reach_known_[k] - back;
        inferred_ = true;
      }
      break;
    }
  }
  while (known < limit && !beyond_after_known_[i]) {
    if (apex_within(hull, i, (i + known + 1) % m)) {
      ++known;
    } else {
      beyond_after_known_[i] = 1;
    }
  }
  return std::min(known, limit);
}

// Whether the lines of edges i and j (j after i, counter-clockwise, not adjacent) meet at a
// point within bound of the outline, and the stretches of those lines that would become new
// edges stay within bound.
bool HullFitter::apex_within(const Ring& hull, std::size_t i, std::size_t j) const {
  ++apex_tests_;
  std::size_t m = hull.size();
  Vec2 a = hull[i], b = hull[(i + 1) % m], c = hull[j], d = hull[(j + 1) % m];
  if (!(cross(b - a, d - c) > 0)) return false;
  double t = 0;
  const Vec2 apex = line_apex(hull, i, j, &t);
  const Vec2 second = d - c;
  bool ahead = t >= 1 && glm::dot(apex - c, second) <= 0 && std::isfinite(t) &&
               (!limits_.keep_inside || limits_.keep_inside->holds(apex));
  std::optional<OutlineDistance::EdgeSpan> nearest;
  OutlineDistance::EdgeSpan found{};
  double at_apex = bound_ + 1;
  if (ahead && !clearly_beyond(hull, i, j, apex)) {
    at_apex = reach_.distance(apex, bound_, &found);
    if (at_apex > 0 && at_apex <= bound_) nearest = found;
  }
  // A segment needs no closer look when distance, 1-Lipschitz, cannot exceed bound between
  // its ends, or when both ends lie within bound of the edge nearest the apex (the distance
  // to one edge is convex along the segment), or of the whole outline when it is convex (so is
  // the distance to it: a convex cap's scans measured hundreds of capsules per apex, which made
  // slicing a disc of thousands of vertices superlinear). There the ends are taken a margin
  // within, for the rounding of their distances (segment_within's margin), so that the answer
  // is segment_within's.
  auto within = [&](Vec2 corner, double at_corner) {
    if ((at_corner + at_apex + glm::length(apex - corner)) / 2 <= bound_ ||
        (nearest && point_segment_distance(corner, nearest->a, nearest->b) <= bound_)) {
      return true;
    }
    if (reach_.is_convex()) {
      const double margin = 1e-9 * bound_ + 1e-15 * (std::abs(corner.x) + std::abs(corner.y) +
                                                     std::abs(apex.x) + std::abs(apex.y));
      if (std::max(at_corner, at_apex) <= bound_ - margin) return true;
    }
    return reach_.segment_within(corner, apex, bound_);
  };
  return at_apex <= bound_ && within(b, corner_reach_[(i + 1) % m]) && within(c, corner_reach_[j]);
}

// Whether the apex of edges i and j lies, by its distance beyond the line of an edge it cuts off,
// further than bound from the component: the hull being reduced holds the component, so that
// distance bounds the distance to it from below. Most apexes that fail are settled here, without
// the outline query (a point-in-outline ray cast and a search of cells). The margins keep the
// answer the query's wherever the two round differently, and allow for component vertices that
// rounding leaves just outside the hull.
bool HullFitter::clearly_beyond(const Ring& hull, std::size_t i, std::size_t j, Vec2 apex) const {
  if (!reach_is_component_) return false;
  const std::size_t m = hull.size();
  for (std::size_t k = (i + 1) % m; k != j; k = (k + 1) % m) {
    const Vec2 from = hull[k], edge = hull[(k + 1) % m] - from, offset = apex - from;
    // |edge| times the apex's distance beyond the edge's line (the hull is counter-clockwise).
    const double outward = -cross(edge, offset);
    if (outward > glm::length(edge) *
                      (bound_ * (1 + 1e-6) + 1e-9 * glm::length(offset) + outside_by_rounding_)) {
      return true;
    }
  }
  return false;
}

}  // namespace hullcook
