// --report report.json: per-asset figures that agree with the debug JSON and add up to the
// bundle's size, from cook (with timings) and from link (without).
#include "run_command.h"
#include "test_directory.h"

#include "hullcook/core/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace hullcook {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::read_bytes;
using test::run_hullcook;

const fs::path kSprites = fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";

class ReportCli : public test::TestDirectory {
 protected:
  ReportCli() : TestDirectory("hullcook_report_cli_") {}
  void SetUp() override {
    TestDirectory::SetUp();
    fs::create_directories(directory / "sprites/level");
    for (const auto& [sample, name] :
         {std::pair{"frozen-bubble__balls__bubble-1-mini.png", "bubble.png"},
          std::pair{"pingus__groundpieces__bridge__space__grid1.png", "level/grid.png"},
          std::pair{"frozen-bubble__balls__stick_effect_2.png", "stick.png"}}) {
      fs::copy_file(kSprites / sample, directory / "sprites" / name);
    }
  }

  // Checks report against the debug JSON and the bundle it came with.
  void expect_consistent(const json& report, const json& debug, const fs::path& bundle,
                         bool timed) {
    ASSERT_EQ(report["assets"].size(), debug["assets"].size());
    std::size_t pieces = 0, hulls = 0, vertices = 0, bytes = 0;
    for (std::size_t a = 0; a < report["assets"].size(); ++a) {
      const json& figures = report["assets"][a];
      const json& asset = debug["assets"][a];
      SCOPED_TRACE(asset["name"].get<std::string>());
      EXPECT_EQ(figures["name"], asset["name"]);
      EXPECT_EQ(figures["pieces"], asset["pieces"].size());
      EXPECT_EQ(figures["vertices_traced"], asset["stats"]["traced_vertices"]);
      EXPECT_EQ(figures["max_concavity"], asset["stats"]["max_concavity"]);
      EXPECT_EQ(figures["levels"], asset["levels"].size());
      const json& finest = asset["levels"][0]["hulls"];
      EXPECT_EQ(figures["hulls"], finest.size());
      std::size_t asset_vertices = 0;
      for (const json& hull : finest) asset_vertices += hull.size();
      EXPECT_EQ(figures["hull_vertices"], asset_vertices);
      EXPECT_EQ(figures.contains("ms"), timed);
      if (timed) {
        EXPECT_GT(figures["ms"]["total"].get<double>(), 0.0);
        // Every stage is named (stop 53's sweep: a font sheet at --max-verts 3 spent 34 of its
        // 41 s fitting hulls, in no stage the report named), and those after decoding (a sheet's
        // cells share its decoding, timed once) add up to no more than the whole.
        double stages = 0.0;
        for (const char* stage : {"decode", "trace", "decompose", "limits", "contract"}) {
          ASSERT_TRUE(figures["ms"].contains(stage)) << stage;
          if (std::string(stage) != "decode") stages += figures["ms"][stage].get<double>();
        }
        EXPECT_GT(figures["ms"]["limits"].get<double>(), 0.0);
        EXPECT_LE(stages, figures["ms"]["total"].get<double>() * (1 + 1e-9));
      }
      pieces += figures["pieces"].get<std::size_t>();
      hulls += figures["hulls"].get<std::size_t>();
      vertices += asset_vertices;
      bytes += figures["bundle_bytes"].get<std::size_t>();
    }
    EXPECT_EQ(report["totals"]["assets"], report["assets"].size());
    EXPECT_EQ(report["totals"]["pieces"], pieces);
    EXPECT_EQ(report["totals"]["hulls"], hulls);
    EXPECT_EQ(report["totals"]["hull_vertices"], vertices);
    EXPECT_EQ(report["totals"]["bundle_bytes"], bytes);
    // The bundle is the assets' bytes, the header and the name table (SPEC §2, §6).
    const std::string file = read_bytes(bundle);
    ASSERT_GE(file.size(), 64u);
    std::uint32_t slot_count = 0;
    std::memcpy(&slot_count, file.data() + 20, 4);
    EXPECT_EQ(bytes + 64 + 4 * std::size_t{slot_count}, file.size());
  }
};

TEST_F(ReportCli, CookAndLinkReportFiguresThatAddUp) {
  const fs::path sprites = directory / "sprites";
  const std::string options = " -q --lod 6 --friction 0.5 ";
  auto cooked = run_hullcook(
      "cook " + sprites.string() + options + "-o " + (directory / "one.hcb").string() + " --json " +
      (directory / "one.json").string() + " --report " + (directory / "cook.json").string());
  ASSERT_EQ(cooked.exit_code, 0) << cooked.output;
  const json debug = json::parse(read_bytes(directory / "one.json"));
  expect_consistent(json::parse(read_bytes(directory / "cook.json")), debug, directory / "one.hcb",
                    true);

  std::string fragments;
  for (const char* name : {"bubble.png", "level/grid.png", "stick.png"}) {
    const fs::path fragment = directory / (std::to_string(fragments.size()) + ".hcf");
    auto result = run_hullcook("cook " + (sprites / name).string() + options + "--name " + name +
                               " -o " + fragment.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    fragments += " " + fragment.string();
  }
  auto linked = run_hullcook("link" + fragments + " -q -o " + (directory / "linked.hcb").string() +
                             " --report " + (directory / "link.json").string());
  ASSERT_EQ(linked.exit_code, 0) << linked.output;
  expect_consistent(json::parse(read_bytes(directory / "link.json")), debug,
                    directory / "linked.hcb", false);
}

TEST_F(ReportCli, RefusedBeforeCookingWhereItCannotBeWritten) {
  const std::string cook = "cook " + (directory / "sprites/stick.png").string() + " -o " +
                           (directory / "out.hcb").string() + " --report ";
  EXPECT_EQ(run_hullcook(cook + (directory / "report.txt").string()).exit_code,
            static_cast<int>(ExitCode::usage));
  EXPECT_EQ(run_hullcook(cook + (directory / "r.json").string() + " --depfile " +
                         (directory / "r.json").string())
                .exit_code,
            static_cast<int>(ExitCode::usage));
  EXPECT_EQ(run_hullcook(cook + (directory / "missing/r.json").string()).exit_code,
            static_cast<int>(ExitCode::output_failed));
  EXPECT_FALSE(fs::exists(directory / "out.hcb"));
}

}  // namespace
}  // namespace hullcook
