#include "cut.h"
#include "hidden_vertices.h"
#include "hullcook/core/geometry.h"
#include "resolve.h"
#include "scored_search.h"
#include "sight.h"

#include <algorithm>
#include <functional>

namespace hullcook::detail {
namespace {

// A search with quick_tests > 0 may give up (see first_accepted_by_score): it then returns
// kGaveUp.
constexpr std::size_t kGaveUp = kNone - 1;
// A failed attempt fails again: the searches depend on p (and q) only.
constexpr std::size_t kNotSearched = kNone - 2;
constexpr std::size_t kQuickTests = 16;
// The widened searches (any vertex of the hole) start from this many of its best-placed vertices.
constexpr std::size_t kFirstCutsTried = 4;
// A full search among fewer vertices of ∂P0 tests them all rather than prove some hidden.
constexpr std::size_t kCandidatesWorthHiding = 64;

// The cuts that open one hole, from the paper's (Eq. 5's antipodal pair joined to ∂P0) to the one
// that always exists (a slab cut, see cut_across_slab). Each search reuses the sight lines the
// earlier ones tested.
class HoleOpener {
 public:
  HoleOpener(const Region& region, const Evaluation& e, std::size_t h,
             const DecomposeSettings& settings, std::pair<ParentHint, ParentHint>& hints)
      : region_(region),
        e_(e),
        h_(h),
        settings_(settings),
        hints_(hints),
        view_(region),
        outer_(region.outer),
        hole_(region.holes[h]),
        hole_ring_(static_cast<int>(h + 1)),
        info_(e.holes[h]),
        sees_known_(hole_.size()),
        closest_visible_from_(hole_.size(), kNotSearched) {
    view_.expect_many_tests();
  }

  std::optional<std::pair<Region, Region>> open() {
    if (auto pieces = to_outer_from_antipodal_pairs()) return pieces;
    if (auto pieces = to_outer_from_any_vertices()) return pieces;
    // The holes holding the vertices nearest to the antipodal pair (Eq. 5's x, before a cycle of
    // closest vertices sent it to ∂P0).
    const HoleEnds& ends = e_.hole_ends[h_];
    int tried = -1;
    for (const NearVertex* nearest : {&ends.from_p, &ends.from_q}) {
      if (!nearest->known() || nearest->ring == 0 || nearest->ring == tried) continue;
      tried = nearest->ring;
      if (auto pieces = to_hole(static_cast<std::size_t>(nearest->ring - 1))) return pieces;
    }
    hints_.first.reset(), hints_.second.reset();
    if (auto pieces = cut_across_slab(region_, h_)) {
      if (!has_sliver(*pieces) || !sliver_fallback_) return pieces;
    }
    // Every cut left a sliver (a region this thin all over): the first found is still a cut.
    if (sliver_fallback_) return sliver_fallback_();
    return std::nullopt;
  }

 private:
  bool sees(std::size_t p, std::size_t i) {
    std::vector<signed char>& known = sees_known_[p];
    if (known.empty()) known.assign(outer_.size(), -1);
    if (known[i] < 0) known[i] = view_.is_diagonal({hole_ring_, p}, {0, i}) ? 1 : 0;
    return known[i] == 1;
  }

  std::size_t closest_visible(std::size_t p, std::size_t quick_tests) {
    // Eq. 5 found the vertex nearest to the joined end, by the same distances and tie-break: when
    // it lies on ∂P0 and p sees it, no other vertex needs a look.
    if (p == info_.joined && info_.closest_ring == 0 && sees(p, info_.closest)) {
      return info_.closest;
    }
    const std::vector<signed char>* const known = hidden_from(p, quick_tests);
    auto each = [&](auto&& visit) {
      for (std::size_t i = 0; i < outer_.size(); ++i) {
        if (!known || (*known)[i] != 0) visit(i);
      }
    };
    thread_local std::vector<ScoredVertex> candidates;
    bool gave_up = false;
    const auto chosen = best_accepted(
        Nearest{outer_, hole_[p]}, each, candidates, [&](std::size_t i) { return sees(p, i); },
        quick_tests, &gave_up);
    return chosen ? *chosen : gave_up ? kGaveUp : kNone;
  }

  // A full search returns the best vertex p sees, whichever others it leaves out, so it leaves
  // out those proved hidden (a quick search tests its first few whatever they are): p's entries
  // of sees_known_ with them marked unseen, else null. Proving takes the grid of the region's
  // edges, which a search of a few candidates does without.
  const std::vector<signed char>* hidden_from(std::size_t p, std::size_t quick_tests) {
    if (quick_tests != 0 || outer_.size() < kCandidatesWorthHiding) return nullptr;
    std::vector<signed char>& seen = sees_known_[p];
    if (seen.empty()) seen.assign(outer_.size(), -1);
    if (!hidden_) {
      hidden_.emplace(outer_);
      hidden_proved_.assign(hole_.size(), 0);
    }
    // Once per vertex: a second proof would try again the runs the first could not prove.
    if (!hidden_proved_[p]) {
      hidden_->refuse(view_, {hole_ring_, p}, seen);
      hidden_proved_[p] = 1;
    }
    return &seen;
  }

  // The vertex of ∂P0 but x that q's cut best reaches by Eq. 8 without meeting p-x.
  std::size_t best_second(std::size_t p, std::size_t x, std::size_t q, std::size_t quick_tests) {
    const Eq8 eq8{outer_, e_.outer.vertex, settings_.sc, settings_.sd, hole_[q]};
    const std::vector<signed char>* const known = hidden_from(q, quick_tests);
    auto each = [&](auto&& visit) {
      for (std::size_t i = 0; i < outer_.size(); ++i) {
        if (i != x && (!known || (*known)[i] != 0)) visit(i);
      }
    };
    thread_local std::vector<ScoredVertex> candidates;
    bool gave_up = false;
    const auto chosen = best_accepted(
        eq8, each, candidates,
        [&](std::size_t i) {
          return sees(q, i) && !segments_intersect(hole_[p], outer_[x], hole_[q], outer_[i]);
        },
        quick_tests, &gave_up);
    return chosen ? *chosen : gave_up ? kGaveUp : kNone;
  }

  // Algorithm 4.2 as the paper has it: the hole's end nearer to ∂P0 (Eq. 5) joined to the closest
  // vertex it sees, its antipode to the best vertex by Eq. 8; then the other antipodal pairs.
  std::optional<std::pair<Region, Region>> to_outer_from_antipodal_pairs() {
    std::vector<std::pair<std::size_t, std::size_t>> attempts{{info_.joined, info_.far_end},
                                                              {info_.far_end, info_.joined}};
    for (std::size_t i = 0; i < hole_.size(); ++i) {
      attempts.emplace_back(i, (i + hole_.size() / 2) % hole_.size());
    }
    // A hole vertex walled in by other holes sees no vertex of ∂P0, and its searches are refused
    // by every candidate: on the neuron, three such searches of a thousand candidates each took a
    // quarter of the decomposition. The attempts are first made with quick searches, and only if
    // none succeeds, again with full ones. A quick success is what the full search would return,
    // so the first pass returns what the second would unless an earlier attempt needs a full
    // search.
    for (const std::size_t quick_tests : {kQuickTests, std::size_t(0)}) {
      for (std::size_t a = 0; a < attempts.size(); ++a) {
        const auto [p, q] = attempts[a];
        if (p == q) continue;
        if (a >= 2 && (attempts[a] == attempts[0] || attempts[a] == attempts[1])) continue;
        std::size_t& x = closest_visible_from_[p];
        if (x == kNotSearched || (x == kGaveUp && quick_tests == 0)) {
          x = closest_visible(p, quick_tests);
        }
        if (x == kNone || x == kGaveUp) continue;
        const std::size_t y = best_second(p, x, q, quick_tests);
        if (y == kNone || y == kGaveUp) continue;
        if (auto pieces = to_outer(p, x, q, y)) return pieces;
      }
    }
    return std::nullopt;
  }

  // Any two vertices of the hole that see distinct vertices of ∂P0 (a hole whose antipodal pairs
  // are walled in, or whose ∂P0 has few vertices: a square with four diamond holes, issue 16).
  // After the full searches above, every vertex's closest visible vertex of ∂P0 is known.
  std::optional<std::pair<Region, Region>> to_outer_from_any_vertices() {
    std::vector<std::pair<double, std::size_t>> seeing;  // (cut length, hole vertex)
    for (std::size_t p = 0; p < hole_.size(); ++p) {
      const std::size_t x = closest_visible_from_[p];
      if (x < outer_.size()) seeing.emplace_back(distance(hole_[p], outer_[x]), p);
    }
    std::sort(seeing.begin(), seeing.end());
    for (std::size_t first = 0; first < std::min(seeing.size(), kFirstCutsTried); ++first) {
      const std::size_t p = seeing[first].second, x = closest_visible_from_[p];
      for (const auto& [length, q] : seeing) {
        if (q == p) continue;
        const std::size_t x_q = closest_visible_from_[q];
        const std::size_t y =
            x_q != x && !segments_intersect(hole_[p], outer_[x], hole_[q], outer_[x_q])
                ? x_q
                : best_second(p, x, q, kQuickTests);
        if (y >= outer_.size()) continue;
        if (auto pieces = to_outer(p, x, q, y)) return pieces;
      }
    }
    return std::nullopt;
  }

  // Two cuts to another hole, which merge the two (Fig. 12(b)'s dependency, resolved at once):
  // each vertex of this hole joined to the closest vertex of the other that it sees; the shortest
  // such cut, and the shortest that neither shares an end with it nor meets it.
  std::optional<std::pair<Region, Region>> to_hole(std::size_t other) {
    const Ring& across = region_.holes[other];
    const int other_ring = static_cast<int>(other + 1);
    struct Cut {
      double length;
      std::size_t p, u;
      bool operator<(const Cut& c) const {
        return length != c.length ? length < c.length : p != c.p ? p < c.p : u < c.u;
      }
    };
    std::vector<Cut> cuts;
    std::vector<ScoredVertex> candidates(across.size());
    for (std::size_t p = 0; p < hole_.size(); ++p) {
      for (std::size_t u = 0; u < across.size(); ++u) {
        candidates[u] = {-distance(across[u], hole_[p]), u};
      }
      bool gave_up = false;
      const auto u = best_accepted_by_score(
          candidates,
          [&](std::size_t i) {
            return view_.is_diagonal({hole_ring_, p}, {other_ring, i});
          },
          kQuickTests, &gave_up);
      if (u) cuts.push_back({distance(across[*u], hole_[p]), p, *u});
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t first = 0; first < std::min(cuts.size(), kFirstCutsTried); ++first) {
      const Cut& a = cuts[first];
      for (const Cut& b : cuts) {
        if (b.p == a.p || b.u == a.u) continue;
        if (segments_intersect(hole_[a.p], across[a.u], hole_[b.p], across[b.u])) continue;
        const auto make = [this, other, a, b] {
          return split_between_holes(region_, h_, a.p, b.p, other, a.u, b.u, e_.outer,
                                     inherits_values(settings_), hints_);
        };
        if (auto pieces = make();
            pieces && accept(*pieces, {hole_[a.p], across[a.u]}, {hole_[b.p], across[b.u]}, make)) {
          return pieces;
        }
      }
    }
    return std::nullopt;
  }

  std::optional<std::pair<Region, Region>> to_outer(std::size_t p, std::size_t x, std::size_t q,
                                                    std::size_t y) {
    const auto make = [this, p, x, q, y] {
      return split_hole(region_, h_, p, x, q, y, e_.outer, inherits_values(settings_), hints_);
    };
    std::pair<Region, Region> pieces = make();
    if (accept(pieces, {hole_[p], outer_[x]}, {hole_[q], outer_[y]}, make)) return pieces;
    return std::nullopt;
  }

  // Cuts that leave a sliver or graze a vertex (through near-collinear vertices of different
  // rings, issue 16) are kept only as a last resort; make remakes them.
  using Segment = std::pair<Vec2, Vec2>;
  template <typename Make>
  bool accept(const std::pair<Region, Region>& pieces, const Segment& cut, const Segment& other_cut,
              const Make& make) {
    if (!has_sliver(pieces) && !view_.grazes_a_vertex(cut.first, cut.second) &&
        !view_.grazes_a_vertex(other_cut.first, other_cut.second)) {
      return true;
    }
    if (!sliver_fallback_) {
      sliver_fallback_ = [make]() -> std::optional<std::pair<Region, Region>> { return make(); };
    }
    return false;
  }

  // The piece with fewer vertices: slivers come from a few near-collinear vertices, and every
  // hole resolution checks its cut.
  static bool has_sliver(const std::pair<Region, Region>& pieces) {
    const Ring& first = pieces.first.outer;
    const Ring& second = pieces.second.outer;
    return is_sliver(first.size() <= second.size() ? first : second);
  }

  const Region& region_;
  const Evaluation& e_;
  const std::size_t h_;
  const DecomposeSettings& settings_;
  std::pair<ParentHint, ParentHint>& hints_;
  RegionView view_;
  const Ring& outer_;
  const Ring& hole_;
  const int hole_ring_;
  const HoleConcavity& info_;
  // The searches from p and from q ask the same sight lines when an attempt's q is a later p,
  // and a refused search asks all of them: each is computed once.
  std::vector<std::vector<signed char>> sees_known_;
  std::vector<std::size_t> closest_visible_from_;
  std::optional<HiddenVertices> hidden_;  // made by the first full search
  std::vector<char> hidden_proved_;       // per vertex of the hole: its hidden vertices marked
  std::function<std::optional<std::pair<Region, Region>>()> sliver_fallback_;
};

}  // namespace

std::optional<std::pair<Region, Region>> resolve_hole(const Region& region, const Evaluation& e,
                                                      std::size_t h,
                                                      const DecomposeSettings& settings,
                                                      std::pair<ParentHint, ParentHint>& hints) {
  return HoleOpener(region, e, h, settings, hints).open();
}

}  // namespace hullcook::detail
