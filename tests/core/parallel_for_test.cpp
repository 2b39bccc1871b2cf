// parallel_for and parallel_join (issue 17: one image's regions, rings and pieces split over the
// cook's threads): every item done once, in its own slot, the results joined in index order, and
// the error thrown the first by index whatever the thread count.
#include "hullcook/core/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hullcook {
namespace {

TEST(ParallelFor, EveryItemOnceWithAWorkerBelowTheThreadCount) {
  for (unsigned threads : {1u, 2u, 3u, 8u, 64u}) {
    for (std::size_t count : {0u, 1u, 2u, 15u, 16u, 1000u}) {
      std::vector<int> done(count, 0);
      std::atomic<bool> worker_in_range{true};
      parallel_for(
          count, threads,
          [&](std::size_t i, unsigned worker) {
            ++done[i];
            if (worker >= threads || worker >= count) worker_in_range = false;
          },
          16);
      EXPECT_EQ(done, std::vector<int>(count, 1)) << threads << " threads, " << count;
      EXPECT_TRUE(worker_in_range) << threads << " threads, " << count;
    }
  }
}

TEST(ParallelFor, TheFirstErrorByIndexIsThrownAfterEveryItemBeforeIt) {
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<std::atomic<int>> done(500);
    try {
      parallel_for(500, threads, [&](std::size_t i, unsigned) {
        ++done[i];
        if (i == 77 || i == 301 || i == 420) throw std::runtime_error("item " + std::to_string(i));
      });
      ADD_FAILURE() << threads << " threads: nothing thrown";
    } catch (const std::runtime_error& error) {
      EXPECT_STREQ(error.what(), "item 77") << threads << " threads";
    }
    for (std::size_t i = 0; i <= 77; ++i) EXPECT_EQ(done[i], 1) << threads << " threads, " << i;
    for (std::size_t i = 78; i < 500; ++i) EXPECT_LE(done[i], 1) << threads << " threads, " << i;
  }
}

// Items that make none, one or several results each: the joined vector is the serial loop's.
TEST(ParallelJoin, ResultsInIndexOrderWhateverTheThreadCount) {
  auto produce = [](std::size_t i, unsigned, std::vector<std::size_t>& out) {
    for (std::size_t k = 0; k < i % 4; ++k) out.push_back(i * 10 + k);
  };
  for (std::size_t count : {0u, 1u, 15u, 16u, 17u, 999u}) {
    std::vector<std::size_t> serial;
    for (std::size_t i = 0; i < count; ++i) produce(i, 0, serial);
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
      EXPECT_EQ(parallel_join<std::size_t>(count, threads, produce), serial)
          << threads << " threads, " << count << " items";
    }
  }
}

TEST(ParallelJoin, TheFirstErrorByIndexIsThrown) {
  for (unsigned threads : {1u, 2u, 3u}) {
    try {
      parallel_join<int>(300, threads, [](std::size_t i, unsigned, std::vector<int>& out) {
        if (i == 40 || i == 250) throw std::runtime_error("item " + std::to_string(i));
        out.push_back(static_cast<int>(i));
      });
      ADD_FAILURE() << threads << " threads: nothing thrown";
    } catch (const std::runtime_error& error) {
      EXPECT_STREQ(error.what(), "item 40") << threads << " threads";
    }
  }
}

// Bands of rows: one per thread, none empty, together every row once and in order.
TEST(ParallelForBands, EveryRowInOneBandInOrder) {
  EXPECT_EQ(band_count(1000, 8, false), 1);
  EXPECT_EQ(band_count(1000, 1, true), 1);
  EXPECT_EQ(band_count(3, 8, true), 3);
  for (int rows : {1, 2, 7, 1000}) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
      const int bands = band_count(rows, threads, true);
      std::vector<std::pair<int, int>> spans(static_cast<std::size_t>(bands));
      parallel_for_bands(rows, bands, [&](std::size_t band, int first, int end) {
        spans[band] = {first, end};
      });
      int next = 0;
      for (const auto& [first, end] : spans) {
        EXPECT_EQ(first, next) << rows << " rows, " << threads << " threads";
        EXPECT_LT(first, end) << rows << " rows, " << threads << " threads";
        next = end;
      }
      EXPECT_EQ(next, rows) << rows << " rows, " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace hullcook
