// glTF with --meshopt (EXT_meshopt_compression + KHR_mesh_quantization): decoded by
// meshoptimizer's reference decoder and read by the glTF rules (no writer code), every level's
// hulls are within half a grid step of the cooked ones, on the stated grid, and the mesh is the
// finest level.
#include "gltf_test_support.h"
#include "sample_assets.h"

#include "hullcook/cook/gltf_writer.h"
#include "hullcook/core/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcook {
namespace {

using json = nlohmann::json;

// Every level of every asset, read back through the node's translation and scale, lies within
// half a step of the cooked hulls; the mesh's POSITION is the finest level, its indices fans
// that stay within each hull.
void expect_meshopt_file_holds(const std::vector<CookedAsset>& assets, bool binary) {
  const test::Parsed parsed =
      test::parse(write_gltf(assets, {.binary = binary, .meshopt = true}), binary);
  const json& root = parsed.root;
  EXPECT_EQ(root["extensionsRequired"],
            json::array({"EXT_meshopt_compression", "KHR_mesh_quantization"}));
  ASSERT_EQ(root["buffers"].size(), 2u);
  EXPECT_FALSE(root["buffers"][1].contains("uri"));
  EXPECT_EQ(root["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"], true);
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const CookedAsset& asset = assets[a];
    const json& node = root["nodes"][root["scenes"][0]["nodes"][a].get<std::size_t>()];
    ASSERT_EQ(node["name"], asset.name);
    const double step = node["scale"][0];
    EXPECT_EQ(node["scale"][1].get<double>(), step);
    const Vec2 origin{node["translation"][0].get<double>(), node["translation"][1].get<double>()};
    const json& levels = node["extras"]["hullcook"]["levels"];
    ASSERT_EQ(levels.size(), asset.levels.size());
    if (test::vertex_count({asset}) > 0) {
      EXPECT_LE(step, test::largest_meshopt_step(asset) * (1 + 1e-12)) << asset.name;
    }
    for (std::size_t l = 0; l < asset.levels.size(); ++l) {
      const std::vector<Ring>& hulls = asset.levels[l].hulls;
      if (hulls.empty()) {
        EXPECT_FALSE(levels[l].contains("counts"));
        continue;
      }
      const std::vector<double> counts = test::accessor_values(parsed, levels[l]["counts"]);
      const json& accessor = root["accessors"][levels[l]["vertices"].get<std::size_t>()];
      EXPECT_EQ(accessor["componentType"], 5122);  // SHORT
      const std::size_t components = accessor["type"] == "VEC2" ? 2 : 3;
      const std::vector<double> values = test::accessor_values(parsed, levels[l]["vertices"]);
      ASSERT_EQ(counts.size(), hulls.size());
      std::size_t next = 0;
      for (std::size_t h = 0; h < hulls.size(); ++h) {
        ASSERT_EQ(counts[h], hulls[h].size());
        for (const Vec2& cooked : hulls[h]) {
          const Vec2 read{origin.x + step * values.at(next * components),
                          origin.y + step * values.at(next * components + 1)};
          EXPECT_LE(std::abs(read.x - cooked.x), 0.5 * step * (1 + 1e-9)) << asset.name;
          EXPECT_LE(std::abs(read.y - cooked.y), 0.5 * step * (1 + 1e-9)) << asset.name;
          ++next;
        }
      }
      EXPECT_EQ(next * components, values.size());
      if (l != 0) continue;

      const json& primitive = root["meshes"][node["mesh"].get<std::size_t>()]["primitives"][0];
      EXPECT_EQ(primitive["attributes"]["POSITION"], levels[0]["vertices"]);
      for (std::size_t axis = 0; axis < 3; ++axis) {
        double min = 1e300, max = -1e300;
        for (std::size_t i = axis; i < values.size(); i += 3) {
          min = std::min(min, values[i]), max = std::max(max, values[i]);
        }
        EXPECT_EQ(accessor["min"][axis].get<double>(), min);
        EXPECT_EQ(accessor["max"][axis].get<double>(), max);
      }
      const std::vector<double> indices = test::accessor_values(parsed, primitive["indices"]);
      std::vector<std::size_t> first{0};
      for (const Ring& hull : hulls) first.push_back(first.back() + hull.size());
      std::size_t fan_triangles = 0;
      for (const Ring& hull : hulls) fan_triangles += hull.size() >= 3 ? hull.size() - 2 : 0;
      EXPECT_EQ(indices.size(), 3 * fan_triangles) << asset.name;
      for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const auto h = std::upper_bound(first.begin(), first.end(), std::size_t(indices[t])) -
                       first.begin() - 1;
        for (int c = 0; c < 3; ++c) {
          EXPECT_GE(indices[t + c], first[h]) << "a triangle across two hulls";
          EXPECT_LT(indices[t + c], first[h + 1]) << "a triangle across two hulls";
        }
      }
    }
  }
}

TEST(GltfMeshopt, HandMadeAssetsWithinHalfAStep) {
  for (bool binary : {false, true}) expect_meshopt_file_holds(test::all_sample_assets(), binary);
}

TEST(GltfMeshopt, SampleSpritesWithinHalfAStep) {
  expect_meshopt_file_holds(test::sample_sprites({Tolerance{8.0, false}}), true);
}

// Where the extent sets the step (extent / 65 000), extent / step can come back a few ulps over
// 65 000: a generated polygon 2e6 wide was refused ("its hulls do not fit a 16-bit grid", exit 3).
TEST(GltfMeshopt, HullsWhoseExtentSetsTheStepAreWritten) {
  const double extent = 4328237.9119826285;  // extent / (extent / 65000) > 65000 in doubles
  ASSERT_GT(extent / (extent / 65000.0), 65000.0);
  CookedAsset asset = test::base_asset("wide");
  asset.pixels_per_unit = 1.0;
  asset.levels.push_back({asset.tau, {{{0.0, 0.0}, {extent, 0.0}, {extent, 3.0}, {0.0, 7.0}}}});
  expect_meshopt_file_holds({asset}, true);
}

TEST(GltfMeshopt, SameBytesEveryRun) {
  const GltfOptions options{.binary = true, .meshopt = true};
  EXPECT_EQ(write_gltf(test::all_sample_assets(), options),
            write_gltf(test::all_sample_assets(), options));
}

TEST(GltfMeshopt, DracoAndMeshoptTogetherAreRefused) {
  EXPECT_THROW(write_gltf(test::all_sample_assets(), {.draco = true, .meshopt = true}), UsageError);
}

}  // namespace
}  // namespace hullcook
