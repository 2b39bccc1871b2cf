#include "hullcook/core/buckets.h"

#include "hullcook/core/parallel_for.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace hullcook {
namespace {

// Seeded filings (item, bucket), as a grid files edges: some buckets empty, some with many.
std::vector<std::pair<int, std::size_t>> filings(std::size_t buckets, std::size_t count,
                                                 unsigned seed) {
  std::mt19937 random(seed);
  std::vector<std::pair<int, std::size_t>> out;
  for (std::size_t i = 0; i < count; ++i) {
    // Half the filings in the first tenth of the buckets: crowded cells beside empty ones.
    const std::size_t span = random() % 2 ? buckets : std::max<std::size_t>(buckets / 10, 1);
    out.emplace_back(static_cast<int>(random() % 1000), random() % span);
  }
  return out;
}

// What the index must hold: per bucket, its entries in filing order.
std::vector<std::vector<int>> expected(const std::vector<std::pair<int, std::size_t>>& filed,
                                       std::size_t buckets) {
  std::vector<std::vector<int>> per_bucket(buckets);
  for (const auto& [item, bucket] : filed) per_bucket[bucket].push_back(item);
  return per_bucket;
}

template <typename Offset>
void expect_holds(const Buckets<int, Offset>& index,
                  const std::vector<std::vector<int>>& per_bucket) {
  ASSERT_EQ(index.bucket_count(), per_bucket.size());
  std::size_t total = 0;
  for (std::size_t b = 0; b < per_bucket.size(); ++b) {
    EXPECT_EQ(static_cast<std::size_t>(index.start(b)), total) << "bucket " << b;
    EXPECT_EQ(std::vector<int>(index.begin(b), index.end(b)), per_bucket[b]) << "bucket " << b;
    EXPECT_EQ(index.size(b), per_bucket[b].size());
    EXPECT_EQ(index.empty(b), per_bucket[b].empty());
    total += per_bucket[b].size();
  }
  EXPECT_EQ(index.entries().size(), total);
}

TEST(Buckets, EachBucketHoldsItsEntriesInFilingOrder) {
  for (unsigned seed : {1u, 2u, 3u}) {
    for (std::size_t buckets : {std::size_t(1), std::size_t(7), std::size_t(1000)}) {
      const auto filed = filings(buckets, 5000, seed);
      Buckets<int, std::uint32_t> index;
      index.build(buckets, [&](auto&& add) {
        for (const auto& [item, bucket] : filed) add(bucket, item);
      });
      expect_holds(index, expected(filed, buckets));
    }
  }
}

TEST(Buckets, ARebuildForgetsTheLastBuild) {
  Buckets<int> index;
  const auto first = filings(50, 400, 4), second = filings(9, 30, 5);
  index.build(50, [&](auto&& add) {
    for (const auto& [item, bucket] : first) add(bucket, item);
  });
  index.build(9, [&](auto&& add) {
    for (const auto& [item, bucket] : second) add(bucket, item);
  });
  expect_holds(index, expected(second, 9));
  index.build(3, [](auto&&) {});
  expect_holds(index, expected({}, 3));
}

// A file that builds buckets of its own (the same types) on the same thread: each build keeps its
// own filling position, and both indexes hold their entries.
TEST(Buckets, ABuildInsideAFileKeepsBothIndexes) {
  const auto outer_filed = filings(40, 300, 7), inner_filed = filings(25, 200, 8);
  Buckets<int> outer, inner;
  outer.build(40, [&](auto&& add) {
    for (std::size_t k = 0; k < outer_filed.size(); ++k) {
      if (k == outer_filed.size() / 2) {
        inner.build(25, [&](auto&& add_inner) {
          for (const auto& [item, bucket] : inner_filed) add_inner(bucket, item);
        });
      }
      add(outer_filed[k].second, outer_filed[k].first);
    }
  });
  {
    SCOPED_TRACE("outer");
    expect_holds(outer, expected(outer_filed, 40));
  }
  SCOPED_TRACE("inner");
  expect_holds(inner, expected(inner_filed, 25));
}

// Filings spread over threads, each band of buckets filed by one thread (as the tracer's grids
// file their rows), give the one-thread index.
TEST(Buckets, FiledByBandsOnThreadsAsByOneThread) {
  const int rows = 300;
  const auto filed = filings(rows, 20000, 6);
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    const int bands = band_count(rows, threads, true);
    Buckets<int, int> index;
    index.build(rows, [&](auto&& add) {
      parallel_for_bands(rows, bands, [&](std::size_t, int low, int high) {
        for (const auto& [item, bucket] : filed) {
          if (static_cast<int>(bucket) >= low && static_cast<int>(bucket) < high) add(bucket, item);
        }
      });
    });
    expect_holds(index, expected(filed, rows));
  }
}

// Filings split into consecutive parts of the items, each part on a thread of its own (as the
// tracer's nesting and untangling grids file their edges), give the one-thread index: every
// bucket in item order, whatever the count of parts, also with fewer items than parts.
TEST(Buckets, FiledInPartsOnThreadsAsByOneThread) {
  for (std::size_t buckets : {std::size_t(1), std::size_t(7), std::size_t(300)}) {
    for (std::size_t count : {std::size_t(0), std::size_t(2), std::size_t(20000)}) {
      const auto filed = filings(buckets, count, 9);
      for (unsigned parts : {1u, 2u, 3u, 8u}) {
        SCOPED_TRACE(testing::Message()
                     << buckets << " buckets, " << count << " items, " << parts << " parts");
        Buckets<int, int> index;
        std::vector<int> filed_by_part(count, -1);
        // Twice: a rebuild of an index built before forgets it.
        for (int round = 0; round < 2; ++round) {
          index.build_in_parts(buckets, count, parts,
                               [&](unsigned part, std::size_t begin, std::size_t end, auto&& add) {
                                 for (std::size_t i = begin; i < end; ++i) {
                                   filed_by_part[i] = static_cast<int>(part);
                                   add(filed[i].second, filed[i].first);
                                 }
                               });
        }
        expect_holds(index, expected(filed, buckets));
        // Consecutive ranges, every item in one.
        EXPECT_TRUE(std::is_sorted(filed_by_part.begin(), filed_by_part.end()));
        EXPECT_EQ(std::count(filed_by_part.begin(), filed_by_part.end(), -1), 0);
      }
    }
  }
}

}  // namespace
}  // namespace hullcook
