#include "cut.h"
#include "resolve.h"
#include "scored_search.h"
#include "sight.h"

namespace hullcook::detail {

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

}  // namespace hullcook::detail
