#include "hullcook/cook/process_heap.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <mutex>

namespace hullcook {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr int kHugeHeap = 64 << 20;        // [bytes] of heap prepared for huge pages
constexpr int kDefaultTopPad = 128 << 10;  // glibc's M_TOP_PAD
constexpr std::size_t kProbeReach = std::size_t{16} << 20;  // below the mmap threshold

// The heap below the first whole huge page, kept allocated (never freed, so never reused).
// Volatile: the compiler would otherwise drop the allocation of a block that nothing reads.
void* volatile g_below_first_huge_page = nullptr;

// Grows the heap by kHugeHeap (and kProbeReach) at once and marks its whole huge pages
// MADV_HUGEPAGE (what glibc's glibc.malloc.hugetlb=1 tunable does, which a program cannot set for
// itself). The heap starts anywhere within a huge page, and the part below the first whole one gets
// small pages: a block over that part is kept allocated (untouched but for its header), so that the
// work's blocks start on a huge page. Only address space is reserved: pages are allocated when
// touched.
void reserve_huge_heap() {
#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  mallopt(M_TOP_PAD, kHugeHeap);
  // Larger than the free top of the heap (keepcost), so that the heap grows now, by the pad;
  // freed, it joins the top again, which then starts where it started. Growing writes a header
  // at the probe's end, before the advice: that huge page is left to small pages, so the probe
  // is long enough (kProbeReach) for the work to start far below it.
  void* probe = std::malloc(mallinfo2().keepcost + kProbeReach);
  mallopt(M_TOP_PAD, kDefaultTopPad);
  if (probe == nullptr) return;
  const auto top = reinterpret_cast<std::uintptr_t>(probe);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(kHugePage - 1);
  std::free(probe);
  const std::uintptr_t begin = (top + kHugePage - 1) & ~(kHugePage - 1);
  // The probe lies in the heap (below the mmap threshold set first) unless sbrk failed.
  if (top >= end || end <= begin) return;
  constexpr std::uintptr_t kChunkHeader = 2 * sizeof(std::size_t);
  if (begin - top > 2 * kChunkHeader)
    g_below_first_huge_page = std::malloc(begin - top - kChunkHeader);
  madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice: may fail
#endif
}

}  // namespace

void keep_freed_memory() {
  static std::once_flag kept;
  std::call_once(kept, [] {
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
  });
}

void prepare_process_heap() {
  keep_freed_memory();  // first: the probe below must come from the heap, not a mapping
  static std::once_flag prepared;
  std::call_once(prepared, reserve_huge_heap);
}

}  // namespace hullcook
