#include "hullcook/core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace hullcook {

void parallel_for(std::size_t count, unsigned threads,
                  const std::function<void(std::size_t, unsigned)>& work, std::size_t min_count) {
  if (threads <= 1 || count < std::max<std::size_t>(min_count, 2)) {
    for (std::size_t i = 0; i < count; ++i) work(i, 0);
    return;
  }
  std::vector<std::exception_ptr> errors(count);
  std::atomic<std::size_t> next{0};
  // Past an error, the items after it are skipped: the call throws the first error by index, as
  // the serial loop does, and their results are not read.
  std::atomic<std::size_t> first_error{count};
  auto run = [&](unsigned worker) {
    for (std::size_t i = next++; i < count; i = next++) {
      if (i > first_error.load(std::memory_order_relaxed)) continue;
      try {
        work(i, worker);
      } catch (...) {
        errors[i] = std::current_exception();
        std::size_t seen = first_error.load(std::memory_order_relaxed);
        while (i < seen && !first_error.compare_exchange_weak(seen, i)) {
        }
      }
    }
  };
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(threads, count));
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (unsigned t = 1; t < workers; ++t) {
    // A thread the system refuses is one fewer worker: the others take its items.
    try {
      pool.emplace_back(run, t);
    } catch (const std::system_error&) {
      break;
    }
  }
  run(0);
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace hullcook
