// `hullcook inspect` on bundles: the text summary, the debug JSON (hulls within the quantization
// bound of the cooked ones), and exit code 2 with the status in words for bad files.
#include "synthetic_assets.h"

#include "../cli/run_command.h"
#include "hullcook/cook/bundle_writer.h"
#include "hullcook/format/bundle_layout.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace hullcook {
namespace {

namespace fs = std::filesystem;

fs::path work_dir() {
  const fs::path dir = fs::path(HULLCOOK_BINARY_DIR) / "tests/formats/inspect_test";
  fs::create_directories(dir);
  return dir;
}

fs::path write(const std::string& name, const std::string& bytes) {
  const fs::path path = work_dir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(Inspect, PrintsASummaryOfABundle) {
  const fs::path path = write("synthetic.hcb", write_bundle(test::synthetic_assets()));
  const auto result = test::run_hullcook("inspect " + path.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("hullcook bundle 1.0"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("6 assets"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("bytes per vertex"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("asset \"terrain/hill.png\""), std::string::npos);
  EXPECT_NE(result.output.find("level 2: tau 24, 1 hull, 5 vertices"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("physics: density 2.5, friction 0.6"), std::string::npos)
      << result.output;
}

TEST(Inspect, JsonGivesTheCookedHullsBackWithinTheQuantizationBound) {
  const std::vector<CookedAsset> assets = test::synthetic_assets();
  const fs::path path = write("synthetic_json.hcb", write_bundle(assets));
  const auto result = test::run_hullcook("inspect --json " + path.string() + " 2>/dev/null");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const nlohmann::json root = nlohmann::json::parse(result.output);
  EXPECT_EQ(root["hullcook"], 1);
  ASSERT_EQ(root["assets"].size(), assets.size());
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const CookedAsset& cooked = assets[a];
    const nlohmann::json& asset = root["assets"][a];
    EXPECT_EQ(asset["name"], cooked.name);
    EXPECT_EQ(asset["transform"]["flip_y"], cooked.transform.flip_y);
    EXPECT_NEAR(asset["transform"]["scale"].get<double>(), 1.0 / cooked.pixels_per_unit, 1e-9);
    if (cooked.levels.empty()) continue;
    ASSERT_EQ(asset["levels"].size(), cooked.levels.size());
    ASSERT_EQ(asset["pieces"].size(), cooked.levels[0].hulls.size());
    const double bound =
        format::quantization_error_bound(cooked.levels[0].tau, cooked.pixels_per_unit);
    for (std::size_t l = 0; l < cooked.levels.size(); ++l) {
      const nlohmann::json& hulls = asset["levels"][l]["hulls"];
      ASSERT_EQ(hulls.size(), cooked.levels[l].hulls.size());
      for (std::size_t h = 0; h < hulls.size(); ++h) {
        // Every stored vertex lies within the bound of the cooked hull's boundary or inside it;
        // here simply within bound of some cooked vertex or edge.
        for (const auto& point : hulls[h]) {
          const Vec2 p{point[0].get<double>(), point[1].get<double>()};
          const Ring& ring = cooked.levels[l].hulls[h];
          double best = 1e300;
          for (std::size_t i = 0; i < ring.size(); ++i) {
            const Vec2 a0 = ring[i], b0 = ring[(i + 1) % ring.size()], ab = b0 - a0;
            const double t = std::clamp(
                ((p.x - a0.x) * ab.x + (p.y - a0.y) * ab.y) / (ab.x * ab.x + ab.y * ab.y), 0.0,
                1.0);
            best = std::min(best, std::hypot(p.x - a0.x - t * ab.x, p.y - a0.y - t * ab.y));
          }
          EXPECT_LE(best, bound * (1 + 1e-5) + 1e-6) << cooked.name;
        }
      }
      if (l == 0 && !hulls.empty()) {
        EXPECT_EQ(asset["pieces"][0]["hull"], hulls[0]) << cooked.name;
      }
    }
  }
}

TEST(Inspect, BadFilesPrintTheirStatusAndExitWith2) {
  std::string bytes = write_bundle(test::synthetic_assets());
  std::string corrupt = bytes;
  corrupt[200] ^= 0x40;
  const fs::path checksum = write("corrupt.hcb", corrupt);
  const fs::path truncated = write("truncated.hcb", bytes.substr(0, 100));
  // Shorter than the header itself: the message said "shorter than the bundle's header says"
  // of a file with no header to say anything (a helper's sweep, stop 54).
  const fs::path empty = write("empty.hcb", "");
  const fs::path ten_bytes = write("ten_bytes.hcb", bytes.substr(0, 10));
  // hullcook's other outputs are named as what they are (the sweep found "bad magic" alone).
  const fs::path debug_json = write("debug.json", "{\"hullcook\": 1,\n \"assets\": []}\n");
  const fs::path fragment = write("sprite.hcf", std::string("HCF\x1a", 4) + std::string(60, '\0'));
  const fs::path text =
      write("text.hcb", "hello, this is not a bundle at all, but long enough for a header!");
  const struct {
    fs::path path;
    std::string words;
  } cases[] = {{checksum, "bad checksum"},
               {truncated, "truncated"},
               {empty, "truncated (shorter than the 64-byte header"},
               {debug_json, "; it is JSON, as hullcook's debug JSON is"},
               {fragment, "it is a hullcook fragment (.hcf): `hullcook link` it"},
               {ten_bytes, "truncated (shorter than the 64-byte header"},
               {text, "not a hullcook bundle"},
               {work_dir() / "missing.hcb", "could not be opened"}};
  for (const auto& c : cases) {
    const auto result = test::run_hullcook("inspect " + c.path.string());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(c.words), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(c.path.filename().string()), std::string::npos) << result.output;
  }
}

// From the adversarial review of 2026-12-01: a file name that is not UTF-8 was written raw, and
// strict JSON parsers refused the debug JSON of `cook` and of `inspect --json`.
TEST(Inspect, ReviewNamesThatAreNotUtf8GiveValidJson) {
  const std::string name = std::string("caf\xc3\xa9/a\xff") + "b\xe2\x82.png";
  const fs::path bundle = write(
      "latin1.hcb", write_bundle({test::make_asset(name, {{1.0, {test::rectangle(0, 0, 4, 2)}}})}));
  const auto result = test::run_hullcook("inspect " + bundle.string() + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  nlohmann::json json;
  ASSERT_NO_THROW(json = nlohmann::json::parse(result.output)) << result.output;
  // Valid sequences are kept; each byte that starts none becomes U+FFFD.
  EXPECT_EQ(json["assets"][0]["name"], "caf\u00e9/a\ufffdb\ufffd\ufffd.png");
}

// Stop 60's review: glTF and JSON outputs refuse two names that U+FFFD would make one; a bundle
// keeps the bytes, and `inspect --json` prints such a bundle (its names as the debug JSON
// spells them), which the refusal inside the JSON writer had made exit 3.
TEST(Inspect, Stop60_ABundleOfNamesAlikeInUtf8IsPrintedAsJson) {
  const fs::path bundle =
      write("alike.hcb",
            write_bundle({test::make_asset("x\xfe", {{1.0, {test::rectangle(0, 0, 4, 2)}}}),
                          test::make_asset("x\xff", {{1.0, {test::rectangle(0, 0, 2, 4)}}})}));
  const auto result = test::run_hullcook("inspect " + bundle.string() + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  nlohmann::json json;
  ASSERT_NO_THROW(json = nlohmann::json::parse(result.output)) << result.output;
  ASSERT_EQ(json["assets"].size(), 2u);
  EXPECT_EQ(json["assets"][1]["name"], "x\ufffd");
}

// Review of stop 61's glTF checks: inspect read a glTF's floats as their shortest decimals,
// which can turn a nearly straight run of three hull vertices the other way; it refused files
// that cook wrote (19 of a helper's 2,500: a pivot 1,000 sprites away, --ppu 7.3 --weld 0).
// The hulls are checked as stored (and printed by their shortest decimals, as before).
TEST(Inspect, Stop61_AGltfIsCheckedOnItsFloatsAsStored) {
  const fs::path sprite =
      fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites/teeworlds__mapres__jungle_midground.png";
  for (const char* name : {"far_pivot.glb", "far_pivot.gltf"}) {
    const fs::path out = work_dir() / name;
    const auto cooked =
        test::run_hullcook("cook " + sprite.string() + " --pivot 1000,1000 -q -o " + out.string());
    ASSERT_EQ(cooked.exit_code, 0) << cooked.output;
    const auto text = test::run_hullcook("inspect " + out.string());
    EXPECT_EQ(text.exit_code, 0) << text.output;
    const auto json_text = test::run_hullcook("inspect --json " + out.string() + " 2>/dev/null");
    EXPECT_EQ(json_text.exit_code, 0) << json_text.output;
  }
}

}  // namespace
}  // namespace hullcook
