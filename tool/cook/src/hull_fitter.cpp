#include "hull_fitter.h"
#include "nearest_edges.h"

#include "mend_queue.h"

#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <tuple>
#include <unordered_map>

namespace hullcook {
namespace {

// The square of the distance from p to the ring's boundary, and the start of the first edge at
// that distance.
std::pair<double, Vec2> squared_distance_and_edge(Vec2 p, const Ring& ring) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t at = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const double squared = point_segment_distance_squared(p, ring[i], ring[i + 1 == n ? 0 : i + 1]);
    if (squared < best) best = squared, at = i;
  }
  return {best, ring.empty() ? Vec2{} : ring[at]};
}

double distance_to_ring(Vec2 p, const Ring& ring) {
  return std::sqrt(squared_distance_and_edge(p, ring).first);
}

template <typename Visit>
void for_each_vertex(const Region& region, Visit visit) {
  for (Vec2 v : region.outer) visit(v);
  for (const Ring& hole : region.holes) {
    for (Vec2 v : hole) visit(v);
  }
}

// True when the ring turns left at every vertex (exactly) and winds once around: a simple convex
// polygon, inside which is every point left of all its edges.
bool winds_once_left(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  double turning = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 before = ring[i == 0 ? n - 1 : i - 1], at = ring[i], after = ring[(i + 1) % n];
    if (orientation(before, at, after) <= 0) return false;
    turning += std::atan2(cross(at - before, after - at), glm::dot(at - before, after - at));
  }
  return turning < 3 * std::acos(-1.0);  // 2π once, 4π or more for a star
}

// True when p lies left of every edge of the ring by more than a floating-point orientation's
// rounding can reach (Shewchuk's first error bound, taken three times over).
bool clearly_left_of_every_edge(const Ring& ring, Vec2 p) {
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 a = ring[i], b = ring[i + 1 == n ? 0 : i + 1];
    const double left = (a.x - p.x) * (b.y - p.y), right = (a.y - p.y) * (b.x - p.x);
    if (!(left - right > 1e-15 * (std::abs(left) + std::abs(right)))) return false;
  }
  return true;
}

Ring without_edge(const Ring& hull, std::size_t i, Vec2 apex) {
  std::size_t n = hull.size();
  Ring grown;
  grown.reserve(n - 1);
  for (std::size_t k = 0; k < n; ++k) {
    if (k == i) {
      grown.push_back(apex);
    } else if (k != (i + 1) % n) {
      grown.push_back(hull[k]);
    }
  }
  return grown;
}

}  // namespace

std::optional<Vec2> removed_edge_apex(const Ring& hull, std::size_t i) {
  std::size_t n = hull.size();
  if (n < 4) return std::nullopt;
  Vec2 a = hull[i], b = hull[(i + 1) % n];
  Vec2 before = a - hull[(i + n - 1) % n];
  Vec2 after = hull[(i + 2) % n] - b;
  double denominator = cross(before, after);
  if (!(denominator > 0)) return std::nullopt;
  double t = cross(b - a, after) / denominator;
  if (!(t >= 0) || !std::isfinite(t)) return std::nullopt;
  return a + before * t;
}

double turn_height(const Ring& ring, std::size_t i) {
  std::size_t n = ring.size();
  Vec2 previous = ring[(i + n - 1) % n];
  Vec2 next = ring[(i + 1) % n];
  Vec2 base = next - previous;
  double length = glm::length(base);
  if (length == 0) return 0;
  return cross(base, ring[i] - previous) * -1.0 / length;
}

std::vector<std::size_t> edges_to_mend(const Ring& hull, const EngineLimits& limits) {
  std::size_t n = hull.size();
  // Scratch, reused: the fitter asks this of every hull it grows.
  thread_local std::vector<char> wanted;
  wanted.assign(n, 0);
  auto want = [&](std::size_t edge) { wanted[edge % n] = 1; };
  double collinear = limits.least_turn();
  for (std::size_t i = 0; i < n; ++i) {
    // A turn too small to measure (0 or -0 where the exact turn is a left one) breaks the limits
    // whatever the weld, so it is mended at weld 0 too.
    const double height = turn_height(hull, i);
    if (height < collinear || !(height > 0)) {
      want(i + n - 1);
      want(i);
    }
  }
  // Pairs closer than the weld, found in order along an axis (every pair was measured: quadratic
  // in hulls of thousands of vertices). Only vertices within the weld along it can be that close.
  // The axis is at an angle of 1 radian, so that no side along x, y or a small-integer slope (a
  // traced outline's) puts many vertices at one abscissa; the window allows for the rounding of
  // the abscissas and for distances whose squares underflow.
  if (limits.weld > 0) {
    const Vec2 axis{0.54030230586813977, 0.84147098480789650};
    thread_local std::vector<std::pair<double, std::size_t>> along;
    along.resize(n);
    double scale = 0;
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i) {
      along[i] = {glm::dot(hull[i], axis), i};
      // The abscissa too: near the largest double it may overflow where the coordinates do not.
      finite = finite && std::isfinite(along[i].first);
      scale = std::max({scale, std::abs(hull[i].x), std::abs(hull[i].y)});
    }
    if (finite) std::sort(along.begin(), along.end());
    // Not finite: every pair, in index order.
    const double window = finite ? 2 * limits.weld_distance() + 1e-12 * scale + 1e-140
                                 : std::numeric_limits<double>::infinity();
    for (std::size_t p = 0; p < n; ++p) {
      const std::size_t i = along[p].second;
      for (std::size_t q = p + 1; q < n && !(along[q].first - along[p].first > window); ++q) {
        const std::size_t j = along[q].second;
        if (glm::length(hull[i] - hull[j]) < limits.weld_distance()) {
          want(i + n - 1);
          want(i);
          want(j + n - 1);
          want(j);
        }
      }
    }
  }
  std::vector<std::size_t> edges;
  for (std::size_t i = 0; i < n; ++i) {
    if (wanted[i]) edges.push_back(i);
  }
  return edges;
}

bool pockets_within(const Region& component, const Ring& hull, double bound) {
  const Ring& ring = component.outer;
  std::size_t n = ring.size();
  if (!component.holes.empty() || n < 3 || hull.size() < 3) return false;
  auto less = [](Vec2 p, Vec2 q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); };
  Ring corners = hull;
  std::sort(corners.begin(), corners.end(), less);
  std::vector<bool> on_hull(n);
  std::size_t first = n;
  for (std::size_t i = 0; i < n; ++i) {
    on_hull[i] = std::binary_search(corners.begin(), corners.end(), ring[i], less);
    if (on_hull[i] && first == n) first = i;
  }
  if (first == n) return false;
  // The ring meets the hull's vertices in order; between two of them lies a pocket.
  std::size_t bridge_start = first;
  for (std::size_t step = 1; step <= n; ++step) {
    std::size_t i = (first + step) % n;
    if (!on_hull[i]) continue;
    Vec2 a = ring[bridge_start], edge = ring[i] - a;
    double length = glm::length(edge);
    for (std::size_t k = (bridge_start + 1) % n; k != i; k = (k + 1) % n) {
      if (!(length > 0) || std::abs(cross(edge, ring[k] - a)) / length > bound) return false;
    }
    bridge_start = i;
  }
  return true;
}

std::vector<double> allowed_depths(const Region& component, const Ring& hull, double bound) {
  std::vector<double> allowed;
  // Most vertices lie on the hull or in shallow pockets: one edge within the bound settles them.
  // Below this square the distance's square root is below the bound whatever the rounding.
  const double settled = bound * bound * (1 - 1e-14);
  const std::size_t m = hull.size();
  std::size_t hint = 0;  // the edge that settled the last vertex; its neighbours come next
  for_each_vertex(component, [&](Vec2 v) {
    double least = std::numeric_limits<double>::infinity();  // as distance_to_ring's
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t i = hint + k < m ? hint + k : hint + k - m;
      least =
          std::min(least, point_segment_distance_squared(v, hull[i], hull[i + 1 == m ? 0 : i + 1]));
      if (least <= settled) {
        hint = i;
        allowed.push_back(bound);
        return;
      }
    }
    allowed.push_back(std::max(bound, std::sqrt(least)));
  });
  return allowed;
}

bool HullFitter::growth_within(const Ring& grown, const Ring& known) const {
  return edges_suffice_ ? reach_.new_edges_within(grown, known, bound_)
                        : reach_.growth_within(grown, known, bound_);
}

bool HullFitter::holds_component(const Ring& hull) const {
  std::size_t k = 0;
  bool ok = true;
  // A vertex on an edge that was extended may fall outside by rounding; seal() mends that.
  double rounding = 1e-12 * largest_coordinate(hull);
  for_each_vertex(component_, [&](Vec2 v) {
    if (!ok) return;
    double depth = distance_to_ring(v, hull);
    if (depth > allowed_[k] * (1 + 1e-12) ||
        (depth > rounding && locate_point(hull, v) == Location::outside)) {
      ok = false;
    }
    ++k;
  });
  return ok;
}

bool HullFitter::edges_within_depth(const Ring& hull) const {
  // In the component's own convex hull an edge lies under one bridge, and its depth below that
  // bridge's line is linear: no deeper than its ends.
  const Ring& outer = component_.outer;
  if (std::all_of(hull.begin(), hull.end(), [&](Vec2 v) {
        return std::find(outer.begin(), outer.end(), v) != outer.end();
      })) {
    return true;
  }
  // Inside a convex hull a point's depth is its least distance to an edge's line: along a
  // component edge, the least of linear functions, concave, so its top may lie between the ends
  // (where the hull grew over the edge's middle). The top is at an end or where two lines cross.
  std::size_t m = hull.size();
  std::vector<Vec2> normals(m);
  for (std::size_t k = 0; k < m; ++k) {
    Vec2 edge = hull[(k + 1) % m] - hull[k];
    normals[k] = Vec2{-edge.y, edge.x} / glm::length(edge);
  }
  auto depth_of = [&](Vec2 p) {
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < m; ++k) least = std::min(least, glm::dot(normals[k], p - hull[k]));
    return least;
  };
  std::vector<double> at_start(m), slope(m);
  double rounding =
      1e-12 * largest_coordinate(hull);  // an edge on the hull's boundary is at depth 0
  std::size_t index = 0;
  bool ok = true;
  auto check_ring = [&](const Ring& ring) {
    std::size_t n = ring.size(), first = index;
    double du = n > 0 ? depth_of(ring[0]) : 0;
    for (std::size_t i = 0; i < n && ok; ++i) {
      Vec2 u = ring[i], w = ring[(i + 1) % n];
      double dw = depth_of(w);
      double limit =
          std::max(allowed_[first + i], allowed_[first + (i + 1) % n]) * (1 + 1e-12) + rounding;
      // Depth is 1-Lipschitz: the edge cannot reach deeper than this.
      bool shallow = (du + dw + glm::length(w - u)) / 2 <= limit;
      du = dw;
      if (shallow) continue;
      for (std::size_t k = 0; k < m; ++k) {
        at_start[k] = glm::dot(normals[k], u - hull[k]);
        slope[k] = glm::dot(normals[k], w - u);
      }
      auto depth = [&](double t) {
        double least = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < m; ++k) least = std::min(least, at_start[k] + slope[k] * t);
        return least;
      };
      double deepest = std::max(depth(0), depth(1));
      for (std::size_t k = 0; k < m; ++k) {
        for (std::size_t l = k + 1; l < m; ++l) {
          if (slope[k] == slope[l]) continue;
          double t = (at_start[l] - at_start[k]) / (slope[k] - slope[l]);
          if (t > 0 && t < 1) deepest = std::max(deepest, depth(t));
        }
      }
      ok = deepest <= limit;
    }
    index += n;
  };
  check_ring(component_.outer);
  for (const Ring& hole : component_.holes) check_ring(hole);
  return ok;
}

std::optional<Ring> HullFitter::seal(Ring hull) const {
  std::size_t n = hull.size();
  double size = largest_coordinate(hull);
  // An edge a vertex is outside of is moved outward parallel to itself: its ends slide along
  // their other edges, whose lines (proven within bound) stay where they were.
  for (double shift = 0x1p-52 * size; shift <= 0x1p-30 * size; shift *= 2) {
    std::vector<bool> push(n, false);
    bool outside = false;
    // Most vertices are well inside: the exact location is taken only near the boundary.
    const bool convex = winds_once_left(hull);
    for_each_vertex(component_, [&](Vec2 v) {
      if (convex && clearly_left_of_every_edge(hull, v)) return;
      if (std::find(hull.begin(), hull.end(), v) != hull.end()) return;  // a corner: on it
      if (locate_point(hull, v) != Location::outside) return;
      outside = true;
      for (std::size_t i = 0; i < n; ++i) {
        if (orientation(hull[i], hull[(i + 1) % n], v) < 0) push[i] = true;
      }
    });
    if (!outside) return hull;
    for (std::size_t i = 0; i < n; ++i) {
      if (!push[i]) continue;
      Vec2 before = hull[(i + n - 1) % n], &from = hull[i], &to = hull[(i + 1) % n];
      Vec2 after = hull[(i + 2) % n];
      Vec2 edge = to - from;
      Vec2 outward = Vec2{edge.y, -edge.x} / glm::length(edge);
      double in_from = glm::dot(from - before, outward), in_to = glm::dot(to - after, outward);
      if (!(in_from > 0) || !(in_to > 0)) return std::nullopt;
      from += (from - before) * (shift / in_from);
      to += (to - after) * (shift / in_to);
    }
  }
  return std::nullopt;
}

bool HullFitter::too_small(const Ring& hull) const {
  const double weld = limits_.weld_distance();
  return hull.size() < 3 || std::abs(signed_area(hull)) < 0.5 * weld * weld;
}

std::optional<Ring> HullFitter::fit(Ring hull) {
  const Ring given = hull;
  // Reducing the vertex count creates new apexes, which may need welding again.
  for (int round = 0; round < 4; ++round) {
    std::optional<Ring> mended = mend_local_violations(std::move(hull));
    if (!mended) return std::nullopt;
    hull = std::move(*mended);
    if (limits_.max_verts == 0 || hull.size() <= limits_.max_verts) {
      // The hull given holds the component exactly (a convex hull of its vertices and more).
      if (hull == given) {
        if (!hull_meets_limits(hull, limits_) || !edges_within_depth(hull)) return std::nullopt;
        return hull;
      }
      std::optional<Ring> sealed = seal(std::move(hull));
      if (!sealed || !hull_meets_limits(*sealed, limits_) || !edges_within_depth(*sealed)) {
        return std::nullopt;
      }
      return sealed;
    }
    std::optional<Ring> reduced = reduce_vertex_count(hull);
    if (!reduced) return std::nullopt;
    hull = std::move(*reduced);
  }
  return std::nullopt;
}

// Vertices are found by the coordinates of their edge's start, as holds_component_after compares
// them (so -0 and 0 are one key): each removal then visits only the vertices of the three edges
// it changes. Visiting every vertex per candidate made mending a hull of thousands of nearly
// collinear vertices quadratic.
class HullFitter::DepthIndex {
 public:
  DepthIndex(const Region& component, std::vector<VertexDepth> depths)
      : depths_(std::move(depths)), position_(depths_.size()) {
    vertices_.reserve(depths_.size());
    for_each_vertex(component, [&](Vec2 v) { vertices_.push_back(v); });
    for (std::size_t k = 0; k < depths_.size(); ++k) {
      insert(k);
      if (!depths_[k].not_outside) by_rounding_.push_back(static_cast<std::uint32_t>(k));
    }
  }

  Vec2 vertex(std::size_t k) const { return vertices_[k]; }
  const VertexDepth& depth(std::size_t k) const { return depths_[k]; }

  // Calls visit(k) once for each vertex that may lie outside the hull by rounding, and for each
  // other vertex whose edge starts at one of starts; stops when visit returns false.
  template <typename Visit>
  bool for_each_near(const std::array<Vec2, 3>& starts, Visit visit) const {
    for (std::uint32_t k : by_rounding_) {
      if (!depths_[k].not_outside && !visit(k)) return false;
    }
    for (std::size_t s = 0; s < starts.size(); ++s) {
      if (std::find(starts.begin(), starts.begin() + s, starts[s]) != starts.begin() + s) continue;
      const auto bucket = by_start_.find(key(starts[s]));
      if (bucket == by_start_.end()) continue;
      for (std::uint32_t k : bucket->second) {
        if (depths_[k].not_outside && !visit(k)) return false;
      }
    }
    return true;
  }

  void update(std::size_t k, const VertexDepth& depth) {
    const bool moved = !(depths_[k].edge_start == depth.edge_start);
    if (moved) erase(k);
    depths_[k] = depth;  // a vertex once known not outside stays so (by_rounding_ skips it)
    if (moved) insert(k);
  }

 private:
  using Key = std::pair<std::uint64_t, std::uint64_t>;
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      return std::hash<std::uint64_t>{}(key.first * 0x9E3779B97F4A7C15ull ^ key.second);
    }
  };
  static Key key(Vec2 p) {
    Key bits;
    const double x = p.x + 0.0, y = p.y + 0.0;  // -0 + 0 is 0
    std::memcpy(&bits.first, &x, sizeof x);
    std::memcpy(&bits.second, &y, sizeof y);
    return bits;
  }
  void insert(std::size_t k) {
    std::vector<std::uint32_t>& bucket = by_start_[key(depths_[k].edge_start)];
    position_[k] = static_cast<std::uint32_t>(bucket.size());
    bucket.push_back(static_cast<std::uint32_t>(k));
  }
  void erase(std::size_t k) {
    std::vector<std::uint32_t>& bucket = by_start_[key(depths_[k].edge_start)];
    const std::uint32_t last = bucket.back();
    bucket[position_[k]] = last;
    position_[last] = position_[k];
    bucket.pop_back();
  }

  std::vector<VertexDepth> depths_;
  std::vector<Vec2> vertices_;
  std::vector<std::uint32_t> position_;  // per vertex: where it is in its bucket
  std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> by_start_;
  std::vector<std::uint32_t> by_rounding_;  // not known not to lie outside, when indexed
};

// Removes, one at a time, the cheapest edge that mends a weld or collinearity violation.
std::optional<Ring> HullFitter::mend_local_violations(Ring hull) const {
  // A candidate's checks look only at what removing its edge changes (see holds_component_after
  // and OutlineDistance::apex_growth_within) once every vertex is known to pass in the hull:
  // mending a hull of thousands of nearly collinear vertices one edge at a time, each candidate
  // checked against every vertex and edge, took minutes.
  std::optional<DepthIndex> depths;
  std::vector<std::pair<std::size_t, VertexDepth>> changed;
  bool local = false, measured = false;
  // The error of each apex, by its coordinates: most apexes stay the same from one removal to
  // the next (an apex depends on the four vertices round its edge).
  std::map<std::pair<double, double>, double> errors;
  auto error_of = [&](Vec2 apex) {
    if (!std::isfinite(apex.x) || !std::isfinite(apex.y)) return reach_.distance(apex, bound_);
    const auto [known, added] = errors.try_emplace({apex.x, apex.y}, 0.0);
    if (added) known->second = reach_.distance(apex, bound_);
    return known->second;
  };
  // The edges to mend and the candidates among them, kept up to date for a large hull (else
  // measured again after each removal: cheaper for a few dozen vertices, and for coordinates too
  // large for the queue's grid).
  MendQueue queue(limits_, bound_, error_of);
  const bool queued = hull.size() >= queued_from_ && queue.start(hull);
  struct Candidate {
    double error;
    std::size_t edge;
    Vec2 apex;
  };
  std::vector<Candidate> scanned;
  // Removing an edge only grows the hull: once its area is twice too_small's, by more than the
  // sum's rounding can take, it stays above (summing it after each removal made mending a long
  // hull quadratic). A sliver far longer than the weld, whose sum is all rounding, is summed on.
  bool large_enough = false;
  while (true) {
    if (hull.size() < 3 || (!large_enough && too_small(hull))) return std::nullopt;
    if (!large_enough) {
      const double weld = limits_.weld_distance();
      double twice = 0, magnitude = 0, reach = 0;
      for (std::size_t i = 1; i + 1 < hull.size(); ++i) {
        const Vec2 a = hull[i] - hull[0], b = hull[i + 1] - hull[0];
        twice += a.x * b.y - a.y * b.x;
        magnitude += std::abs(a.x * b.y) + std::abs(a.y * b.x);
        reach = std::max({reach, std::abs(a.x) + std::abs(a.y), std::abs(b.x) + std::abs(b.y)});
      }
      // Without a weld, too_small asks only for 3 vertices.
      // The sum's worst rounding is (n + 2) units in the last place of the magnitude; later
      // hulls, grown within τ from this one, have about its magnitude.
      const double n = double(hull.size());
      large_enough = weld == 0 || (std::abs(twice) >= 2 * weld * weld &&
                                   (n + 2) * 0x1p-52 * magnitude <= 0.25 * weld * weld);
      // Or, where the bound is of the component (which this hull holds), the area is so far
      // above that no rounding brings a later hull's back under: a later hull's vertices are
      // this one's and apexes within bound of the component, so within reach + 2 bound of
      // hull[0] in |x| + |y| (with slack for the component's rounding), and its sum's terms are
      // below 4 (reach + 2 bound)^2 each (taken twice over below). The first test alone failed
      // wherever n times the magnitude outgrew the weld's square (a disc's cap of thousands of
      // vertices at the default weld): the area was summed again after every removal, which
      // made mending it quadratic.
      if (!large_enough && reach_is_component_) {
        const double spread = reach * (1 + 1e-9) + 2 * bound_;
        const double later = 8 * n * spread * spread;
        large_enough = twice >= 2 * weld * weld + 2 * (n + 2) * 0x1p-52 * (magnitude + later);
      }
    }
    std::vector<std::size_t> edges;
    if (!queued) edges = edges_to_mend(hull, limits_);
    if (queued ? queue.wanted_count() == 0 : edges.empty()) return hull;
    if (!measured) {
      std::vector<VertexDepth> measured_depths;
      local = !whole_hull_checks_ && measure_depths(hull, measured_depths), measured = true;
      if (local) depths.emplace(component_, std::move(measured_depths));
    }
    scanned.clear();
    for (std::size_t edge : edges) {
      std::optional<Vec2> apex = removed_edge_apex(hull, edge);
      if (!apex) continue;
      const double error = error_of(*apex);
      if (error <= bound_) scanned.push_back({error, edge, *apex});
    }
    std::sort(scanned.begin(), scanned.end(), [](const Candidate& a, const Candidate& b) {
      return std::tie(a.error, a.edge) < std::tie(b.error, b.edge);
    });
    // Tries a candidate; true when it passed and hull is without its edge.
    auto try_removing = [&](std::size_t edge, Vec2 at) {
      // The hull without the edge is built only when a check needs it whole: most look only
      // round the apex, and a copy per candidate made mending a long hull quadratic.
      std::optional<Ring> whole;
      const std::function<const Ring&()> next = [&]() -> const Ring& {
        if (!whole) whole = without_edge(hull, edge, at);
        return *whole;
      };
      const bool passes =
          local ? holds_component_after(at, next, hull, edge, *depths, changed) &&
                      reach_.apex_growth_within(at, next, hull, edge, !edges_suffice_, bound_)
                : holds_component(next()) && growth_within(next(), hull);
      if (!passes) return false;
      if (local) {
        for (const auto& [k, depth] : changed) depths->update(k, depth);
      }
      // As without_edge: the apex where the edge started, or last when the edge closed the ring.
      const std::size_t n = hull.size();
      hull[edge] = at;
      hull.erase(hull.begin() + static_cast<std::ptrdiff_t>((edge + 1) % n));
      if (queued) queue.remove_edge(edge, hull);
      return true;
    };
    bool grown = false;
    if (queued && hull.size() >= 4) {
      for (const MendQueue::Candidate& candidate : queue.candidates()) {
        if (try_removing(queue.index_of(candidate.id), queue.apex_of(candidate.id))) {
          grown = true;
          break;
        }
      }
    }
    for (const Candidate& candidate : scanned) {
      if (try_removing(candidate.edge, candidate.apex)) {
        grown = true;
        break;
      }
    }
    if (!grown) return std::nullopt;
  }
}

bool HullFitter::measure_depths(const Ring& hull, std::vector<VertexDepth>& depths) const {
  depths.clear();
  const double rounding = 1e-12 * largest_coordinate(hull);
  bool ok = true;
  std::size_t k = 0;
  const NearestEdges nearest_edge(hull);
  // locate_point's answers by bands of the hull's edges, built at the first vertex located: a
  // scan of the whole hull for each vertex not on it made measuring a rough disc's cap of
  // thousands of vertices, in a hull of hundreds, quadratic.
  std::optional<RingLocator> locator;
  std::size_t edge = 0;  // the last vertex's: most neighbours share it
  for_each_vertex(component_, [&](Vec2 v) {
    double squared;
    std::tie(squared, edge) = nearest_edge(v, edge);
    const Vec2 edge_start = hull.empty() ? Vec2{} : hull[edge];
    const double depth = std::sqrt(squared);
    // Located even within rounding (where holds_component passes it unlocated), so that
    // holds_component_after knows which vertices it must measure again.
    const bool located = squared > 0;
    if (located && !locator) locator.emplace(hull);
    const bool outside = located && locator->locate(v) == Location::outside;
    if (depth > allowed_[k] * (1 + 1e-12) || (outside && depth > rounding)) ok = false;
    depths.push_back({squared, edge_start, !outside});
    ++k;
  });
  return ok;
}

bool HullFitter::holds_component_after(
    Vec2 at, const std::function<const Ring&()>& next, const Ring& hull, std::size_t edge,
    const DepthIndex& depths, std::vector<std::pair<std::size_t, VertexDepth>>& changed) const {
  changed.clear();
  const std::size_t m = hull.size();
  // next keeps hull's edges but three: edge is removed, and the two beside it are extended along
  // their lines to the apex. A vertex inside hull is no nearer to next's boundary than to hull's,
  // so only a vertex nearest to one of those three may lie deeper in next: nearest to an extended
  // edge at a point of the edge hull had, it lies as deep (the segment grew along its line);
  // else it is measured again, as is every vertex outside hull (passed by rounding alone).
  const Vec2 before = hull[(edge + m - 1) % m], from = hull[edge], to = hull[(edge + 1) % m],
             after = hull[(edge + 2) % m];
  auto projects_onto = [](Vec2 v, Vec2 a, Vec2 b) {
    const Vec2 along = b - a;
    const double t = glm::dot(v - a, along);
    return t >= 0 && t <= glm::dot(along, along);
  };
  // Asked only of a vertex outside (a pass over next per candidate made mending quadratic).
  auto rounding = [&] { return 1e-12 * largest_coordinate(next()); };
  return depths.for_each_near({before, from, to}, [&](std::size_t k) {
    ++depth_visits_;
    const Vec2 v = depths.vertex(k);
    const VertexDepth& known = depths.depth(k);
    const bool by_rounding = !known.not_outside;
    const Vec2 start = known.edge_start;
    if (!by_rounding && start == before && projects_onto(v, before, from)) {
      return true;  // the extended edge still starts at before
    }
    if (!by_rounding && start == to && projects_onto(v, to, after)) {
      changed.push_back({k, {known.squared, at, known.not_outside}});
      return true;
    }
    // The nearer new edge bounds the depth from above, and a vertex within allowed of it passes:
    // recorded with that edge, which stays in the hull until a removal changes it (then the
    // vertex is measured again), the bound stays true. Measured over every edge otherwise, or
    // when the vertex may lie outside hull.
    const double to_before = point_segment_distance_squared(v, before, at);
    const double to_after = point_segment_distance_squared(v, at, after);
    auto [squared, edge_start] =
        std::pair<double, Vec2>{std::min(to_before, to_after), to_after < to_before ? at : before};
    if (by_rounding || !(std::sqrt(squared) <= allowed_[k] * (1 + 1e-12))) {
      std::tie(squared, edge_start) = squared_distance_and_edge(v, next());
    }
    const double depth = std::sqrt(squared);
    // Not outside hull: not outside next, which holds hull (its new edges lie on the lines of
    // hull's; within rounding of them holds_component does not ask).
    const bool outside =
        !known.not_outside && squared > 0 && locate_point(next(), v) == Location::outside;
    if (depth > allowed_[k] * (1 + 1e-12) || (outside && depth > rounding())) return false;
    changed.push_back({k, {squared, edge_start, !outside}});
    return true;
  });
}

}  // namespace hullcook
