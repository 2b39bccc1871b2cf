#include "outer_concavity.h"

#include "hullcook/core/geometry.h"
#include "pocket_paths.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>

namespace hullcook::detail {
namespace {

bool is_notch(const Ring& ring, std::size_t i) {
  const std::size_t n = ring.size();
  return detail::fast_orient2d(ring[prev_index(i, n)], ring[i], ring[next_index(i, n)]) < 0.0;
}

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

}  // namespace

void measure_outer(const Ring& ring, Measure measure, double tau, OuterConcavity& result,
                   PocketCache* cache, const ParentHint* hint) {
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

}  // namespace hullcook::detail
