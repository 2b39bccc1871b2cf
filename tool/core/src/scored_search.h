// Internal: candidates of a cut visited in the order of their scores (Eq. 8, or nearest first)
// until one is accepted, without sorting them all.
#pragma once

#include "decomposition_types.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace hullcook::detail {

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

inline bool scores_before(const ScoredVertex& u, const ScoredVertex& v) {
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

// Scorers of the vertices of a ring as cut ends, which tell without a square root or a division
// that a vertex scores below a threshold: most candidates of a cut lie far from it. A bar is the
// threshold in the scorer's terms; below(i, bar) holds only where score(i) is surely lower (by a
// margin far beyond rounding; a square that overflows or underflows fails the test).
//
// Eq. 8's score of a cut from `from` to vertex i: (1 + sc concave(i)) / (sd |cut|).
struct Eq8 {
  const Ring& ring;
  const std::vector<double>& concavity;
  double sc, sd;
  Vec2 from;
  double score(std::size_t i) const {
    return (1.0 + sc * concavity[i]) / (sd * distance(ring[i], from));
  }
  static double no_bar() { return 0.0; }
  // score < threshold where numerator² < (threshold sd)² |cut|². A square that overflows or
  // underflows bars nothing: an infinite bar would pass over vertices that score higher.
  double bar(double threshold) const {
    const double scaled = threshold * sd;
    const double squared = scaled * scaled;
    return squared > 1e-280 && squared < 1e280 ? squared * (1.0 - 1e-9) : no_bar();
  }
  bool below(std::size_t i, double bar) const {
    const Vec2 d = ring[i] - from;
    const double numerator = 1.0 + sc * concavity[i];
    return numerator * numerator < bar * (d.x * d.x + d.y * d.y);
  }
};

// Nearest first: the score of vertex i is its negated distance from `from`.
struct Nearest {
  const Ring& ring;
  Vec2 from;
  double score(std::size_t i) const { return -distance(ring[i], from); }
  static double no_bar() { return std::numeric_limits<double>::infinity(); }
  // score < threshold where |cut|² exceeds the threshold's square.
  static double bar(double threshold) {
    const double squared = threshold * threshold;
    return squared > 1e-280 && squared < 1e280 ? squared * (1.0 + 1e-9) : no_bar();
  }
  bool below(std::size_t i, double bar) const {
    const Vec2 d = ring[i] - from;
    return d.x * d.x + d.y * d.y > bar;
  }
};

// The top of the vertices each(visit) visits by scores_before; nullopt without candidates.
template <typename Scorer, typename Each>
std::optional<ScoredVertex> top_of(const Scorer& scorer, Each&& each) {
  std::optional<ScoredVertex> top;
  double bar = scorer.no_bar();
  each([&](std::size_t i) {
    if (scorer.below(i, bar)) return;
    const ScoredVertex candidate{scorer.score(i), i};
    if (!top || scores_before(candidate, *top)) {
      top = candidate;
      bar = scorer.bar(candidate.score);
    }
  });
  return top;
}

// The best `count` of the vertices each visits, in order, into best; returns how many it visited.
template <typename Scorer, typename Each>
std::size_t best_few_of(const Scorer& scorer, Each&& each, std::size_t count,
                        std::vector<ScoredVertex>& best) {
  best.clear();
  std::size_t visited = 0;
  double bar = scorer.no_bar();
  each([&](std::size_t i) {
    ++visited;
    if (best.size() == count && scorer.below(i, bar)) return;
    const ScoredVertex candidate{scorer.score(i), i};
    if (best.size() == count && !scores_before(candidate, best.back())) return;
    best.insert(std::upper_bound(best.begin(), best.end(), candidate, scores_before), candidate);
    if (best.size() > count) best.pop_back();
    if (best.size() == count) bar = scorer.bar(best.back().score);
  });
  return visited;
}

// best_accepted_by_score over the scores of the vertices each visits, in that order, scoring
// only what the search needs: a quick search its best few, a full one its top, and every score
// (into candidates) only if accept refuses the top.
template <typename Scorer, typename Each, typename Accept>
std::optional<std::size_t> best_accepted(const Scorer& scorer, Each&& each,
                                         std::vector<ScoredVertex>& candidates, Accept&& accept,
                                         std::size_t quick_tests = 0, bool* gave_up = nullptr) {
  if (quick_tests > 0) {
    // What first_accepted_by_score's quick search tests, in its order.
    thread_local std::vector<ScoredVertex> best_few;
    const std::size_t visited = best_few_of(scorer, each, quick_tests, best_few);
    for (const ScoredVertex& candidate : best_few) {
      if (accept(candidate.index)) return candidate.index;
    }
    if (best_few.size() < visited && gave_up) *gave_up = true;
    return std::nullopt;
  }
  const std::optional<ScoredVertex> top = top_of(scorer, each);
  if (!top) return std::nullopt;
  if (accept(top->index)) return top->index;
  candidates.clear();
  each([&](std::size_t i) { candidates.push_back({scorer.score(i), i}); });
  return first_accepted_by_score(candidates, accept, 0, gave_up);
}

}  // namespace hullcook::detail
