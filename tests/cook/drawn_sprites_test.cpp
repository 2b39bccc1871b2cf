// Issue 16 on sprites the test draws: thin bars, specks near the weld size, rings, spokes and a
// seeded set of random ones, cooked at the scales the issue is checked at.
#include "drawn_sprites.h"
#include "contract.h"

#include "hullcook/cook/cook.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace hullcook {
namespace {

using test::Scale;

class DrawnSpriteContract : public ::testing::TestWithParam<Scale> {
 protected:
  void SetUp() override {
    // ctest runs test cases in parallel: one directory per case.
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');
    directory = std::filesystem::temp_directory_path() / ("hullcook_drawn_" + name);
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
  }
  void TearDown() override { std::filesystem::remove_all(directory); }

  std::filesystem::path directory;
};

// Every drawn sprite keeps the contract: no piece dropped (the areas add up), every hull
// engine-ready and within τ of the outline. The random set's seed was picked so that the engine
// limits of before issue 16 dropped slivers from two of its sprites at 100 px per unit.
TEST_P(DrawnSpriteContract, EveryDrawnSpriteKeepsTheContract) {
  std::vector<test::DrawnSprite> sprites = test::drawn_sprites();
  for (test::DrawnSprite& sprite : test::random_sprites(16, 40))
    sprites.push_back(std::move(sprite));
  for (const test::DrawnSprite& sprite : sprites) {
    std::ofstream(directory / sprite.name, std::ios::binary) << sprite.png();
  }
  Settings settings;
  settings.tau = Tolerance{GetParam().tau_px, false};
  settings.pixels_per_unit = GetParam().pixels_per_unit;
  CookResult result = cook({directory}, settings);
  ASSERT_EQ(result.assets.size(), sprites.size());
  EngineLimits limits{settings.max_verts, kDefaultWeld};
  for (const CookedAsset& asset : result.assets) {
    SCOPED_TRACE(asset.name);
    EXPECT_FALSE(asset.pieces.empty());
    for (const std::string& warning : asset.warnings) {
      EXPECT_EQ(warning.find("too small"), std::string::npos) << warning;
    }
    test::expect_cooked_contract(asset, asset.tau, limits);
  }
}

INSTANTIATE_TEST_SUITE_P(Issue16, DrawnSpriteContract,
                         ::testing::Values(Scale{1, 1}, Scale{4, 1}, Scale{1, 100},
                                           Scale{0.5, 100}));

}  // namespace
}  // namespace hullcook
