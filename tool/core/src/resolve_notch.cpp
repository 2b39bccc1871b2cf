#include "cut.h"
#include "predicates_inline.h"
#include "resolve.h"
#include "scored_search.h"
#include "sight.h"

#include <algorithm>
#include <array>

namespace hullcook::detail {
namespace {

// The edges (by their first vertex) that blocked a notch's last candidate diagonals, tried
// first: in a maze most candidates by Eq. 8 run into a wall, and the same wall blocks many of
// them, where the scan of the whole ring found it anew each time (a 1 Mpx maze: 17-26 s, a
// helper's hunt, stop 60). A blocker found here is one the scan finds: the answer is the same.
class RecentBlockers {
 public:
  // Whether an edge kept here crosses u-v as is_diagonal_of_outer counts a crossing.
  bool block(const Ring& ring, std::size_t u, std::size_t v) const {
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < count_; ++k) {
      const std::size_t i = edges_[k], j = i + 1 == n ? 0 : i + 1;
      if (i == u || i == v || j == u || j == v) continue;
      if (segments_intersect(ring[u], ring[v], ring[i], ring[j])) return true;
    }
    return false;
  }
  void add(std::size_t edge) {
    edges_[next_] = edge;
    next_ = (next_ + 1) % edges_.size();
    count_ = std::min(count_ + 1, edges_.size());
  }

 private:
  std::array<std::size_t, 4> edges_{};
  std::size_t next_ = 0, count_ = 0;
};

// RegionView::is_diagonal for a region without holes, in one tight pass over the ring: a notch is
// resolved once per split, and the scan was a tenth of the time of the straight-line measure.
// Sets *grazes when the diagonal grazes a vertex (see Graze), and *blocker to the first vertex of
// the edge it crosses, if any.
bool is_diagonal_of_outer(const RegionView& view, const Ring& ring, std::size_t u, std::size_t v,
                          bool* grazes, std::size_t* blocker) {
  const Vec2 a = ring[u], b = ring[v];
  if (a == b || !view.in_cone({0, u}, b) || !view.in_cone({0, v}, a)) return false;
  const Graze graze(a, b);
  const double min_x = graze.min_x, max_x = graze.max_x;
  const double min_y = graze.min_y, max_y = graze.max_y;
  const std::size_t n = ring.size();
  Vec2 c = ring[n - 1];
  for (std::size_t j = 0, i = n - 1; j < n; i = j++) {
    const Vec2 d = ring[j];
    const bool apart = (c.x < min_x && d.x < min_x) || (c.x > max_x && d.x > max_x) ||
                       (c.y < min_y && d.y < min_y) || (c.y > max_y && d.y > max_y);
    if (!apart && i != u && i != v) {
      if (j != u && j != v && segments_intersect(a, b, c, d)) {
        *blocker = i;
        return false;
      }
      if (graze.by(c)) *grazes = true;
    }
    c = d;
  }
  return true;
}

// Whether the diagonal u-v cuts a sliver off the ring (see is_sliver). Slivers come from a few
// near-collinear vertices, so only the side with fewer vertices is measured: a decomposition
// resolves a notch per node, and measuring both sides cost 7-11 % of SL's instructions.
bool cuts_off_sliver(const Ring& ring, std::size_t u, std::size_t v) {
  const std::size_t n = ring.size();
  const std::size_t forward = (v + n - u) % n + 1;  // vertices from u to v
  return forward <= n + 2 - forward ? is_sliver(ring, u, v) : is_sliver(ring, v, u);
}

}  // namespace

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
  // The vertices that resolve r (a diagonal there splits its reflex angle), scored by Eq. 8 only
  // as far as the search needs (see best_accepted).
  thread_local std::vector<std::size_t> resolving;
  thread_local std::vector<ScoredVertex> scored;
  std::vector<ScoredVertex> others;
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
  // Only grown, never cleared: the first resolving_count entries are this call's (a resize after
  // a clear zero-filled n entries per split, 1 % of SP's instructions).
  if (resolving.size() < n) resolving.resize(n);
  std::size_t resolving_count = 0;
  auto take = [&](std::size_t i) { resolving[resolving_count++] = i; };
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
  // A diagonal that grazes a vertex or cuts off a sliver (through near-collinear vertices, issue
  // 16) is taken only when no other is valid.
  std::optional<std::size_t> sliver_cut;
  RecentBlockers blockers;
  auto is_valid_cut = [&](std::size_t i) {
    bool grazes = false;
    if (region.holes.empty()) {
      if (blockers.block(ring, r, i)) return false;
      std::size_t blocker = n;
      if (!is_diagonal_of_outer(view, ring, r, i, &grazes, &blocker)) {
        if (blocker < n) blockers.add(blocker);
        return false;
      }
    } else if (!view.is_diagonal({0, r}, {0, i})) {
      return false;
    }
    if (!grazes && !cuts_off_sliver(ring, r, i)) return true;
    if (!sliver_cut) sliver_cut = i;
    return false;
  };
  const Eq8 eq8{ring, concavity.vertex, settings.sc, settings.sd, pr};
  auto each_resolving = [&](auto&& visit) {
    for (std::size_t k = 0; k < resolving_count; ++k) visit(resolving[k]);
  };
  if (const auto chosen = best_accepted(eq8, each_resolving, scored, is_valid_cut)) {
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
          others, scores_before, [&](const ScoredVertex& c) { return is_valid_cut(c.index); })) {
    return split_outer(region, r, chosen->index, concavity, inherits_values(settings), hints);
  }
  // A notch no deeper than the sliver width is rounding, not shape (the contract measures
  // concavity with that width as slack): it is left rather than cut off as a sliver.
  if (sliver_cut && !is_rounding_deep(concavity.value))
    return split_outer(region, r, *sliver_cut, concavity, inherits_values(settings), hints);
  return std::nullopt;
}

}  // namespace hullcook::detail
