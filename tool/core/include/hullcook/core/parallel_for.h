// Work split over a few threads with results that never depend on how many.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iterator>
#include <vector>

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

// Runs job(worker) on the caller (worker 0) and on up to `helpers` threads started for this call
// (workers 1 ..), and returns when every one has; for work that must not share the process's
// pool (a cook's assets, each of which runs parallel_for). A thread the system refuses is one
// fewer helper: the others take its share. Every thread started is joined, however job ends.
void run_on_new_threads(unsigned helpers, const std::function<void(unsigned worker)>& job);

// parallel_for over the ranges [begin, end) of at most `chunk` items each, for items so small
// (a ring's nesting query) that handing them out one by one would cost more than they do.
inline void parallel_for_ranges(
    std::size_t count, unsigned threads, std::size_t chunk,
    const std::function<void(std::size_t begin, std::size_t end, unsigned worker)>& work) {
  const std::size_t ranges = (count + chunk - 1) / chunk;
  parallel_for(ranges, threads, [&](std::size_t r, unsigned worker) {
    work(r * chunk, std::min(count, (r + 1) * chunk), worker);
  });
}

// How many bands of consecutive rows work on `rows` rows splits into: one per thread, at most one
// per row, and one when the work is not worth a thread.
inline int band_count(int rows, unsigned threads, bool worth_a_thread) {
  return worth_a_thread && threads > 1 ? static_cast<int>(std::min<long long>(threads, rows)) : 1;
}

// Runs work(band, first_row, end_row) for each of `bands` bands of rows [0, rows), in order of
// rows and each on a thread of its own: for grids every worker builds by walking all the items in
// order and writing only its own rows, which keeps each row in the one-thread order.
inline void parallel_for_bands(
    int rows, int bands, const std::function<void(std::size_t band, int first, int end)>& work) {
  const std::size_t count = static_cast<std::size_t>(std::max(bands, 1));
  parallel_for(count, static_cast<unsigned>(count), [&](std::size_t band, unsigned) {
    work(band, static_cast<int>(band * rows / count), static_cast<int>((band + 1) * rows / count));
  });
}

// Below this many items (pieces, rings, trees), doing them all on the caller costs less than
// starting a thread; regions, each several pieces' work, are worth one from fewer.
inline constexpr std::size_t kItemsWorthAThread = 16;
inline constexpr std::size_t kRegionsWorthAThread = 8;

// Runs produce(i, worker, out) for every i below count on up to `threads` threads, each i
// appending what it makes to an `out` of its own, and returns the outs joined in index order:
// the same vector whatever the thread count. On one thread, or below min_count items, every i
// appends to the result itself, which first reserves `expected` (a guess of the total: a
// doubling vector of large items, reallocated, held both copies at once). Errors as
// parallel_for's.
template <typename T, typename Produce>
std::vector<T> parallel_join(std::size_t count, unsigned threads, const Produce& produce,
                             std::size_t min_count = kItemsWorthAThread, std::size_t expected = 0) {
  std::vector<T> joined;
  if (threads <= 1 || count < min_count) {
    joined.reserve(expected);
    for (std::size_t i = 0; i < count; ++i) produce(i, 0u, joined);
    return joined;
  }
  std::vector<std::vector<T>> outs(count);
  parallel_for(
      count, threads, [&](std::size_t i, unsigned worker) { produce(i, worker, outs[i]); },
      min_count);
  std::size_t total = 0;
  for (const std::vector<T>& out : outs) total += out.size();
  joined.reserve(total);
  for (std::vector<T>& out : outs) std::move(out.begin(), out.end(), std::back_inserter(joined));
  return joined;
}

}  // namespace hullcook
