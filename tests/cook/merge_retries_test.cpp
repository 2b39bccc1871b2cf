// Which failed slots merging tries again (merge_retries.h): those that now share two points with
// a grown slot's parts, or grew themselves; not those that grown slots touch at a single point.
#include "merge_retries.h"

#include <gtest/gtest.h>

#include <vector>

namespace hullcook {
namespace {

using Touch = MergeRetries::Touch;

// Slots 1..n, the thin triangles of a fan in order round its apex, each failed touching every
// other at the apex and its neighbours along an edge; slot 0, placed, lies next to slot 1.
MergeRetries failed_fan(std::size_t n) {
  const Vec2 apex{0, 0};
  MergeRetries retries;
  retries.reset(n + 1);
  for (std::size_t k = 1; k <= n; ++k) {
    std::vector<Touch> touching;
    for (std::size_t j = 0; j <= n; ++j) {
      if (j == k) continue;
      const bool next_to = j + 1 == k || k + 1 == j;
      touching.push_back({j, next_to ? 2 : 1, apex});
    }
    retries.failed(k, touching);
    EXPECT_FALSE(retries.worth_trying(k));
  }
  return retries;
}

TEST(MergeRetries, AFanGrowingAtItsApexRetriesOnlyThePieceNextToIt) {
  constexpr std::size_t kPieces = 50;
  MergeRetries retries = failed_fan(kPieces);
  for (std::size_t k = 1; k < kPieces; ++k) {
    retries.merged(k, 0);  // slot 0 takes slot k: it now shares an edge with slot k + 1 alone
    EXPECT_TRUE(retries.worth_trying(0));
    for (std::size_t j = k + 1; j <= kPieces; ++j) {
      EXPECT_EQ(retries.worth_trying(j), j == k + 1) << "after " << k << " merged, slot " << j;
    }
    // Slot k + 1 is tried again, and fails: listed at its first failure, it is not listed again.
    retries.failed(k + 1, {});
    EXPECT_FALSE(retries.worth_trying(k + 1));
  }
}

TEST(MergeRetries, PartsTouchingAtDifferentPointsMayShareAnEdgeOnceJoined) {
  MergeRetries retries;
  retries.reset(4);
  // Slot 3 touched slots 1 and 2 at one point each; slot 0 touched nothing.
  retries.failed(3, {{1, 1, Vec2{0, 0}}, {2, 1, Vec2{1, 0}}});
  retries.merged(0, 1);  // slot 1 grew by a slot that touched nothing of slot 3
  EXPECT_FALSE(retries.worth_trying(3));
  EXPECT_TRUE(retries.worth_trying(1));
  retries.merged(2, 1);  // slot 1 now holds both points
  EXPECT_TRUE(retries.worth_trying(3));
}

TEST(MergeRetries, PartsTouchingAtOnePointStayApart) {
  MergeRetries retries;
  retries.reset(4);
  // -0 and 0 are one point.
  retries.failed(3, {{1, 1, Vec2{-0.0, 2}}, {2, 1, Vec2{0.0, 2}}});
  retries.merged(2, 1);
  EXPECT_FALSE(retries.worth_trying(3));
}

TEST(MergeRetries, ANeighbourAlongAnEdgeIsRetriedWheneverItGrows) {
  MergeRetries retries;
  retries.reset(3);
  retries.failed(2, {{0, 2, Vec2{}}});
  retries.failed(1, {});
  retries.merged(1, 0);  // slot 0 grew by a slot that touched nothing of slot 2
  EXPECT_TRUE(retries.worth_trying(2));
}

TEST(MergeRetries, ASlotThatGrewIsTriedAgainAndOneNeverTriedIsTried) {
  MergeRetries retries;
  retries.reset(3);
  retries.failed(0, {});
  retries.failed(1, {});
  EXPECT_FALSE(retries.worth_trying(0));
  retries.merged(1, 0);
  EXPECT_TRUE(retries.worth_trying(0));
  EXPECT_TRUE(retries.worth_trying(2));
}

}  // namespace
}  // namespace hullcook
