// prepare_process_heap: what a batch process's work allocates after it lies on memory marked for
// transparent huge pages (where the C library is glibc's and the kernel offers them).
#include "hullcook/cook/process_heap.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hullcook {
namespace {

bool huge_pages_offered() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return !modes.empty() && modes.find("[never]") == std::string::npos;
}

// The VmFlags line of the mapping holding address, from /proc/self/smaps ("" if none).
std::string flags_of_mapping_at(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

// In a process of its own: prepare_process_heap is for a process's start, and a test process that
// ran other tests first has a heap laid out by them. Exits 0 when the buffer lies on huge pages,
// 1 (printing the mapping's flags) when not.
[[noreturn]] void prepare_and_check_a_large_buffer() {
  prepare_process_heap();
  prepare_process_heap();  // once per process: a second call changes nothing
  std::vector<char> buffer(std::size_t{4} << 20, 1);  // below the mmap threshold: on the heap
  for (const char* byte : {&buffer.front(), &buffer.back()}) {
    const std::string flags = flags_of_mapping_at(byte);
    if (flags.find(" hg") == std::string::npos) {
      std::fprintf(stderr, "not on huge pages: '%s'\n", flags.c_str());
      std::_Exit(1);
    }
  }
  std::_Exit(0);
}

TEST(ProcessHeap, AfterItALargeBufferLiesWhollyOnMemoryMarkedForHugePages) {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
  GTEST_SKIP() << "the heap is glibc's malloc only";
#endif
  if (!huge_pages_offered()) GTEST_SKIP() << "transparent huge pages are off in this kernel";
  // "threadsafe" runs the check in the test binary started again for this test alone.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(prepare_and_check_a_large_buffer(), testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace hullcook
