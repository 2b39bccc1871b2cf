// The stress generators make what they promise: the same case from the same seed, valid input
// almost always, the shapes of each family, and placements across the scales.
#include "generators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace hullcook::stress {
namespace {

constexpr int kSeeds = 200;

TEST(Generators, ASeedNamesOneCase) {
  for (Family family : all_families()) {
    const GeneratedCase a = generate_case(family, 42), b = generate_case(family, 42);
    ASSERT_EQ(a.regions.size(), b.regions.size()) << family_name(family);
    for (std::size_t r = 0; r < a.regions.size(); ++r) {
      EXPECT_EQ(a.regions[r].outer, b.regions[r].outer) << family_name(family);
      EXPECT_EQ(a.regions[r].holes, b.regions[r].holes) << family_name(family);
    }
    EXPECT_EQ(a.description, b.description);
    EXPECT_NE(a.description, generate_case(family, 43).description) << family_name(family);
  }
}

TEST(Generators, AlmostEveryCaseIsValidInputWithHoles) {
  for (Family family : all_families()) {
    int rejected = 0, with_holes = 0;
    for (int seed = 0; seed < kSeeds; ++seed) {
      const GeneratedCase generated = generate_case(family, seed);
      if (!generated.rejection.empty()) {
        ++rejected;
        continue;
      }
      ASSERT_FALSE(generated.regions.empty());
      with_holes += !generated.regions[0].holes.empty();
    }
    EXPECT_LE(rejected, kSeeds / 50) << family_name(family);
    if (family == Family::random_simple) {
      EXPECT_EQ(with_holes, 0);
    } else {
      EXPECT_GE(with_holes, kSeeds * 9 / 10) << family_name(family);
    }
  }
}

TEST(Generators, GridsAndRowsHaveFourVertexOuterBoundariesAndUpTo400Holes) {
  std::size_t most = 0;
  for (Family family : {Family::grid, Family::row, Family::thin_wall}) {
    for (int seed = 0; seed < kSeeds; ++seed) {
      const GeneratedCase generated = generate_case(family, seed);
      if (generated.regions.empty()) continue;
      EXPECT_EQ(generated.regions[0].outer.size(), 4u) << family_name(family) << " " << seed;
      EXPECT_LE(generated.regions[0].holes.size(), 400u);
      most = std::max(most, generated.regions[0].holes.size());
    }
  }
  EXPECT_GE(most, 200u);
}

TEST(Generators, PlacementsSpanTheScalesOffsetsAndRoundings) {
  int small = 0, large = 0, far = 0, rounded = 0, thin = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const GeneratedCase generated = generate_case(Family::thin_wall, seed);
    const std::string& text = generated.description;
    if (generated.regions.empty()) continue;
    const Vec2 p = generated.regions[0].outer[0];
    far += std::abs(p.x) > 5e4;
    const double scale = std::stod(text.substr(text.find("scale ") + 6));
    small += scale < 0.1;
    large += scale > 100;
    rounded += text.substr(text.rfind("rounding ") + 9) != "0";
    thin += generated.thinnest_feature / scale <= 0.01 * 1.000001;
  }
  EXPECT_GE(small, kSeeds / 20);
  EXPECT_GE(large, kSeeds / 20);
  EXPECT_GE(far, kSeeds / 10);
  EXPECT_GE(rounded, kSeeds / 10);
  EXPECT_GE(thin, kSeeds / 20);
}

}  // namespace
}  // namespace hullcook::stress
