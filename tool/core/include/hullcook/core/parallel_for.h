// Work split over a few threads with results that never depend on how many.
#pragma once

#include <cstddef>
#include <functional>

namespace hullcook {

// Runs work(i, worker) for every i below count on up to `threads` threads, the caller's included
// (worker: which of them, below min(threads, count), for scratch kept per worker). Each i's result
// must go to its own slot, so that nothing depends on the thread count. Below min_count items the
// caller does them all: a thread costs more than small work. The first exception by index is
// rethrown, once every item before it has run (items after it may be skipped). When the system
// refuses a thread, the threads it started do the work.
void parallel_for(std::size_t count, unsigned threads,
                  const std::function<void(std::size_t index, unsigned worker)>& work,
                  std::size_t min_count = 2);

}  // namespace hullcook
