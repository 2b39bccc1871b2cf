// Internal to the cooker: the nearest edge of a ring, for many points (HullFitter's depths).
#pragma once

#include "hullcook/core/geometry.h"
#include "hullcook/core/polygon.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace hullcook {

// The nearest edge of a ring to each of many points, as a scan of every edge in index order finds
// it (the least squared distance, and of those edges the first). The edges are grouped in runs of
// 16 (and runs of 256) with their boxes, and a run is skipped where its box lies farther from the
// point than the nearest edge found, by a margin beyond rounding. Mending measured every component
// vertex against every hull edge: a 20,000-vertex circle spent a quarter of its cook there.
class NearestEdges {
 public:
  explicit NearestEdges(const Ring& ring) : ring_(ring) {
    const std::size_t n = ring.size();
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = ring[i], b = ring[i + 1 == n ? 0 : i + 1];
      finite = finite && std::isfinite(a.x) && std::isfinite(a.y);
      scale_ = std::max({scale_, std::abs(a.x), std::abs(a.y)});
      if (i % kRun == 0) runs_.push_back(kEmpty);
      if (i % (kRun * kRunsOfRun) == 0) groups_.push_back(kEmpty);
      for (Box* box : {&runs_.back(), &groups_.back()}) {
        box->low = glm::min(box->low, glm::min(a, b));
        box->high = glm::max(box->high, glm::max(a, b));
      }
    }
    use_runs_ = finite && n >= 64;
  }

  // As squared_distance_and_edge(p, ring), with the edge's index; hint: an edge to measure first.
  std::pair<double, std::size_t> operator()(Vec2 p, std::size_t hint) const {
    const std::size_t n = ring_.size();
    double best = std::numeric_limits<double>::infinity();
    std::size_t at = 0;
    if (!use_runs_) {
      for (std::size_t i = 0; i < n; ++i) {
        const double squared =
            point_segment_distance_squared(p, ring_[i], ring_[i + 1 == n ? 0 : i + 1]);
        if (squared < best) best = squared, at = i;
      }
      return {best, at};
    }
    auto measure = [&](std::size_t i) {
      const double squared =
          point_segment_distance_squared(p, ring_[i], ring_[i + 1 == n ? 0 : i + 1]);
      // The least distance, and of those the lowest index, as the scan in index order finds.
      if (squared < best || (squared == best && i < at)) best = squared, at = i;
    };
    if (hint < n) measure(hint);
    const double margin = 1e-12 * (scale_ + std::abs(p.x) + std::abs(p.y));
    auto beyond = [&](const Box& box) {
      const double dx = std::max({box.low.x - p.x, 0.0, p.x - box.high.x});
      const double dy = std::max({box.low.y - p.y, 0.0, p.y - box.high.y});
      return std::sqrt(dx * dx + dy * dy) > std::sqrt(best) * (1 + 1e-12) + margin;
    };
    for (std::size_t group = 0; group < groups_.size(); ++group) {
      if (beyond(groups_[group])) continue;
      const std::size_t last_run = std::min(runs_.size(), (group + 1) * kRunsOfRun);
      for (std::size_t run = group * kRunsOfRun; run < last_run; ++run) {
        if (beyond(runs_[run])) continue;
        for (std::size_t i = run * kRun, end = std::min(n, i + kRun); i < end; ++i) measure(i);
      }
    }
    return {best, at};
  }

 private:
  struct Box {
    Vec2 low, high;
  };
  static constexpr std::size_t kRun = 16, kRunsOfRun = 16;
  static constexpr Box kEmpty{Vec2{std::numeric_limits<double>::infinity()},
                              Vec2{-std::numeric_limits<double>::infinity()}};
  const Ring& ring_;
  std::vector<Box> runs_, groups_;
  double scale_ = 0;
  bool use_runs_ = false;
};

}  // namespace hullcook
