#include "hullcook/core/parallel_for.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace hullcook {
namespace {

// Threads kept for the whole process. A thread started for each call took about 57 µs to start
// and join, several times per cook of one sprite (tracing, cleaning, decomposing, the engine
// limits and the contract check each split their items), and lost its thread_local scratch with
// it: a 512 x 512 sprite cooked no faster on two threads than on one (issue 17).
class WorkerPool {
 public:
  // The process's pool. At exit its threads are stopped and joined, so that their thread_local
  // scratch is freed (as a leak checker expects), except in a forked child (the threads are its
  // parent's, and one may have held the mutex or waited on a condition at the fork) and when exit
  // is called from inside a job (a kept thread cannot join itself): there the pool, its threads'
  // handles and its synchronisation are left to the process's end, never destroyed.
  static WorkerPool& instance() {
    struct Owner {
      WorkerPool* const pool = new WorkerPool;
      ~Owner() {
        if (getpid() != pool->owner_ || inside_a_job) return;
        pool->stop_and_join();
        delete pool;
      }
    };
    static Owner owner;
    return *owner.pool;
  }

  // Runs job(worker) on the caller (worker 0) and on up to `helpers` kept threads (workers 1, 2,
  // ...), and returns once all have returned; job must return only when no work is left for any
  // worker (a helper that wakes after the caller's part is not given the job). False (nothing
  // run) when the pool is taken: by another call on another thread, by a call from inside a job,
  // or in a child process forked after the pool started its threads.
  bool run(unsigned helpers, const std::function<void(unsigned)>& job) {
    if (inside_a_job || getpid() != owner_ || busy_.exchange(true)) return false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      // A thread the system refuses is one fewer helper: the others take its items.
      while (threads_.size() < helpers) {
        try {
          threads_.emplace_back([this] { serve(); });
        } catch (const std::system_error&) {
          break;
        }
      }
      job_ = &job;
      wanted_ = std::min<unsigned>(helpers, static_cast<unsigned>(threads_.size()));
      taken_ = finished_ = 0;
      ++generation_;
    }
    wake_.notify_all();
    inside_a_job = true;
    job(0);
    inside_a_job = false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      // The caller's part ends when no item is left: a helper not awake yet would find none.
      wanted_ = taken_;
      done_.wait(lock, [this] { return finished_ == wanted_; });
      job_ = nullptr;
    }
    busy_ = false;
    return true;
  }

 private:
  WorkerPool() : owner_(getpid()) {}

  void stop_and_join() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& thread : threads_) thread.join();
  }

  void serve() {
    inside_a_job = true;  // a kept thread's own calls run without the pool
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || (generation_ != seen && taken_ < wanted_); });
      if (stopping_) return;
      seen = generation_;
      const unsigned worker = ++taken_;
      const std::function<void(unsigned)>& job = *job_;
      lock.unlock();
      job(worker);
      lock.lock();
      if (++finished_ == wanted_) done_.notify_one();
    }
  }

  static thread_local bool inside_a_job;
  const pid_t owner_;
  std::atomic<bool> busy_{false};
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_;
  // The job being run, and how many helpers it asked for, have taken it, have finished it.
  const std::function<void(unsigned)>* job_ = nullptr;
  unsigned wanted_ = 0, taken_ = 0, finished_ = 0;
  std::uint64_t generation_ = 0;  // one per job, so that a helper takes each at most once
  bool stopping_ = false;
};

thread_local bool WorkerPool::inside_a_job = false;

}  // namespace

void run_on_new_threads(unsigned helpers, const std::function<void(unsigned)>& job) {
  std::vector<std::thread> pool;
  // Joined on every way out (an exception from job on the caller, say): an unjoined thread
  // aborts the process.
  struct JoinAll {
    std::vector<std::thread>& threads;
    ~JoinAll() {
      for (std::thread& thread : threads) {
        if (thread.joinable()) thread.join();
      }
    }
  } join_all{pool};
  pool.reserve(helpers);
  for (unsigned t = 1; t <= helpers; ++t) {
    // A thread the system refuses (a limit on threads or address space) is one fewer worker.
    try {
      pool.emplace_back(job, t);
    } catch (const std::system_error&) {
      break;
    }
  }
  job(0);
}

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
  const std::function<void(unsigned)> run = [&](unsigned worker) {
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
  const unsigned helpers = static_cast<unsigned>(std::min<std::size_t>(threads, count)) - 1;
  if (!WorkerPool::instance().run(helpers, run)) run_on_new_threads(helpers, run);
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace hullcook
