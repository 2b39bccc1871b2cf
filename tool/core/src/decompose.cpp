#include "hullcook/core/decompose.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"
#include "length_inline.h"
#include "pocket_paths.h"
#include "predicates_inline.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace hullcook {

std::optional<Measure> parse_measure(std::string_view name) {
  if (name == "sl") return Measure::sl;
  if (name == "sp") return Measure::sp;
  if (name == "h1") return Measure::h1;
  if (name == "h2") return Measure::h2;
  return std::nullopt;
}

const char* measure_name(Measure measure) {
  switch (measure) {
    case Measure::sl:
      return "sl";
    case Measure::sp:
      return "sp";
    case Measure::h1:
      return "h1";
    case Measure::h2:
      return "h2";
  }
  return "?";
}

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

double distance(Vec2 a, Vec2 b) { return detail::length(b - a); }

// Ring index steps without a division (i < n).
std::size_t next_index(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }
std::size_t prev_index(std::size_t i, std::size_t n) { return i == 0 ? n - 1 : i - 1; }

// The outer boundary's concavity under a measure.
struct OuterConcavity {
  std::vector<double> vertex;  // per vertex: the value Eq. 8 and the witness use
  // Per vertex, the values that decide splitting (H1's); differs from vertex only under H2,
  // whose witness depends on τ. Eq. 5 uses these so hole depths do not depend on τ.
  std::vector<double> depth;
  double value = 0.0;           // decides splitting (for H2: the H1 value, see decompose.h)
  std::size_t witness = kNone;  // the notch with the largest vertex value
  std::vector<char> on_hull;    // per vertex: 2 a hull vertex, 1 exactly on a hull edge, else 0
};

// A candidate for Eq. 5's closest vertex x. Ties in distance go to the first vertex in the order
// outer ring, holes by index, vertex index: the order in which a plain scan would meet them.
struct NearVertex {
  double distance = std::numeric_limits<double>::infinity();  // infinity: none (not known)
  int ring = 0;                                               // 0 outer, h + 1 hole h
  std::size_t index = 0;
  bool unique = false;  // no other vertex searched lies as near
  bool known() const { return distance != std::numeric_limits<double>::infinity(); }
  bool before(const NearVertex& other) const {
    if (distance != other.distance) return distance < other.distance;
    return ring != other.ring ? ring < other.ring : index < other.index;
  }
  // Takes a candidate if it comes before, keeping track of ties.
  void offer(double candidate_distance, int candidate_ring, std::size_t candidate_index) {
    if (candidate_distance < distance) {
      *this = {candidate_distance, candidate_ring, candidate_index, true};
    } else if (candidate_distance == distance) {
      unique = false;
      if (candidate_ring < ring || (candidate_ring == ring && candidate_index < index)) {
        ring = candidate_ring, index = candidate_index;
      }
    }
  }
};

// Eq. 5's antipodal pair of a hole (p, q) and the vertices of the other rings nearest to each;
// and, once a cycle of closest vertices asked for them, the vertices of ∂P0 nearest to each.
struct HoleEnds {
  std::size_t p = kNone, q = kNone;  // kNone: not known
  NearVertex from_p, from_q;
  NearVertex outer_from_p, outer_from_q;
};

// What a child ring inherits from its parent's hull, per vertex. The parent's hull points that
// the child keeps stay on the child's hull, and a parent pocket kept whole by the child cannot
// hold a vertex of the child's hull: the ray leaving such a vertex outward would cross the pocket
// chain (a point of the child) or the bridge (between two points of the child). So only the runs
// at the child's two ends (cut open pockets) need a fresh look.
// The ring that replaces every kept pocket by its bridge, without the parent's collinear hull
// points, is simple (the child plus its kept pockets) and has the child's hull: Melkman's linear
// hull runs on it.
// A pocket kept whole is the same chain with the same bridge, so it keeps its concavities. A
// pocket cut open at the child's ends whose bridge the child keeps (see child_hint) keeps its
// straight-line ones.
enum HintCode : signed char {
  kFresh = 0,
  kParentHullPoint = 1,  // exactly on a parent hull edge
  kInsideKeptPocket = 2,
  kParentHullVertex = 3,
  kInsideCutPocket = 4,   // in the parent pocket cut open at the child's ends, its bridge kept
  kInsideAddedChain = 5,  // a hole's chain added inside that pocket
};
struct ParentHint {
  std::vector<signed char> code;  // per vertex, a HintCode; empty: nothing inherited
  std::vector<double> value;      // per vertex, the parent's value where inherited; or empty
  // The vertices Melkman's scan visits, ascending: the fresh ones, the parent's hull vertices, and
  // the ends of the inherited range [known_first, known_last] (parent hull points, kept even when
  // collinear so that the reduced ring keeps its shape).
  std::vector<std::size_t> hull_candidates;
  std::size_t known_first = 0, known_last = 0;
  std::size_t start = kNone;  // in hull_candidates: the first parent hull vertex, or kNone
  // Where the child's vertices come from: vertex k < from_parent of its outer ring is the parent's
  // vertex (source_first + k) % n, and its hole c is the parent's hole hole_source[c]. A piece cut
  // along a hole continues its outer ring with that hole's chain, from its vertex chain_first on,
  // less the vertices the seams removed.
  std::size_t source_first = 0, from_parent = 0;
  std::vector<std::size_t> hole_source;
  std::size_t chain_hole = kNone, chain_first = 0;
  // Per hole of the child, what it keeps of its parent's HoleEnds (see inherit_hole_ends).
  std::vector<HoleEnds> hole_ends;

  // Back to nothing inherited, keeping the vectors' storage for the next child's hint.
  void reset() {
    code.clear(), value.clear(), hull_candidates.clear(), hole_source.clear(), hole_ends.clear();
    known_first = known_last = 0, start = kNone;
    source_first = from_parent = 0;
    chain_hole = kNone, chain_first = 0;
  }
};

bool is_notch(const Ring& ring, std::size_t i) {
  const std::size_t n = ring.size();
  return detail::fast_orient2d(ring[prev_index(i, n)], ring[i], ring[next_index(i, n)]) < 0.0;
}

// Shortest paths of pockets already measured in an ancestor, reused instead of re-triangulating
// (only H2 measures a pocket again; see decompose()). A pocket is its chain from β- to β+. A
// child's pocket with the same end points and length is often the same chain, but not always: a
// hole joined to the boundary can bring other vertices between the same ends (issue 3, a traced
// sprite's grid). An entry keeps its chain, and a lookup takes it only for an equal chain.
struct PocketKey {
  double sx, sy, tx, ty;
  std::size_t length;
  bool operator==(const PocketKey&) const = default;
};
struct PocketKeyHash {
  // The coordinates' bits (both zeros as one, since they compare equal), multiplied in: a
  // lookup per pocket, where std::hash<double> called a byte-wise hash four times.
  std::size_t operator()(const PocketKey& k) const {
    auto bits = [](double v) { return v == 0.0 ? 0 : std::bit_cast<std::uint64_t>(v); };
    std::uint64_t h = k.length;
    for (double v : {k.sx, k.sy, k.tx, k.ty}) h = (h ^ bits(v)) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
struct PocketPaths {
  std::vector<Vec2> chain;
  std::vector<double> paths;
};
using PocketCache = std::unordered_map<PocketKey, PocketPaths, PocketKeyHash>;

// The hull of a ring, using what a hint inherits (see ParentHint). Sets on_hull: 2 for hull
// vertices, 1 for the parent's points exactly on a hull edge the child keeps; the other points
// exactly on a hull edge are left to measure_outer. Lists those points in ascending order in
// hull_points. False (nothing set) when the hull has fewer than 3 vertices.
bool hull_with_hint(const Ring& ring, const ParentHint* hint, std::vector<char>& on_hull,
                    std::vector<std::size_t>& hull_points) {
  const std::size_t n = ring.size();
  // The inherited range [known_first, known_last], both ends parent hull points.
  std::size_t known_first = n, known_last = 0;
  thread_local std::vector<std::size_t> hull;
  if (hint && hint->code.size() == n) {
    thread_local Ring points;
    const std::vector<std::size_t>& candidates = hint->hull_candidates;
    known_first = hint->known_first, known_last = hint->known_last;
    // A parent hull vertex the child keeps is a vertex of its hull: Melkman's scan starts there
    // (kNone: none kept, the scan searches for one).
    const std::size_t start = hint->start;
    if (candidates.size() * 10 < n * 9) {
      points.clear();
      for (std::size_t k : candidates) points.push_back(ring[k]);
      simple_polygon_hull_indices(points, start, hull);
      for (std::size_t& h : hull) h = candidates[h];
    } else {
      // Little to skip: not worth the copy.
      simple_polygon_hull_indices(ring, start == kNone ? kNone : candidates[start], hull);
    }
  } else {
    simple_polygon_hull_indices(ring, kNone, hull);
  }
  if (hull.size() < 3) return false;
  on_hull.assign(n, 0);
  for (std::size_t h : hull) on_hull[h] = 2;
  // The hull runs in ring order (counter-clockwise, as the ring does): from its lowest index on,
  // its vertices ascend.
  hull_points.clear();
  const std::size_t lowest =
      static_cast<std::size_t>(std::min_element(hull.begin(), hull.end()) - hull.begin());
  for (std::size_t step = 0, k = lowest; step < hull.size(); ++step) {
    const std::size_t s = hull[k];
    k = next_index(k, hull.size());
    const std::size_t t = hull[k];
    hull_points.push_back(s);
    if (known_first <= s && s < t && t <= known_last) {
      // A parent hull edge (no parent hull vertex between s and t would be missing from the
      // child's hull): its points are the parent's.
      for (std::size_t i = s + 1; i < t; ++i) {
        if (hint->code[i] == kParentHullPoint) on_hull[i] = 1, hull_points.push_back(i);
      }
    }
    // Points on a fresh edge are found by measure_outer, which evaluates the same orientations.
  }
  // A clockwise ring (not a cleaned outer boundary) has its hull in descending order.
  if (!std::is_sorted(hull_points.begin(), hull_points.end())) {
    std::sort(hull_points.begin(), hull_points.end());
  }
  return true;
}

// Calls visit(i) for the vertices strictly between s and t, going forward round a ring of n (plain
// loops: stepping with a wrap test was a fifth of the measure's time).
template <typename Visit>
void for_each_between(std::size_t s, std::size_t t, std::size_t n, Visit&& visit) {
  if (s < t) {
    for (std::size_t i = s + 1; i < t; ++i) visit(i);
  } else {
    for (std::size_t i = s + 1; i < n; ++i) visit(i);
    for (std::size_t i = 0; i < t; ++i) visit(i);
  }
}

// Whether test(i) holds for some i from s up to (not including) t, going forward round the ring.
template <typename Test>
bool any_from(std::size_t s, std::size_t t, std::size_t n, Test&& test) {
  if (s < t) {
    for (std::size_t i = s; i < t; ++i) {
      if (test(i)) return true;
    }
    return false;
  }
  for (std::size_t i = s; i < n; ++i) {
    if (test(i)) return true;
  }
  for (std::size_t i = 0; i < t; ++i) {
    if (test(i)) return true;
  }
  return false;
}

// Measures into result, whose storage is reused: a decomposition measures every component.
void measure_outer(const Ring& ring, Measure measure, double tau, OuterConcavity& result,
                   PocketCache* cache = nullptr, const ParentHint* hint = nullptr) {
  const std::size_t n = ring.size();
  result.vertex.assign(n, 0.0);
  result.depth.clear();
  result.value = 0.0;
  result.witness = kNone;
  result.on_hull.clear();
  // The hull points in ring order; each pair of consecutive ones with a gap bounds a pocket.
  thread_local std::vector<std::size_t> hull_points;
  if (!hull_with_hint(ring, hint, result.on_hull, hull_points)) return;
  std::vector<char>& on_hull = result.on_hull;
  auto collect_hull_points = [&] {
    hull_points.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (on_hull[i]) hull_points.push_back(i);
    }
  };
  auto for_each_pocket = [&](auto&& visit) {
    for (std::size_t h = 0; h < hull_points.size(); ++h) {
      const std::size_t s = hull_points[h];
      const std::size_t t = hull_points[h + 1 == hull_points.size() ? 0 : h + 1];
      if (t != next_index(s, n)) visit(s, t);
    }
  };
  // SL: distance to the bridge's line. A vertex exactly on the line is a point of the hull edge:
  // it becomes a hull point (marked kFoundOnEdge for now), splitting the bridge so that every
  // pocket stays simple; the pockets it splits are measured again with their own bridges.
  constexpr char kFoundOnEdge = 3;
  // A hint carries values only where the measure inherits them (see inherits_values).
  const bool inherits = hint && hint->value.size() == n;
  // A pocket's code is its first vertex's (see ParentHint).
  auto pocket_code = [&](std::size_t s) {
    return inherits ? hint->code[next_index(s, n)] : static_cast<signed char>(kFresh);
  };
  auto inherit = [&](std::size_t i) { result.vertex[i] = hint->value[i]; };
  // A pocket is a parent pocket the child keeps whole when every vertex of it lies inside one. A
  // parent hull point exactly on a bridge, no longer on the child's hull, would otherwise join two
  // parent pockets into one child pocket, which the first vertex's code calls kept (issue 3's
  // fuzzing: SP inherited 16.14 where the pocket measures 10.77).
  auto inside_one_kept_pocket = [&](std::size_t s, std::size_t t) {
    return pocket_code(s) == kInsideKeptPocket &&
           !any_from(next_index(s, n), t, n,
                     [&](std::size_t i) { return hint->code[i] != kInsideKeptPocket; });
  };
  // The pockets split by a point found on their bridge are measured again without inheriting:
  // their bridges are shorter, and the distances may round differently.
  // What the first pass learns of each pocket, in pocket order, for the passes after it (while no
  // point found on a bridge has changed the pockets).
  struct FirstLook {
    bool kept;
    double sl_max;
  };
  thread_local std::vector<FirstLook> first_looks;
  first_looks.clear();
  auto measure_straight_line = [&](std::size_t s, std::size_t t, bool may_inherit) {
    signed char code = may_inherit ? pocket_code(s) : static_cast<signed char>(kFresh);
    if (code == kInsideKeptPocket) {
      if (inside_one_kept_pocket(s, t)) {
        double sl_max = 0.0;
        for_each_between(s, t, n, [&](std::size_t i) {
          inherit(i);
          sl_max = std::max(sl_max, result.vertex[i]);
        });
        first_looks.push_back({true, sl_max});
        return false;
      }
      code = kFresh;
    }
    const bool inherits_cut = measure == Measure::sl && code != kFresh;
    const Vec2 bs = ring[s], bt = ring[t];
    const Vec2 along = bt - bs;
    const double length = detail::length(along);
    bool found = false;
    double sl_max = 0.0;
    for_each_between(s, t, n, [&](std::size_t i) {
      if (inherits_cut && hint->code[i] == kInsideCutPocket) {
        inherit(i);
      } else {
        const double determinant = detail::fast_orient2d(bs, bt, ring[i]);
        if (determinant == 0.0) on_hull[i] = kFoundOnEdge, found = true;
        result.vertex[i] = std::abs(determinant) / length;
      }
      sl_max = std::max(sl_max, result.vertex[i]);
    });
    first_looks.push_back({false, sl_max});
    return found;
  };
  bool found_on_edge = false;
  for_each_pocket([&](std::size_t s, std::size_t t) {
    if (measure_straight_line(s, t, true)) found_on_edge = true;
  });
  if (found_on_edge) {
    collect_hull_points();
    for_each_pocket([&](std::size_t s, std::size_t t) {
      if (on_hull[s] == kFoundOnEdge || on_hull[t] == kFoundOnEdge) {
        measure_straight_line(s, t, false);
      }
    });
  }
  // A pocket measured again above is measured afresh under every measure, whatever its code says:
  // its straight-line values replaced the inherited ones.
  auto is_kept = [&](std::size_t s, std::size_t t) {
    return on_hull[s] != kFoundOnEdge && on_hull[t] != kFoundOnEdge && inside_one_kept_pocket(s, t);
  };
  auto settle_found_points = [&] {
    if (found_on_edge) {
      for (char& mark : on_hull) mark = mark == kFoundOnEdge ? 1 : mark;
    }
  };
  thread_local std::vector<Vec2> chain;
  double best_witness_value = -1.0;
  auto consider_witness = [&](std::size_t i) {
    if (result.vertex[i] > best_witness_value && is_notch(ring, i)) {
      best_witness_value = result.vertex[i];
      result.witness = i;
    }
  };
  // The pockets in the order of the first pass, with what it learnt of them unless a point found
  // on a bridge changed them.
  std::size_t pocket = 0;
  auto first_look = [&](std::size_t s, std::size_t t) -> FirstLook {
    if (!found_on_edge) return first_looks[pocket++];
    double sl_max = 0.0;
    for_each_between(s, t, n, [&](std::size_t i) { sl_max = std::max(sl_max, result.vertex[i]); });
    return {is_kept(s, t), sl_max};
  };
  // No vertex of a pocket whose maximum is no more than the witness's value can replace it.
  auto consider_pocket_witness = [&](std::size_t s, std::size_t t, double pocket_max) {
    if (pocket_max > best_witness_value) for_each_between(s, t, n, consider_witness);
  };
  if (measure == Measure::sl) {
    // The values are final: the maximum of each pocket, and the witness.
    for_each_pocket([&](std::size_t s, std::size_t t) {
      const double sl_max = first_look(s, t).sl_max;
      consider_pocket_witness(s, t, sl_max);
      result.value = std::max(result.value, sl_max);
    });
    settle_found_points();
    return;
  }
  for_each_pocket([&](std::size_t s, std::size_t t) {
    const Vec2 bs = ring[s], bt = ring[t];
    const Vec2 along = bt - bs;
    const auto [kept, sl_max] = first_look(s, t);
    // The hybrids take shortest paths where Observation 5.5 finds a hazard: an edge whose outward
    // normal opposes the bridge's.
    const bool is_hybrid = measure == Measure::h1 || measure == Measure::h2;
    // A pocket kept whole has its values already (inherited above).
    const bool use_sp =
        !kept && (measure == Measure::sp || (is_hybrid && any_from(s, t, n, [&](std::size_t i) {
                                               const Vec2 e = ring[next_index(i, n)] - ring[i];
                                               return e.x * along.x + e.y * along.y < 0.0;
                                             })));
    double pocket_value = sl_max;
    if (use_sp) {
      // The chain s..t, wrapping round the ring's end at most once.
      const auto from = ring.begin() + std::ptrdiff_t(s), to = ring.begin() + std::ptrdiff_t(t);
      if (s < t) {
        chain.assign(from, to + 1);
      } else {
        chain.assign(from, ring.end());
        chain.insert(chain.end(), ring.begin(), to + 1);
      }
      const std::vector<double>* cached = nullptr;
      thread_local std::vector<double> computed;
      if (cache) {
        const auto [entry, added] = cache->try_emplace({bs.x, bs.y, bt.x, bt.y, (t + n - s) % n});
        if (added || entry->second.chain != chain) {
          entry->second.chain = chain;
          detail::shortest_paths_to_bridge(chain, entry->second.paths);
        }
        cached = &entry->second.paths;
      } else {
        detail::shortest_paths_to_bridge(chain, computed);
      }
      const std::vector<double>& paths = cached ? *cached : computed;
      // A shortest path is never shorter than the straight line (§5.1), but the two are rounded
      // differently: where a vertex sees its bridge directly, the path's projection can round
      // below the straight-line distance, even to 0 for a notch a fraction of an ulp deep (issue
      // 3's fuzzing), and τ = 0 then left a notch unresolved. Each vertex takes the larger.
      const bool keep_sl = measure == Measure::h2 && sl_max > tau;
      if (keep_sl && result.depth.empty()) result.depth = result.vertex;
      double sp_max = 0.0;
      std::size_t k = 1;
      if (keep_sl || !result.depth.empty()) {
        for_each_between(s, t, n, [&](std::size_t i) {
          const double path = std::max(paths[k++], result.vertex[i]);
          sp_max = std::max(sp_max, path);
          if (!keep_sl) result.vertex[i] = path;
          if (!result.depth.empty()) result.depth[i] = path;
        });
      } else {
        for_each_between(s, t, n, [&](std::size_t i) {
          const double path = std::max(paths[k++], result.vertex[i]);
          sp_max = std::max(sp_max, path);
          result.vertex[i] = path;
        });
      }
      pocket_value = sp_max;
    } else if (!result.depth.empty()) {
      for_each_between(s, t, n, [&](std::size_t i) { result.depth[i] = result.vertex[i]; });
    }
    result.value = std::max(result.value, pocket_value);
    consider_pocket_witness(s, t, pocket_value);
  });
  settle_found_points();
}

// Eq. 5 for every hole: antipodal pair from the principal axis, depth through the closest vertex.
struct HoleConcavity {
  std::size_t joined = 0;   // hole vertex joined to the boundary first (p)
  std::size_t far_end = 0;  // its antipode cw(p)
  int closest_ring = 0;     // ring holding the closest vertex x: 0 outer, h+1 hole h
  std::size_t closest = 0;  // its index
  double value = 0.0;
};

std::pair<std::size_t, std::size_t> principal_axis_extremes(const Ring& hole) {
  Vec2 mean{0.0, 0.0};
  for (Vec2 p : hole) mean += p;
  mean /= double(hole.size());
  double xx = 0.0, xy = 0.0, yy = 0.0;
  for (Vec2 p : hole) {
    const Vec2 d = p - mean;
    xx += d.x * d.x;
    xy += d.x * d.y;
    yy += d.y * d.y;
  }
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
  const Vec2 axis{std::cos(angle), std::sin(angle)};
  std::size_t low = 0, high = 0;
  double low_value = std::numeric_limits<double>::infinity(), high_value = -low_value;
  for (std::size_t i = 0; i < hole.size(); ++i) {
    const double v = (hole[i].x - mean.x) * axis.x + (hole[i].y - mean.y) * axis.y;
    if (v < low_value) low_value = v, low = i;
    if (v > high_value) high_value = v, high = i;
  }
  return {low, high};
}

// Squared distances decide which vertices need the exact distance: a vertex whose squared
// distance exceeds the smallest seen by this relative margin cannot be the closest (rounding is a
// few ulps), provided no square overflows or loses precision to underflow.
constexpr double kSquaredMargin = 1.0 + 1e-9;
bool squares_are_accurate(double squared) { return squared > 1e-200 && squared < 1e200; }

// The closest vertex to point on ring ring_id, by a scan.
void scan_ring(const Ring& ring, int ring_id, Vec2 point, NearVertex& best) {
  // The squared distance beyond which a vertex is farther than the best (infinity: not known).
  auto limit_of = [](double bound) {
    return bound > 1e-100 && bound < 1e100 ? bound * bound * kSquaredMargin
                                           : std::numeric_limits<double>::infinity();
  };
  double limit = limit_of(best.distance);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 offset = ring[i] - point;
    if (offset.x * offset.x + offset.y * offset.y > limit) continue;
    best.offer(distance(ring[i], point), ring_id, i);
    limit = limit_of(best.distance);
  }
}

// The closest vertex to point on every ring but skip_ring, by a scan.
NearVertex nearest_by_scan(const Region& region, Vec2 point, int skip_ring) {
  NearVertex best;
  scan_ring(region.outer, 0, point, best);
  for (std::size_t o = 0; o < region.holes.size(); ++o) {
    const int ring_id = static_cast<int>(o + 1);
    if (ring_id != skip_ring) scan_ring(region.holes[o], ring_id, point, best);
  }
  return best;
}

// Every vertex of a region in a uniform grid of square cells, for Eq. 5's nearest-vertex searches
// (each hole's two ends against all the other rings).
class VertexGrid {
 public:
  // Out of line: whether GCC inlines it into evaluate() flips with unrelated edits of this file,
  // and inlined it ran more instructions.
  [[gnu::noinline]] explicit VertexGrid(const Region& region) {
    std::size_t count = region.outer.size();
    for (const Ring& hole : region.holes) count += hole.size();
    // The holes lie inside the outer ring, so its box holds every vertex.
    double max_x = region.outer[0].x, max_y = region.outer[0].y;
    min_x_ = max_x, min_y_ = max_y;
    for (Vec2 p : region.outer) {
      min_x_ = std::min(min_x_, p.x), max_x = std::max(max_x, p.x);
      min_y_ = std::min(min_y_, p.y), max_y = std::max(max_y, p.y);
    }
    // About one vertex per cell if they were spread evenly over the box.
    const double width = max_x - min_x_, height = max_y - min_y_;
    cell_size_ = std::sqrt(width * height / static_cast<double>(count));
    if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) cell_size_ = std::max(width, height);
    if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) return;  // no grid: scans only
    columns_ = static_cast<int>(std::clamp(width / cell_size_, 0.0, 1023.0)) + 1;
    rows_ = static_cast<int>(std::clamp(height / cell_size_, 0.0, 1023.0)) + 1;
    scale_ = 1.0 / cell_size_;
    cell_start_.assign(static_cast<std::size_t>(columns_ * rows_ + 1), 0);
    std::vector<int> cell_of_vertex;
    cell_of_vertex.reserve(count);
    auto each_ring = [&](auto&& visit) {
      visit(region.outer, 0);
      for (std::size_t h = 0; h < region.holes.size(); ++h) {
        visit(region.holes[h], static_cast<int>(h + 1));
      }
    };
    each_ring([&](const Ring& ring, int) {
      for (Vec2 p : ring) {
        const int cell = row_of(p.y) * columns_ + column_of(p.x);
        cell_of_vertex.push_back(cell);
        ++cell_start_[static_cast<std::size_t>(cell) + 1];
      }
    });
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    entries_.resize(count);
    std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
    std::size_t next = 0;
    each_ring([&](const Ring& ring, int ring_id) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const int slot = fill[static_cast<std::size_t>(cell_of_vertex[next++])]++;
        entries_[static_cast<std::size_t>(slot)] = {ring[i], ring_id, i};
      }
    });
  }

  // The closest vertex to point on the rings that searched(ring id) takes, as a scan finds it;
  // nullopt where squared distances could mislead (then scan).
  template <typename Searched>
  std::optional<NearVertex> nearest(Vec2 point, Searched&& searched) const {
    if (cell_start_.empty()) return std::nullopt;
    const int column = column_of(point.x), row = row_of(point.y);
    NearVertex best;
    double best_squared = std::numeric_limits<double>::infinity();
    auto visit_cell = [&](int x, int y) {
      const std::size_t cell = static_cast<std::size_t>(y * columns_ + x);
      for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const Entry& entry = entries_[static_cast<std::size_t>(k)];
        if (!searched(entry.ring)) continue;
        const Vec2 offset = entry.point - point;
        const double squared = offset.x * offset.x + offset.y * offset.y;
        if (squared > best_squared * kSquaredMargin) continue;
        best_squared = std::min(best_squared, squared);
        best.offer(distance(entry.point, point), entry.ring, entry.index);
      }
    };
    // Square layers of cells around point's cell. After layer L every vertex left lies more than
    // L cells away in x or y; one cell less covers the rounding of the cell assignment.
    for (int layer = 0;; ++layer) {
      const int x0 = column - layer, x1 = column + layer, y0 = row - layer, y1 = row + layer;
      if (x0 < 0 && y0 < 0 && x1 >= columns_ && y1 >= rows_) break;
      const int clipped_x0 = std::max(x0, 0), clipped_x1 = std::min(x1, columns_ - 1);
      if (y0 >= 0) {
        for (int x = clipped_x0; x <= clipped_x1; ++x) visit_cell(x, y0);
      }
      if (y1 < rows_ && y1 != y0) {
        for (int x = clipped_x0; x <= clipped_x1; ++x) visit_cell(x, y1);
      }
      for (int y = std::max(y0 + 1, 0); y <= std::min(y1 - 1, rows_ - 1); ++y) {
        if (x0 >= 0) visit_cell(x0, y);
        if (x1 < columns_ && x1 != x0) visit_cell(x1, y);
      }
      const double reach = (layer - 1) * cell_size_;
      if (reach > 0.0 && reach * reach > best_squared * (1.0 + 1e-6)) break;
    }
    if (!squares_are_accurate(best_squared)) return std::nullopt;
    return best;
  }

 private:
  struct Entry {
    Vec2 point;
    int ring;
    std::size_t index;
  };
  int column_of(double x) const {
    return static_cast<int>(std::clamp((x - min_x_) * scale_, 0.0, columns_ - 1.0));
  }
  int row_of(double y) const {
    return static_cast<int>(std::clamp((y - min_y_) * scale_, 0.0, rows_ - 1.0));
  }
  double min_x_ = 0.0, min_y_ = 0.0, cell_size_ = 0.0, scale_ = 0.0;
  int columns_ = 1, rows_ = 1;
  std::vector<int> cell_start_;  // per cell, its first entry in entries_ (empty: no grid)
  std::vector<Entry> entries_;
};

// Eq. 5's closest vertex x for the two ends (p, q) of a hole: the end nearer to a vertex is joined
// first; on a tie, the vertex first in ring order, then p.
HoleConcavity closest_to_ends(std::size_t p, std::size_t q, const NearVertex& from_p,
                              const NearVertex& from_q) {
  const bool take_q = from_q.before(from_p);
  const NearVertex& chosen = take_q ? from_q : from_p;
  HoleConcavity info;
  info.closest_ring = chosen.ring, info.closest = chosen.index;
  info.joined = take_q ? q : p;
  info.far_end = take_q ? p : q;
  return info;
}

constexpr std::size_t kSearchesForVertexGrid = 6;

// Eq. 5 for every hole. Fills ends (per hole) with the antipodal pair and the nearest vertices,
// taking those of inherited (per hole, or empty) that are known.
std::vector<HoleConcavity> measure_holes(const Region& region, const OuterConcavity& outer,
                                         const std::vector<HoleEnds>& inherited,
                                         std::vector<HoleEnds>& ends) {
  const std::size_t k = region.holes.size();
  std::vector<HoleConcavity> holes(k);
  const double delta = outer.value;
  ends.assign(k, HoleEnds{});
  std::size_t searches = 0;
  for (std::size_t h = 0; h < k; ++h) {
    HoleEnds& hole_ends = ends[h];
    if (inherited.size() == k) hole_ends = inherited[h];
    if (hole_ends.p == kNone) {
      std::tie(hole_ends.p, hole_ends.q) = principal_axis_extremes(region.holes[h]);
    }
    searches += !hole_ends.from_p.known() + !hole_ends.from_q.known();
  }
  // The grid pays for its building from six searches on (three holes without inherited ends);
  // fewer are plain scans.
  std::optional<VertexGrid> grid;
  bool grid_built = false;
  auto vertex_grid = [&]() -> const VertexGrid* {
    if (!grid_built && searches >= kSearchesForVertexGrid) grid.emplace(region);
    grid_built = true;
    return grid ? &*grid : nullptr;
  };
  // Fills nearest, unless known, with the vertex nearest to point on the rings searched takes: by
  // the grid where there is one and it can tell, else by scan(point).
  auto find_nearest = [&](Vec2 point, auto&& searched, auto&& scan, NearVertex& nearest) {
    if (nearest.known()) return;
    if (const VertexGrid* const index = vertex_grid()) {
      if (const auto found = index->nearest(point, searched)) {
        nearest = *found;
        return;
      }
    }
    nearest = scan(point);
  };
  for (std::size_t h = 0; h < k; ++h) {
    const Ring& hole = region.holes[h];
    HoleEnds& hole_ends = ends[h];
    const int hole_ring = static_cast<int>(h + 1);
    auto other_rings = [&](int ring) { return ring != hole_ring; };
    auto scan = [&](Vec2 point) { return nearest_by_scan(region, point, hole_ring); };
    find_nearest(hole[hole_ends.p], other_rings, scan, hole_ends.from_p);
    find_nearest(hole[hole_ends.q], other_rings, scan, hole_ends.from_q);
    holes[h] = closest_to_ends(hole_ends.p, hole_ends.q, hole_ends.from_p, hole_ends.from_q);
  }
  // The closest vertex of ∂P0 alone, where the chain of closest vertices cycles.
  auto outer_fallback = [&](std::size_t h) {
    const Ring& hole = region.holes[h];
    HoleEnds& hole_ends = ends[h];
    auto scan = [&](Vec2 point) {
      NearVertex best;
      scan_ring(region.outer, 0, point, best);
      return best;
    };
    auto outer_only = [](int ring) { return ring == 0; };
    find_nearest(hole[hole_ends.p], outer_only, scan, hole_ends.outer_from_p);
    find_nearest(hole[hole_ends.q], outer_only, scan, hole_ends.outer_from_q);
    return closest_to_ends(hole_ends.p, hole_ends.q, hole_ends.outer_from_p,
                           hole_ends.outer_from_q);
  };
  // Depth through the chain of closest vertices (Fig. 12(b)); a cycle falls back to ∂P0.
  std::vector<int> state(k, 0);  // 0 new, 1 in progress, 2 done
  auto vertex_of = [&](const HoleConcavity& info) {
    return info.closest_ring == 0 ? region.outer[info.closest]
                                  : region.holes[std::size_t(info.closest_ring - 1)][info.closest];
  };
  auto evaluate = [&](auto&& self, std::size_t h) -> double {
    if (state[h] == 2) return holes[h].value;
    state[h] = 1;
    HoleConcavity& info = holes[h];
    if (info.closest_ring != 0 && state[std::size_t(info.closest_ring - 1)] == 1) {
      info = outer_fallback(h);
    }
    const Ring& hole = region.holes[h];
    const std::vector<double>& depth = outer.depth.empty() ? outer.vertex : outer.depth;
    double base = info.closest_ring == 0 ? depth[info.closest]
                                         : self(self, std::size_t(info.closest_ring - 1));
    info.value = base + distance(vertex_of(info), hole[info.joined]) +
                 distance(hole[info.joined], hole[info.far_end]) + delta;
    state[h] = 2;
    return info.value;
  };
  for (std::size_t h = 0; h < k; ++h) evaluate(evaluate, h);
  return holes;
}

// A vertex of the region: ring 0 is the outer boundary, ring h + 1 is hole h.
struct VertexRef {
  int ring;
  std::size_t index;
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

  // For views that test many diagonals from a few vertices: caches blockers by direction, and
  // scans the edges until scans are frequent enough to pay for a grid.
  void expect_many_tests() { expects_many_tests_ = true; }

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
          if (blocks(sight, edge.ring, edge.index)) {
            last_blocker_ = edge;
            remember_blocker(a, edge);
            return false;
          }
        }
      }
    }
    return true;
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

// RegionView::is_diagonal for a region without holes, in one tight pass over the ring: a notch is
// resolved once per split, and the scan was a tenth of the time of the straight-line measure.
bool is_diagonal_of_outer(const RegionView& view, const Ring& ring, std::size_t u, std::size_t v) {
  const Vec2 a = ring[u], b = ring[v];
  if (a == b || !view.in_cone({0, u}, b) || !view.in_cone({0, v}, a)) return false;
  const double min_x = std::min(a.x, b.x), max_x = std::max(a.x, b.x);
  const double min_y = std::min(a.y, b.y), max_y = std::max(a.y, b.y);
  const std::size_t n = ring.size();
  Vec2 c = ring[n - 1];
  for (std::size_t j = 0, i = n - 1; j < n; i = j++) {
    const Vec2 d = ring[j];
    const bool apart = (c.x < min_x && d.x < min_x) || (c.x > max_x && d.x > max_x) ||
                       (c.y < min_y && d.y < min_y) || (c.y > max_y && d.y > max_y);
    if (!apart && i != u && i != v && j != u && j != v && segments_intersect(a, b, c, d)) {
      return false;
    }
    c = d;
  }
  return true;
}

// The chain of ring from first to last (cyclic), cleaned of the repeated and collinear vertices
// the cut leaves at its seam. The ring is clean, so remove_degenerate_vertices_in_place would
// only ever remove vertices at the seam: this does the same removals without looking at every
// vertex. Returns the ring index of the chain's first kept vertex (the rest follow in order).
std::size_t cut_chain(const Ring& ring, std::size_t first, std::size_t last, Ring& out) {
  const std::size_t n = ring.size();
  if (first <= last) {
    out.assign(ring.begin() + std::ptrdiff_t(first), ring.begin() + std::ptrdiff_t(last) + 1);
  } else {
    out.reserve(last + n - first + 1);
    out.assign(ring.begin() + std::ptrdiff_t(first), ring.end());
    out.insert(out.end(), ring.begin(), ring.begin() + std::ptrdiff_t(last) + 1);
  }
  std::size_t front = 0;  // vertices erased at the front, done by one shift at the end
  auto size = [&] { return out.size() - front; };
  auto at = [&](std::size_t k) { return out[front + k]; };
  bool changed = true;
  while (changed && size() >= 3) {
    changed = false;
    const std::size_t m = size();
    if (at(m - 1) == at(0) || detail::fast_orient2d(at(m - 2), at(m - 1), at(0)) == 0.0) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(at(m - 1), at(0), at(1)) == 0.0) {
      ++front;
      changed = true;
    }
  }
  if (front > 0) out.erase(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(front));
  if (out.size() == 2 && out[0] == out[1]) out.pop_back();
  return (first + front) % n;
}

// Gives each hole of a region but cut_hole (kNone: none) to the piece of the two cut from it that
// holds it, and records where the pieces' holes come from (ParentHint::hole_source). A hole the
// cuts do not touch lies strictly inside the region and off the cuts, so inside exactly one
// piece: its first vertex is located in the smaller ring only, by locate_point's crossing count
// without its test for a point on each edge, for all the holes in one pass.
void distribute_holes(const Region& region, std::size_t cut_hole, std::pair<Region, Region>& pieces,
                      std::pair<ParentHint, ParentHint>& hints) {
  const bool search_first = pieces.first.outer.size() <= pieces.second.outer.size();
  const Ring& ring = search_first ? pieces.first.outer : pieces.second.outer;
  // An edge a-b crosses the horizontal line through p where min(a.y, b.y) <= p.y < max(a.y, b.y):
  // the holes' first vertices by height find the few that an edge crosses.
  std::vector<std::pair<double, std::size_t>> by_height;
  for (std::size_t o = 0; o < region.holes.size(); ++o) {
    if (o != cut_hole) by_height.emplace_back(region.holes[o][0].y, o);
  }
  std::sort(by_height.begin(), by_height.end());
  std::vector<char> inside(region.holes.size(), 0);
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size() && !by_height.empty(); j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    const double low = std::min(a.y, b.y), high = std::max(a.y, b.y);
    auto point = std::lower_bound(by_height.begin(), by_height.end(), low,
                                  [](const auto& entry, double y) { return entry.first < y; });
    for (; point != by_height.end() && point->first < high; ++point) {
      const double side = detail::fast_orient2d(a, b, region.holes[point->second][0]);
      if ((b.y > a.y) ? side > 0.0 : side < 0.0) inside[point->second] ^= 1;
    }
  }
  for (std::size_t o = 0; o < region.holes.size(); ++o) {
    if (o == cut_hole) continue;
    const bool in_first = (inside[o] != 0) == search_first;
    (in_first ? pieces.first : pieces.second).holes.push_back(region.holes[o]);
    (in_first ? hints.first : hints.second).hole_source.push_back(o);
  }
}

// The hint (see ParentHint) of a child of size vertices whose vertex k < from_parent is the
// parent's vertex (source_first + k) % parent.on_hull.size(); the rest (a hole's chain) lie inside
// the parent, so off its hull and outside its pockets. The parent's values are inherited unless
// with_values is false.
void child_hint(const OuterConcavity& parent, std::size_t source_first, std::size_t size,
                std::size_t from_parent, bool with_values, ParentHint& hint) {
  hint.reset();
  hint.source_first = source_first, hint.from_parent = from_parent;
  const std::vector<char>& parent_on_hull = parent.on_hull;
  const std::size_t n = parent_on_hull.size();
  if (n == 0) return;
  // The child's vertex k is the parent's vertex source(k).
  auto source = [&](std::size_t k) {
    return source_first + k < n ? source_first + k : source_first + k - n;
  };
  std::size_t known_first = 0;
  while (known_first < from_parent && !parent_on_hull[source(known_first)]) ++known_first;
  if (known_first == from_parent) return;
  std::size_t known_last = from_parent - 1;
  while (!parent_on_hull[source(known_last)]) --known_last;
  // The child's ends (from its last parent hull point round to its first) are fresh, unless both
  // cut ends lie in one parent pocket: then that pocket's bridge is still a hull edge of the child
  // (the child is on the parent's side of it), and the ends lie inside the pocket.
  bool ends_in_one_pocket = known_first < known_last;
  if (ends_in_one_pocket) {
    const std::size_t bridge_end = (source_first + known_first) % n;
    for (std::size_t i = next_index((source_first + known_last) % n, n); i != bridge_end;
         i = next_index(i, n)) {
      if (parent_on_hull[i]) {
        ends_in_one_pocket = false;
        break;
      }
    }
  }
  std::vector<signed char>& code = hint.code;
  std::vector<std::size_t>& candidates = hint.hull_candidates;
  hint.known_first = known_first, hint.known_last = known_last;
  hint.start = kNone;
  candidates.reserve(ends_in_one_pocket ? known_last - known_first + 1 : size);
  code.assign(size, ends_in_one_pocket ? kInsideCutPocket : kFresh);
  if (ends_in_one_pocket) {
    std::fill(code.begin() + std::ptrdiff_t(from_parent), code.end(), kInsideAddedChain);
  } else {
    for (std::size_t k = 0; k < known_first; ++k) candidates.push_back(k);
  }
  constexpr signed char kCodeOfOnHull[3] = {kInsideKeptPocket, kParentHullPoint, kParentHullVertex};
  for (std::size_t k = known_first; k <= known_last; ++k) {
    const char on_hull = parent_on_hull[source(k)];
    code[k] = kCodeOfOnHull[static_cast<std::size_t>(on_hull)];
    if (on_hull == 2 || (on_hull == 1 && (k == known_first || k == known_last))) {
      if (on_hull == 2 && hint.start == kNone) hint.start = candidates.size();
      candidates.push_back(k);
    }
  }
  if (!ends_in_one_pocket) {
    for (std::size_t k = known_last + 1; k < size; ++k) candidates.push_back(k);
  }
  if (with_values) {
    // In two runs: the source wraps round the parent's end at most once. The added chain's
    // vertices (from from_parent on) inherit nothing: zero.
    const std::size_t before_wrap = std::min(from_parent, n - source_first);
    const auto from = parent.vertex.begin() + std::ptrdiff_t(source_first);
    hint.value.reserve(size);
    hint.value.assign(from, from + std::ptrdiff_t(before_wrap));
    hint.value.insert(hint.value.end(), parent.vertex.begin(),
                      parent.vertex.begin() + std::ptrdiff_t(from_parent - before_wrap));
    hint.value.resize(size);
  }
}

// H2's values depend on τ where a pocket is deeper than it: its children measure afresh.
bool inherits_values(const DecomposeSettings& settings) { return settings.measure != Measure::h2; }

// Cuts the outer ring along the diagonal i-j; holes go to the piece containing them. Fills the
// children's hull hints from the parent's hull points.
std::pair<Region, Region> split_outer(const Region& region, std::size_t i, std::size_t j,
                                      const OuterConcavity& parent, bool with_values,
                                      std::pair<ParentHint, ParentHint>& hints) {
  const Ring& ring = region.outer;
  std::pair<Region, Region> pieces;
  Region& first = pieces.first;
  Region& second = pieces.second;
  const std::size_t first_source = cut_chain(ring, i, j, first.outer);
  child_hint(parent, first_source, first.outer.size(), first.outer.size(), with_values,
             hints.first);
  const std::size_t second_source = cut_chain(ring, j, i, second.outer);
  child_hint(parent, second_source, second.outer.size(), second.outer.size(), with_values,
             hints.second);
  distribute_holes(region, kNone, pieces, hints);
  return pieces;
}

// remove_degenerate_vertices_in_place on rings made of chains of clean rings, in two steps:
// append_without_degeneracies for each chain, then close_without_degeneracies. Only the seams
// need its tests: three consecutive vertices of a clean ring are distinct and not collinear, so
// once the last two vertices kept are a chain's, the rest of the chain is kept as it is.
void append_without_degeneracies(const Ring& ring, std::size_t from, std::size_t to, Ring& out) {
  const std::size_t n = ring.size();
  for (std::size_t k = from, step = 0;; k = next_index(k, n), ++step) {
    const std::size_t kept = out.size();
    if (step >= 2 && kept >= 2 && out[kept - 1] == ring[prev_index(k, n)] &&
        out[kept - 2] == ring[prev_index(prev_index(k, n), n)]) {
      const auto begin = ring.begin();
      if (k <= to) {
        out.insert(out.end(), begin + std::ptrdiff_t(k), begin + std::ptrdiff_t(to) + 1);
      } else {
        out.insert(out.end(), begin + std::ptrdiff_t(k), ring.end());
        out.insert(out.end(), begin, begin + std::ptrdiff_t(to) + 1);
      }
      return;
    }
    const Vec2 p = ring[k];
    while (out.size() >= 2 && detail::fast_orient2d(out[out.size() - 2], out.back(), p) == 0.0) {
      out.pop_back();
    }
    if (out.empty() || out.back() != p) out.push_back(p);
    if (k == to) return;
  }
}

void close_without_degeneracies(Ring& out) {
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    if (out.back() == out.front()) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(out[out.size() - 2], out.back(), out.front()) == 0.0) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(out.back(), out[0], out[1]) == 0.0) {
      out.erase(out.begin());
      changed = true;
    }
  }
  if (out.size() == 2 && out[0] == out[1]) out.pop_back();
}

// The hint of a piece cut by split_hole: its ring starts with the outer chain from `from` to `to`,
// less the vertices the seams removed, then runs along the hole.
void hole_piece_hint(const Ring& outer, const OuterConcavity& parent, bool with_values,
                     std::size_t from, std::size_t to, const Ring& piece, ParentHint& hint) {
  const std::size_t n = outer.size();
  hint.reset();
  if (piece.empty() || parent.on_hull.size() != n) return;
  std::size_t first = from, chain = (to + n - from) % n + 1;
  while (chain > 0 && outer[first] != piece[0]) first = next_index(first, n), --chain;
  std::size_t from_parent = 0;
  while (from_parent < chain && from_parent < piece.size() &&
         piece[from_parent] == outer[(first + from_parent) % n]) {
    ++from_parent;
  }
  if (from_parent == 0) return;
  child_hint(parent, first, piece.size(), from_parent, with_values, hint);
}

// Cuts along hole[p]-outer[x] and hole[q]-outer[y] (x != y): two pieces without that hole. Fills
// the pieces' hull hints from the parent's hull points.
std::pair<Region, Region> split_hole(const Region& region, std::size_t h, std::size_t p,
                                     std::size_t x, std::size_t q, std::size_t y,
                                     const OuterConcavity& parent, bool with_values,
                                     std::pair<ParentHint, ParentHint>& hints) {
  const Ring& outer = region.outer;
  const Ring& hole = region.holes[h];
  const std::size_t n = outer.size(), m = hole.size();
  std::pair<Region, Region> pieces;
  Region& first = pieces.first;
  Region& second = pieces.second;
  first.outer.reserve((y + n - x) % n + (p + m - q) % m + 2);
  append_without_degeneracies(outer, x, y, first.outer);
  append_without_degeneracies(hole, q, p, first.outer);
  close_without_degeneracies(first.outer);
  hole_piece_hint(outer, parent, with_values, x, y, first.outer, hints.first);
  second.outer.reserve((x + n - y) % n + (q + m - p) % m + 2);
  append_without_degeneracies(outer, y, x, second.outer);
  append_without_degeneracies(hole, p, q, second.outer);
  close_without_degeneracies(second.outer);
  hole_piece_hint(outer, parent, with_values, y, x, second.outer, hints.second);
  hints.first.chain_hole = hints.second.chain_hole = h;
  hints.first.chain_first = q, hints.second.chain_first = p;
  distribute_holes(region, h, pieces, hints);
  return pieces;
}

// What a piece keeps of its parent's HoleEnds (see ParentHint::hole_ends): a hole keeps its
// antipodal pair, and the vertex nearest to an end where the piece keeps that vertex and no other
// vertex was as near. The piece's vertices are some of the parent's, so none is nearer.
void inherit_hole_ends(const Region& parent, const std::vector<HoleEnds>& parent_ends,
                       const Region& piece, ParentHint& hint) {
  if (parent_ends.size() != parent.holes.size() || hint.hole_source.size() != piece.holes.size()) {
    return;
  }
  std::vector<int> ring_in_piece(parent.holes.size() + 1, -1);  // by the parent's ring id
  for (std::size_t c = 0; c < piece.holes.size(); ++c) {
    ring_in_piece[hint.hole_source[c] + 1] = static_cast<int>(c + 1);
  }
  const std::size_t n = parent.outer.size();
  // On the piece's outer ring at k, if it is there: a piece's vertices are distinct.
  auto on_outer = [&](const NearVertex& nearest, std::size_t k, Vec2 point) -> NearVertex {
    if (k >= piece.outer.size() || piece.outer[k] != point) return {};
    return {nearest.distance, 0, k, true};
  };
  auto in_piece = [&](const NearVertex& nearest) -> NearVertex {
    if (!nearest.unique) return {};
    if (nearest.ring == 0) {
      const std::size_t k = (nearest.index + n - hint.source_first % n) % n;
      return k < hint.from_parent ? on_outer(nearest, k, parent.outer[nearest.index])
                                  : NearVertex{};
    }
    const std::size_t hole = static_cast<std::size_t>(nearest.ring - 1);
    if (hole == hint.chain_hole) {
      const std::size_t m = parent.holes[hole].size();
      const std::size_t k = hint.from_parent + (nearest.index + m - hint.chain_first) % m;
      return on_outer(nearest, k, parent.holes[hole][nearest.index]);
    }
    const int ring = ring_in_piece[static_cast<std::size_t>(nearest.ring)];
    if (ring < 0) return {};
    return {nearest.distance, ring, nearest.index, true};
  };
  // On ∂P0 alone: a piece cut along a hole has the hole's chain on its outer ring too, whose
  // vertices (from from_parent on) must all lie farther.
  auto in_piece_outer = [&](const NearVertex& nearest, Vec2 end) -> NearVertex {
    const NearVertex kept = in_piece(nearest);
    if (!kept.known() || hint.chain_hole == kNone) {
      return kept;
    }
    for (std::size_t k = hint.from_parent; k < piece.outer.size(); ++k) {
      if (!(distance(piece.outer[k], end) > kept.distance)) return {};
    }
    return kept;
  };
  hint.hole_ends.resize(piece.holes.size());
  for (std::size_t c = 0; c < piece.holes.size(); ++c) {
    const HoleEnds& from = parent_ends[hint.hole_source[c]];
    const Ring& hole = piece.holes[c];
    hint.hole_ends[c] = {from.p,
                         from.q,
                         in_piece(from.from_p),
                         in_piece(from.from_q),
                         in_piece_outer(from.outer_from_p, hole[from.p]),
                         in_piece_outer(from.outer_from_q, hole[from.q])};
  }
}

struct Evaluation {
  OuterConcavity outer;
  std::vector<HoleConcavity> holes;
  std::vector<HoleEnds> hole_ends;
  double value = 0.0;
  int deepest_hole = -1;
};

// Evaluates into e, whose storage is reused (see measure_outer).
void evaluate(const Region& region, Measure measure, double tau, Evaluation& e,
              PocketCache* cache = nullptr, const ParentHint* hint = nullptr) {
  measure_outer(region.outer, measure, tau, e.outer, cache, hint);
  e.value = e.outer.value;
  e.holes.clear();
  e.hole_ends.clear();
  e.deepest_hole = -1;
  if (!region.holes.empty()) {
    static const std::vector<HoleEnds> kNothingInherited;
    e.holes =
        measure_holes(region, e.outer, hint ? hint->hole_ends : kNothingInherited, e.hole_ends);
    for (std::size_t h = 0; h < e.holes.size(); ++h) {
      if (e.deepest_hole < 0 || e.holes[h].value > e.holes[std::size_t(e.deepest_hole)].value) {
        e.deepest_hole = static_cast<int>(h);
      }
    }
    e.value = std::max(e.value, e.holes[std::size_t(e.deepest_hole)].value);
  }
}

// Visits items in the order of before (a strict total order) until accept takes one, without
// sorting them all: usually the first few are taken. Returns the accepted item, or nullopt.
template <typename T, typename Before, typename Accept>
std::optional<T> first_accepted(std::vector<T>& items, Before before, Accept accept) {
  auto after = [&](const T& u, const T& v) { return before(v, u); };
  std::make_heap(items.begin(), items.end(), after);
  for (auto end = items.end(); end != items.begin(); --end) {
    std::pop_heap(items.begin(), end, after);
    if (accept(*(end - 1))) return *(end - 1);
  }
  return std::nullopt;
}

// A candidate vertex of a cut and its score (higher first, then lower index).
struct ScoredVertex {
  double score;
  std::size_t index;
};

bool scores_before(const ScoredVertex& u, const ScoredVertex& v) {
  return u.score != v.score ? u.score > v.score : u.index < v.index;
}

// The first candidate, in the order of scores, that accept takes: the best scored of all it
// takes.
// A search refused by its first few candidates is usually refused by all (a hole vertex that sees
// no vertex of ∂P0), and refusals do not depend on the order: the rest is then searched unsorted,
// skipping the candidates that cannot beat the best one taken.
// A quick search (quick_tests > 0) gives up instead, after refusals by its first quick_tests
// candidates in order, and sets *gave_up; what it does return is what the full search returns.
template <typename Accept>
std::optional<std::size_t> first_accepted_by_score(std::vector<ScoredVertex>& candidates,
                                                   Accept&& accept, std::size_t quick_tests = 0,
                                                   bool* gave_up = nullptr) {
  if (quick_tests > 0) {
    // The best few in order, by one pass that keeps them sorted: a quick search that gives up
    // (a walled-in hole vertex, several per decomposition of the neuron) then orders no others.
    thread_local std::vector<ScoredVertex> best_few;
    best_few.clear();
    for (const ScoredVertex& candidate : candidates) {
      if (best_few.size() == quick_tests && !scores_before(candidate, best_few.back())) continue;
      best_few.insert(std::upper_bound(best_few.begin(), best_few.end(), candidate, scores_before),
                      candidate);
      if (best_few.size() > quick_tests) best_few.pop_back();
    }
    for (const ScoredVertex& candidate : best_few) {
      if (accept(candidate.index)) return candidate.index;
    }
    if (best_few.size() < candidates.size() && gave_up) *gave_up = true;
    return std::nullopt;
  }
  auto after = [](const ScoredVertex& u, const ScoredVertex& v) { return scores_before(v, u); };
  std::make_heap(candidates.begin(), candidates.end(), after);
  auto end = candidates.end();
  for (std::size_t tests_in_order = 16 + candidates.size() / 32;
       tests_in_order > 0 && end != candidates.begin(); --tests_in_order) {
    std::pop_heap(candidates.begin(), end, after);
    --end;
    if (accept(end->index)) return end->index;
  }
  if (end == candidates.begin()) return std::nullopt;
  // Heap order: the higher scores, likelier to prune the rest, come first.
  const ScoredVertex* best = nullptr;
  for (auto it = candidates.begin(); it != end; ++it) {
    if ((!best || scores_before(*it, *best)) && accept(it->index)) best = &*it;
  }
  if (!best) return std::nullopt;
  return best->index;
}

// first_accepted_by_score where the best scored candidate is usually taken (a hole's searches,
// and a notch's cut, whose best diagonal by Eq. 8 was valid at every split we counted on the
// Nazca models): one pass finds it without ordering the rest; if it is refused, the full search
// runs.
template <typename Accept>
std::optional<std::size_t> best_accepted_by_score(std::vector<ScoredVertex>& candidates,
                                                  Accept&& accept, std::size_t quick_tests = 0,
                                                  bool* gave_up = nullptr) {
  if (candidates.empty()) return std::nullopt;
  const ScoredVertex* top = &candidates[0];
  for (const ScoredVertex& candidate : candidates) {
    if (scores_before(candidate, *top)) top = &candidate;
  }
  if (accept(top->index)) return top->index;
  return first_accepted_by_score(candidates, accept, quick_tests, gave_up);
}

// Algorithm 4.2 for a notch r of ∂P0: the best valid diagonal by Eq. 8.
std::optional<std::pair<Region, Region>> resolve_notch(const Region& region,
                                                       const OuterConcavity& concavity,
                                                       std::size_t r,
                                                       const DecomposeSettings& settings,
                                                       std::pair<ParentHint, ParentHint>& hints) {
  const Ring& ring = region.outer;
  const std::size_t n = ring.size();
  RegionView view(region);
  const Vec2 a = ring[prev_index(r, n)], pr = ring[r], b = ring[next_index(r, n)];
  thread_local std::vector<ScoredVertex> resolving;
  resolving.clear();
  std::vector<ScoredVertex> others;
  auto eq8 = [&](std::size_t i, double length) {
    return (1.0 + settings.sc * concavity.vertex[i]) / (settings.sd * length);
  };
  // The reflex angle's bisector, for diagonals that can only reduce the notch.
  Vec2 in_a = a - pr, in_b = b - pr;
  in_a /= detail::length(in_a);
  in_b /= detail::length(in_b);
  Vec2 bisector = -(in_a + in_b);
  if (bisector.x == 0.0 && bisector.y == 0.0) bisector = {in_a.y, -in_a.x};
  const std::size_t after_r = next_index(r, n), before_r = prev_index(r, n);
  auto is_candidate = [&](std::size_t i) { return i != r && i != after_r && i != before_r; };
  auto resolves = [&](Vec2 x) {
    return detail::fast_orient2d(a, pr, x) >= 0.0 && detail::fast_orient2d(x, pr, b) >= 0.0;
  };
  resolving.resize(n);
  std::size_t resolving_count = 0;
  auto take = [&](std::size_t i) {
    resolving[resolving_count++] = {eq8(i, distance(pr, ring[i])), i};
  };
  // resolves() by the static filter alone (as in melkman_steps: a call in the loop would keep its
  // registers on the stack); the few vertices it leaves undecided are tested after, exactly. The
  // candidates' order does not matter: the searches order them by score, then index.
  thread_local std::vector<std::size_t> undecided;
  undecided.clear();
  auto collect_resolving = [&](std::size_t from, std::size_t to) {
    const double bound = detail::static_orient_error_bound;
    for (std::size_t i = from; i < to; ++i) {
      const Vec2 x = ring[i];
      const double before = detail::rounded_orient2d(a, pr, x);
      const double after = detail::rounded_orient2d(x, pr, b);
      if (before < -bound || after < -bound) continue;
      if (before > bound && after > bound) {
        take(i);
      } else {
        undecided.push_back(i);
      }
    }
  };
  // Every vertex but r and its neighbours, in index order, without testing each index.
  if (r == 0) {
    collect_resolving(2, n - 1);
  } else if (r == n - 1) {
    collect_resolving(1, n - 2);
  } else {
    collect_resolving(0, r - 1);
    collect_resolving(r + 2, n);
  }
  for (std::size_t i : undecided) {
    if (resolves(ring[i])) take(i);
  }
  resolving.resize(resolving_count);
  auto is_valid = [&](std::size_t i) {
    return region.holes.empty() ? is_diagonal_of_outer(view, ring, r, i)
                                : view.is_diagonal({0, r}, {0, i});
  };
  if (const auto chosen = best_accepted_by_score(resolving, is_valid)) {
    return split_outer(region, r, *chosen, concavity, inherits_values(settings), hints);
  }
  // Rarely needed: scored only when no resolving diagonal is valid.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 x = ring[i];
    if (!is_candidate(i) || resolves(x)) continue;
    const Vec2 d = (x - pr) / distance(pr, x);
    others.push_back({d.x * bisector.x + d.y * bisector.y, i});
  }
  if (const auto chosen = first_accepted(
          others, scores_before, [&](const ScoredVertex& c) { return is_valid(c.index); })) {
    return split_outer(region, r, chosen->index, concavity, inherits_values(settings), hints);
  }
  return std::nullopt;
}

// Algorithm 4.2 for a hole: join p to the closest visible vertex of ∂P0, and its antipode to the
// best vertex of ∂P0 by Eq. 8, so the hole opens into two simple pieces.
std::optional<std::pair<Region, Region>> resolve_hole(const Region& region, const Evaluation& e,
                                                      std::size_t h,
                                                      const DecomposeSettings& settings,
                                                      std::pair<ParentHint, ParentHint>& hints) {
  RegionView view(region);
  view.expect_many_tests();
  const Ring& outer = region.outer;
  const Ring& hole = region.holes[h];
  const int hole_ring = static_cast<int>(h + 1);
  // The searches from p and from q ask the same sight lines when an attempt's q is a later p,
  // and a refused search asks all of them: each is computed once.
  std::vector<std::vector<signed char>> sees_known(hole.size());
  auto sees = [&](std::size_t p, std::size_t i) {
    std::vector<signed char>& known = sees_known[p];
    if (known.empty()) known.assign(outer.size(), -1);
    if (known[i] < 0) known[i] = view.is_diagonal({hole_ring, p}, {0, i}) ? 1 : 0;
    return known[i] == 1;
  };
  const HoleConcavity& info = e.holes[h];
  // A search with quick_tests > 0 may give up (see first_accepted_by_score): it then returns
  // kGaveUp.
  constexpr std::size_t kGaveUp = kNone - 1;
  auto closest_visible = [&](std::size_t p, std::size_t quick_tests) -> std::size_t {
    // Eq. 5 found the vertex nearest to the joined end, by the same distances and tie-break: when
    // it lies on ∂P0 and p sees it, no other vertex needs a look.
    if (p == info.joined && info.closest_ring == 0 && sees(p, info.closest)) return info.closest;
    // Nearest first: the scores are negated distances.
    std::vector<ScoredVertex> candidates(outer.size());
    for (std::size_t i = 0; i < outer.size(); ++i) {
      candidates[i] = {-distance(outer[i], hole[p]), i};
    }
    bool gave_up = false;
    const auto chosen = best_accepted_by_score(
        candidates, [&](std::size_t i) { return sees(p, i); }, quick_tests, &gave_up);
    return chosen ? *chosen : gave_up ? kGaveUp : kNone;
  };
  auto best_second = [&](std::size_t p, std::size_t x, std::size_t q,
                         std::size_t quick_tests) -> std::size_t {
    auto eq8 = [&](std::size_t i, double length) {
      return (1.0 + settings.sc * e.outer.vertex[i]) / (settings.sd * length);
    };
    std::vector<ScoredVertex> candidates;
    candidates.reserve(outer.size());
    for (std::size_t i = 0; i < outer.size(); ++i) {
      if (i != x) candidates.push_back({eq8(i, distance(outer[i], hole[q])), i});
    }
    bool gave_up = false;
    const auto chosen = best_accepted_by_score(
        candidates,
        [&](std::size_t i) {
          return sees(q, i) && !segments_intersect(hole[p], outer[x], hole[q], outer[i]);
        },
        quick_tests, &gave_up);
    return chosen ? *chosen : gave_up ? kGaveUp : kNone;
  };
  std::vector<std::pair<std::size_t, std::size_t>> attempts{{info.joined, info.far_end},
                                                            {info.far_end, info.joined}};
  for (std::size_t i = 0; i < hole.size(); ++i) {
    attempts.emplace_back(i, (i + hole.size() / 2) % hole.size());
  }
  // A hole vertex walled in by other holes sees no vertex of ∂P0, and its searches are refused by
  // every candidate: on the neuron, three such searches of a thousand candidates each took a
  // quarter of the decomposition. The attempts are first made with quick searches, and only if
  // none succeeds, again with full ones. A quick success is what the full search would return, so
  // the first pass returns what the second would unless an earlier attempt needs a full search.
  constexpr std::size_t kQuickTests = 16;
  // A failed attempt fails again: the searches depend on p (and q) only.
  constexpr std::size_t kNotSearched = kNone - 2;
  std::vector<std::size_t> closest_visible_from(hole.size(), kNotSearched);
  for (const std::size_t quick_tests : {kQuickTests, std::size_t(0)}) {
    for (std::size_t a = 0; a < attempts.size(); ++a) {
      const auto [p, q] = attempts[a];
      if (p == q) continue;
      if (a >= 2 && (attempts[a] == attempts[0] || attempts[a] == attempts[1])) continue;
      std::size_t& x = closest_visible_from[p];
      if (x == kNotSearched || (x == kGaveUp && quick_tests == 0)) {
        x = closest_visible(p, quick_tests);
      }
      if (x == kNone || x == kGaveUp) continue;
      const std::size_t y = best_second(p, x, q, quick_tests);
      if (y == kNone || y == kGaveUp) continue;
      return split_hole(region, h, p, x, q, y, e.outer, inherits_values(settings), hints);
    }
  }
  return std::nullopt;
}

Piece make_piece(const Region& component, double concavity) {
  const detail::CoordinateBound coordinate_bound(detail::max_abs_coordinate(component.outer));
  Ring hull;
  for (std::size_t index : simple_polygon_hull_indices(component.outer)) {
    hull.push_back(component.outer[index]);
  }
  return Piece{component, std::move(hull), concavity};
}

}  // namespace

double measure_concavity(const Region& region, Measure measure, double tau) {
  Evaluation e;
  evaluate(region, measure, tau, e);
  return e.value;
}

std::vector<double> outer_vertex_concavity(const Ring& outer, Measure measure, double tau) {
  OuterConcavity result;
  measure_outer(outer, measure, tau, result);
  return result.vertex;
}

DecompositionTree decompose(const Region& region, const DecomposeSettings& settings) {
  if (!(settings.tau >= 0.0)) throw std::invalid_argument("decompose: tau must be >= 0");
  if (!(settings.sc >= 0.0 && std::isfinite(settings.sc))) {
    throw std::invalid_argument("decompose: sc must be finite and >= 0");
  }
  if (!(settings.sd > 0.0 && std::isfinite(settings.sd))) {
    throw std::invalid_argument("decompose: sd must be finite and > 0");
  }
  // Every point the decomposition orients is a vertex of the region (or one turned a quarter).
  const detail::CoordinateBound coordinate_bound(detail::max_abs_coordinate(region));
  DecompositionTree tree;
  tree.tau_ = settings.tau;
  tree.measure_ = settings.measure;
  tree.nodes_.push_back({region, 0.0, {}, {-1, -1}});
  std::vector<int> pending{0};
  // Under every measure but H2 a child inherits the values of the pockets it keeps whole, and
  // measures only new chains: only H2 looks pockets up.
  PocketCache cache;
  PocketCache* const pocket_cache = inherits_values(settings) ? nullptr : &cache;
  std::vector<ParentHint> hints(1);  // per node
  Evaluation e;                      // of the node at hand; its storage is reused
  std::vector<ParentHint> spare_hints;
  auto take_spare_hint = [&] {
    if (spare_hints.empty()) return ParentHint();
    ParentHint hint = std::move(spare_hints.back());
    spare_hints.pop_back();
    return hint;
  };
  while (!pending.empty()) {
    const int id = pending.back();
    pending.pop_back();
    // Valid until the children are appended below (nodes_ may then reallocate).
    const Region& component = tree.nodes_[std::size_t(id)].component;
    evaluate(component, settings.measure, settings.tau, e, pocket_cache, &hints[std::size_t(id)]);
    // The node's hint is spent: its storage serves the hints of the next children made.
    spare_hints.push_back(std::move(hints[std::size_t(id)]));
    tree.nodes_[std::size_t(id)].concavity = e.value;
    if (!(e.value > settings.tau)) continue;
    std::pair<ParentHint, ParentHint> child_hints{take_spare_hint(), take_spare_hint()};
    std::optional<std::pair<Region, Region>> parts;
    Witness witness;
    if (e.deepest_hole >= 0 && e.holes[std::size_t(e.deepest_hole)].value > settings.tau) {
      // Fig. 12(b): a hole whose closest vertex lies on another hole waits for that hole.
      std::size_t h = std::size_t(e.deepest_hole);
      for (std::size_t guard = 0; guard < e.holes.size() && e.holes[h].closest_ring != 0; ++guard) {
        h = std::size_t(e.holes[h].closest_ring - 1);
      }
      parts = resolve_hole(component, e, h, settings, child_hints);
      for (std::size_t o = 0; !parts && o < component.holes.size(); ++o) {
        if (o != h) parts = resolve_hole(component, e, o, settings, child_hints), h = o;
      }
      witness = {component.holes[h][e.holes[h].joined], static_cast<int>(h)};
    } else if (e.outer.witness != kNone) {
      parts = resolve_notch(component, e.outer, e.outer.witness, settings, child_hints);
      witness = {component.outer[e.outer.witness], -1};
    }
    if (!parts) continue;  // cannot happen on a valid region; keep the node whole
    if (!component.holes.empty()) {
      inherit_hole_ends(component, e.hole_ends, parts->first, child_hints.first);
      inherit_hole_ends(component, e.hole_ends, parts->second, child_hints.second);
    }
    const int first = static_cast<int>(tree.nodes_.size());
    tree.nodes_.push_back({std::move(parts->first), 0.0, {}, {-1, -1}});
    tree.nodes_.push_back({std::move(parts->second), 0.0, {}, {-1, -1}});
    hints.push_back(std::move(child_hints.first));
    hints.push_back(std::move(child_hints.second));
    auto& node = tree.nodes_[std::size_t(id)];
    node.witness = witness;
    node.children[0] = first;
    node.children[1] = first + 1;
    pending.push_back(first + 1);
    pending.push_back(first);
  }
  return tree;
}

std::size_t DecompositionTree::piece_count_at(double tau) const {
  std::size_t count = 0;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[std::size_t(stack.back())];
    stack.pop_back();
    if (node.is_leaf() || node.concavity <= tau) {
      ++count;
    } else {
      stack.push_back(node.children[1]);
      stack.push_back(node.children[0]);
    }
  }
  return count;
}

std::vector<Piece> DecompositionTree::pieces_at(double tau) const {
  std::vector<Piece> pieces;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[std::size_t(stack.back())];
    stack.pop_back();
    if (node.is_leaf() || node.concavity <= tau) {
      pieces.push_back(make_piece(node.component, node.concavity));
    } else {
      stack.push_back(node.children[1]);
      stack.push_back(node.children[0]);
    }
  }
  return pieces;
}

std::vector<double> DecompositionTree::level_taus() const {
  std::vector<double> taus{tau_};
  for (const Node& node : nodes_) {
    if (!node.is_leaf() && node.concavity >= tau_) taus.push_back(node.concavity);
  }
  std::sort(taus.begin(), taus.end());
  taus.erase(std::unique(taus.begin(), taus.end()), taus.end());
  return taus;
}

std::vector<Piece> DecompositionTree::pieces_within(std::size_t max_pieces) const {
  const std::size_t budget = std::max<std::size_t>(max_pieces, 1);
  const std::vector<double> taus = level_taus();
  // The piece count does not grow with τ: binary search for the finest level within budget.
  std::size_t low = 0, high = taus.size() - 1;
  if (piece_count_at(taus[high]) > budget)
    return pieces_at(std::numeric_limits<double>::infinity());
  while (low < high) {
    const std::size_t middle = (low + high) / 2;
    if (piece_count_at(taus[middle]) <= budget) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return pieces_at(taus[low]);
}

double convexity(const std::vector<Piece>& pieces) {
  double area = 0.0, hull_area = 0.0;
  for (const Piece& piece : pieces) {
    area += region_area(piece.component);
    hull_area += std::abs(signed_area(piece.hull));
  }
  return hull_area > 0.0 ? area / hull_area : 1.0;
}

double max_concavity(const std::vector<Piece>& pieces) {
  double value = 0.0;
  for (const Piece& piece : pieces) value = std::max(value, piece.concavity);
  return value;
}

}  // namespace hullcook
