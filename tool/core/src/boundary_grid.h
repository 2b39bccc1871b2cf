// Internal: the best scored vertices of ∂P0 round a point, by a grid. A hole's quick searches ask
// for the few vertices of ∂P0 nearest to each of its vertices (and the few best by Eq. 8 for the
// second cut); one scan of ∂P0 per search was a fifth of the decomposition of a noise texture's
// 1,177 holes (issue 17).
#pragma once

#include "decomposition_types.h"
#include "hullcook/core/buckets.h"
#include "scored_search.h"
#include "square_layers.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hullcook::detail {

class BoundaryGrid {
 public:
  // ring: it must outlive this object.
  explicit BoundaryGrid(const Ring& ring);

  // The best `count` vertices of the ring by the scorer's scores (a scorer of scored_search.h
  // whose `from` is from), but `skip`, in scores_before order: what best_few_of(scorer, every
  // vertex but skip, count, best) gives. best_beyond(reach) bounds from above the score of every
  // vertex at least reach (> 0) away from `from`. False (best unset) where the grid cannot tell:
  // then scan.
  template <typename Scorer, typename BestBeyond>
  bool best_few(const Scorer& scorer, Vec2 from, std::size_t count, std::size_t skip,
                BestBeyond&& best_beyond, std::vector<ScoredVertex>& best) const {
    if (cells_.bucket_count() == 0 || count == 0 || !std::isfinite(from.x) ||
        !std::isfinite(from.y)) {
      return false;
    }
    best.clear();
    double bar = scorer.no_bar();
    // As best_few_of offers each vertex: the same scores, the same order, so the same best few
    // of the vertices offered.
    auto offer = [&](std::size_t i) {
      if (i == skip || (best.size() == count && scorer.below(i, bar))) return;
      const ScoredVertex candidate{scorer.score(i), i};
      if (best.size() == count && !scores_before(candidate, best.back())) return;
      best.insert(std::upper_bound(best.begin(), best.end(), candidate, scores_before), candidate);
      if (best.size() > count) best.pop_back();
      if (best.size() == count) bar = scorer.bar(best.back().score);
    };
    auto visit_cell = [&](int x, int y) {
      const std::size_t cell = static_cast<std::size_t>(y) * columns_ + static_cast<std::size_t>(x);
      for (const std::uint32_t* k = cells_.begin(cell); k != cells_.end(cell); ++k) offer(*k);
    };
    // Square layers of cells round from's cell (from's nearest point of the grid's box, whose
    // distances to the vertices are no longer than from's). After layer L every vertex left lies
    // more than L cells away in x or y; one cell less covers the rounding of the cell assignment.
    const int column = column_of(from.x), row = row_of(from.y);
    for (int layer = 0; visit_square_layer(column, row, layer, columns_, rows_, visit_cell);
         ++layer) {
      if (best.size() < count) continue;
      // Every vertex left scores lower than the last of the best few, by far more than the
      // rounding of a score.
      const double reach = (layer - 1) * cell_size_;
      const double last = best.back().score;
      if (reach > 0.0 && best_beyond(reach) < last - 1e-6 * std::abs(last)) break;
    }
    return true;
  }

 private:
  int column_of(double x) const;
  int row_of(double y) const;

  const Ring& ring_;
  double min_x_ = 0.0, min_y_ = 0.0, cell_size_ = 0.0, scale_ = 0.0;
  int columns_ = 1, rows_ = 1;
  Buckets<std::uint32_t, std::uint32_t> cells_;  // vertex indices per cell (none: no grid)
};

}  // namespace hullcook::detail
