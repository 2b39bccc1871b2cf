// The drawn sprites are what they claim: the same image from the same seed, tilesets with many
// holes, the 1000x1000 sheet with its 400 cells, and long outlines of thousands of vertices.
#include "images.h"

#include "hullcook/trace/trace.h"

#include <gtest/gtest.h>

namespace hullcook::stress {
namespace {

TEST(Images, TilesetsHaveManyHolesAndTheGridSheetIsAThousandPixelsSquare) {
  TraceSettings settings;
  for (int seed = 0; seed < 20; ++seed) {
    const DrawnImage image = draw_image(ImageFamily::tileset, seed);
    const TraceResult traced = trace_alpha({image.width, image.height, image.alpha}, settings);
    std::size_t holes = 0;
    for (const Region& region : traced.regions) holes += region.holes.size();
    EXPECT_GE(holes, 4u) << image.description;
  }
  const DrawnImage sheet = draw_image(ImageFamily::grid_sheet, 0);
  EXPECT_EQ(sheet.width, 1000);
  EXPECT_EQ(sheet.height, 1000);
  const TraceResult traced = trace_alpha({sheet.width, sheet.height, sheet.alpha}, settings);
  ASSERT_EQ(traced.regions.size(), 1u);
  EXPECT_EQ(traced.regions[0].holes.size(), 400u);
}

// Most long outlines trace to a ring of 4,096 vertices or more, which the simplifier searches by
// its tree of blocks: one region each, without holes.
TEST(Images, LongOutlinesTraceToThousandsOfVertices) {
  TraceSettings settings;
  int long_ones = 0;
  for (int seed = 0; seed < 20; ++seed) {
    const DrawnImage image = draw_image(ImageFamily::long_outline, seed);
    const TraceResult traced = trace_alpha({image.width, image.height, image.alpha}, settings);
    ASSERT_EQ(traced.regions.size(), 1u) << image.description;
    EXPECT_TRUE(traced.regions[0].holes.empty()) << image.description;
    long_ones += traced.traced_vertices >= 4096;
  }
  EXPECT_GE(long_ones, 18);
}

TEST(Images, ASeedNamesOneImage) {
  for (ImageFamily family : all_image_families()) {
    const DrawnImage a = draw_image(family, 7), b = draw_image(family, 7);
    EXPECT_EQ(a.alpha, b.alpha) << image_family_name(family);
    EXPECT_EQ(a.description, b.description);
  }
}

}  // namespace
}  // namespace hullcook::stress
