// Internal to the cooker: items (a ring's edges) in runs of 16 and runs of 256 runs, each run with
// a summary of its items (a box, coordinate ranges), so that a query skips the runs whose summary
// shows they cannot hold its answer. HullLines and NearestEdges search a hull's edges this way.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace hullcook {

template <typename Summary>
class Runs {
 public:
  static constexpr std::size_t kRun = 16, kRunsOfRun = 16;

  // The summaries of count items, each starting as empty: add(summary, i) adds item i to its
  // run's and to its run of runs'.
  template <typename Add>
  void build(std::size_t count, const Summary& empty, Add&& add) {
    count_ = count;
    runs_.clear(), groups_.clear();
    for (std::size_t i = 0; i < count; ++i) {
      if (i % kRun == 0) runs_.push_back(empty);
      if (i % (kRun * kRunsOfRun) == 0) groups_.push_back(empty);
      add(runs_.back(), i);
      add(groups_.back(), i);
    }
  }

  // Calls visit(i) in index order for the items of each run whose summary, and its run of runs',
  // skip(summary) does not refuse, until visit returns false.
  template <typename Skip, typename Visit>
  void for_each(Skip&& skip, Visit&& visit) const {
    for (std::size_t group = 0; group < groups_.size(); ++group) {
      if (skip(groups_[group])) continue;
      const std::size_t last_run = std::min(runs_.size(), (group + 1) * kRunsOfRun);
      for (std::size_t run = group * kRunsOfRun; run < last_run; ++run) {
        if (skip(runs_[run])) continue;
        for (std::size_t i = run * kRun, end = std::min(count_, i + kRun); i < end; ++i) {
          if (!visit(i)) return;
        }
      }
    }
  }

 private:
  std::size_t count_ = 0;
  std::vector<Summary> runs_, groups_;
};

}  // namespace hullcook
