// Items filed in numbered buckets (the cells or rows of a spatial grid), each bucket's items in
// the order they were filed: a counting sort into compressed rows. One place for the index that
// the tracer's nesting and untangling grids, the cleaner's crossing grid, the outline distance
// and the output contract's grids each built by hand.
#pragma once

#include "hullcook/core/parallel_for.h"

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace hullcook {

// An allocator whose vectors default-initialize what they grow by: Buckets' second filing writes
// every entry, and value-initializing them first (a zero fill) only touched their pages in
// serially, on the building thread: on two threads, four fifths of the tracer's nesting of
// blobs_2048 (bench_cook) was that fill, with the other thread idle.
template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// entries()[start(b) .. start(b + 1)) are bucket b's, in filing order. Offset is the type of
// the offsets (a narrower one halves the index of a grid with many empty cells).
template <typename Entry, typename Offset = std::size_t>
class Buckets {
 public:
  Buckets() = default;

  // Files entries into bucket_count buckets: file(add) calls add(bucket, entry) for each filing.
  // It is called twice, to count and then to fill, and must file the same entries in the same
  // buckets in the same order both times. It may spread its filings over threads if every
  // bucket is filed from one thread only (each bucket's order is then still its thread's).
  // The storage of an earlier build is reused.
  template <typename File>
  void build(std::size_t bucket_count, File&& file) {
    start_.assign(bucket_count + 1, 0);
    Offset* const counts = start_.data() + 1;
    file([counts](std::size_t bucket, const Entry&) { ++counts[bucket]; });
    for (std::size_t b = 1; b <= bucket_count; ++b) start_[b] += start_[b - 1];
    entries_.resize(static_cast<std::size_t>(start_.back()));
    // Scratch kept per thread (most grids are built once per region or piece), unless a build
    // on this thread is using it (a file that builds buckets of its own). Taken by pointer, so
    // that filings on worker threads share the builder's, not their own thread's.
    struct Claim {
      bool& in_use;
      const bool taken = !in_use;
      explicit Claim(bool& flag) : in_use(flag) { in_use = true; }
      ~Claim() {
        if (taken) in_use = false;
      }
    } claim(scratch_in_use());
    std::vector<Offset> own;
    std::vector<Offset>& next = claim.taken ? scratch() : own;
    next.assign(start_.begin(), start_.end() - 1);
    Offset* const slots = next.data();
    Entry* const entries = entries_.data();
    file([slots, entries](std::size_t bucket, const Entry& entry) {
      entries[slots[bucket]++] = entry;
    });
  }

  // The same for items [0, item_count) filed in item order, split into `parts` consecutive
  // ranges filed on threads of their own: file(part, begin, end, add) calls add(bucket, entry)
  // for the items of [begin, end), twice, the same way both times. Each bucket holds its entries
  // in item order, as one build filing every item in turn would: a counting sort with a count
  // per part and bucket, so that every thread reads only its own items (building by bands of
  // buckets made every thread walk every item).
  template <typename File>
  void build_in_parts(std::size_t bucket_count, std::size_t item_count, unsigned parts,
                      File&& file) {
    if (parts <= 1 || item_count < parts) {
      build(bucket_count, [&](auto&& add) { file(0u, std::size_t{0}, item_count, add); });
      return;
    }
    auto for_each_part = [&](auto&& filing) {
      parallel_for(parts, parts, [&](std::size_t part, unsigned) {
        file(static_cast<unsigned>(part), part * item_count / parts,
             (part + 1) * item_count / parts, filing(part));
      });
    };
    // Per part and bucket: its count, then the slot its next entry goes to.
    std::vector<Offset> slots(parts * bucket_count, 0);
    for_each_part([&](std::size_t part) {
      return [counts = slots.data() + part * bucket_count](std::size_t bucket, const Entry&) {
        ++counts[bucket];
      };
    });
    start_.assign(bucket_count + 1, 0);
    Offset running = 0;
    for (std::size_t b = 0; b < bucket_count; ++b) {
      start_[b] = running;
      for (std::size_t part = 0; part < parts; ++part) {
        Offset& slot = slots[part * bucket_count + b];
        const Offset count = slot;
        slot = running;
        running += count;
      }
    }
    start_[bucket_count] = running;
    entries_.resize(static_cast<std::size_t>(running));
    for_each_part([&](std::size_t part) {
      return [own = slots.data() + part * bucket_count, entries = entries_.data()](
                 std::size_t bucket, const Entry& entry) { entries[own[bucket]++] = entry; };
    });
  }

  std::size_t bucket_count() const { return start_.empty() ? 0 : start_.size() - 1; }
  Offset start(std::size_t bucket) const { return start_[bucket]; }
  std::size_t size(std::size_t bucket) const {
    return static_cast<std::size_t>(start_[bucket + 1] - start_[bucket]);
  }
  bool empty(std::size_t bucket) const { return start_[bucket] == start_[bucket + 1]; }

  const Entry* begin(std::size_t bucket) const { return entries_.data() + start_[bucket]; }
  const Entry* end(std::size_t bucket) const { return entries_.data() + start_[bucket + 1]; }
  // Writable, to reorder a bucket in place (e.g. sort it for a walk).
  Entry* begin(std::size_t bucket) { return entries_.data() + start_[bucket]; }
  Entry* end(std::size_t bucket) { return entries_.data() + start_[bucket + 1]; }

  const std::vector<Entry, DefaultInitAllocator<Entry>>& entries() const { return entries_; }

 private:
  // Per thread and per Buckets type (not per build's File type, which each call site has of its
  // own): a build inside another's file must see the scratch taken.
  static std::vector<Offset>& scratch() {
    thread_local std::vector<Offset> next;
    return next;
  }
  static bool& scratch_in_use() {
    thread_local bool in_use = false;
    return in_use;
  }

  std::vector<Offset> start_;  // bucket b's first entry; start_.back() is the total
  std::vector<Entry, DefaultInitAllocator<Entry>> entries_;  // every one written by a filing
};

}  // namespace hullcook
