// --grid WxH [--margin M] [--spacing S]: every non-empty cell of a sheet is an asset named
// NAME/INDEX, in its own cell's coordinates; empty cells are skipped.
#include "png_writer.h"
#include "run_command.h"
#include "test_directory.h"

#include "hullcook/core/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace hullcook {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::read_bytes;
using test::run_hullcook;

// A 3 x 2 grid of 8 x 8 cells, 1 px of margin and 2 px between cells: a sheet of
// 1 + 3 * 8 + 2 * 2 + 1 = 30 by 1 + 2 * 8 + 2 + 1 = 20 px (the last pixel column and row are
// spare). Cells 0, 2, 3 and 5 hold an opaque rectangle [x0, x1) x [y0, y1) in cell pixels; 1 and
// 4 are empty.
constexpr int kCell = 8, kMargin = 1, kSpacing = 2, kColumns = 3, kWidth = 30, kHeight = 20;
const std::map<int, std::array<int, 4>> kRectangles = {
    {0, {0, 0, 8, 8}}, {2, {2, 1, 7, 4}}, {3, {1, 3, 4, 8}}, {5, {5, 5, 8, 7}}};

std::string sheet_png() {
  std::vector<std::uint8_t> pixels(kWidth * kHeight * 4, 0);
  for (const auto& [index, r] : kRectangles) {
    const int left = kMargin + (index % kColumns) * (kCell + kSpacing);
    const int top = kMargin + (index / kColumns) * (kCell + kSpacing);
    for (int y = r[1]; y < r[3]; ++y) {
      for (int x = r[0]; x < r[2]; ++x) pixels[((top + y) * kWidth + left + x) * 4 + 3] = 255;
    }
  }
  // Opaque pixels in the margin and the spacing, which no cell may see.
  for (int x = 0; x < kWidth; ++x) pixels[x * 4 + 3] = 255;
  for (int y = 0; y < kHeight; ++y) pixels[(y * kWidth + kMargin + kCell) * 4 + 3] = 255;
  return test::make_png(kWidth, kHeight, 6, pixels);
}

class GridCli : public test::TestDirectory {
 protected:
  GridCli() : TestDirectory("hullcook_grid_cli_") {}
  void SetUp() override {
    TestDirectory::SetUp();
    fs::create_directories(directory / "art/tiles");
    std::ofstream(directory / "art/tiles/sheet.png", std::ios::binary) << sheet_png();
  }
};

// No simplification: the traced outline keeps every pixel edge, so the hulls span the rectangles.
const std::string kGrid = " --grid 8x8 --margin 1 --spacing 2 --pivot 0,0 --y-down --simplify 0 -q";

TEST_F(GridCli, EveryNonEmptyCellIsAnAssetInItsOwnCoordinates) {
  auto result = run_hullcook("cook " + (directory / "art").string() + kGrid + " -o " +
                             (directory / "out.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // The opaque margin, spacing and spare last column are no cell's, and no warning's either.
  EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
  const json assets = json::parse(read_bytes(directory / "out.json"))["assets"];
  ASSERT_EQ(assets.size(), kRectangles.size());
  for (const json& asset : assets) {
    const std::string name = asset["name"];
    SCOPED_TRACE(name);
    ASSERT_EQ(name.rfind("tiles/sheet.png/", 0), 0u);
    const int index = std::stoi(name.substr(name.rfind('/') + 1));
    ASSERT_TRUE(kRectangles.count(index));
    EXPECT_EQ(asset["image"]["width"], kCell);
    EXPECT_EQ(asset["image"]["height"], kCell);
    // Hard edges lie on pixel borders: the hulls span the rectangle exactly, in cell pixels.
    double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
    for (const json& hull : asset["levels"][0]["hulls"]) {
      for (const json& point : hull) {
        x0 = std::min(x0, point[0].get<double>());
        x1 = std::max(x1, point[0].get<double>());
        y0 = std::min(y0, point[1].get<double>());
        y1 = std::max(y1, point[1].get<double>());
      }
    }
    const std::array<int, 4>& r = kRectangles.at(index);
    EXPECT_NEAR(x0, r[0], 1e-9);
    EXPECT_NEAR(y0, r[1], 1e-9);
    EXPECT_NEAR(x1, r[2], 1e-9);
    EXPECT_NEAR(y1, r[3], 1e-9);
  }
}

TEST_F(GridCli, ASheetsFragmentLinksToTheBytesOfOneCook) {
  auto one = run_hullcook("cook " + (directory / "art").string() + kGrid + " -o " +
                          (directory / "one.hcb").string());
  ASSERT_EQ(one.exit_code, 0) << one.output;
  auto fragment = run_hullcook("cook " + (directory / "art/tiles/sheet.png").string() + kGrid +
                               " --name tiles/sheet.png -o " + (directory / "sheet.hcf").string());
  ASSERT_EQ(fragment.exit_code, 0) << fragment.output;
  auto linked = run_hullcook("link " + (directory / "sheet.hcf").string() + " -q -o " +
                             (directory / "linked.hcb").string());
  ASSERT_EQ(linked.exit_code, 0) << linked.output;
  EXPECT_EQ(read_bytes(directory / "linked.hcb"), read_bytes(directory / "one.hcb"));
}

// A cell's warnings and errors name the cell's asset beside the sheet: their points are the
// cell's (ValyriaTear's and Shattered Pixel Dungeon's tilesets, whose messages named the sheet
// alone).
TEST_F(GridCli, MessagesAboutACellNameItsAsset) {
  // Two 8 x 8 cells: two 3 x 3 blobs in cell 0, one in cell 1.
  std::vector<std::uint8_t> pixels(16 * 8 * 4, 0);
  auto blob = [&](int left, int top) {
    for (int y = top; y < top + 3; ++y) {
      for (int x = left; x < left + 3; ++x) pixels[(y * 16 + x) * 4 + 3] = 255;
    }
  };
  blob(0, 0), blob(4, 4), blob(10, 2);
  const fs::path sheet = directory / "two.png";
  std::ofstream(sheet, std::ios::binary) << test::make_png(16, 8, 6, pixels);
  auto cooked = run_hullcook("cook " + sheet.string() + " --grid 8 --max-pieces 1 -q -o " +
                             (directory / "two.hcb").string());
  ASSERT_EQ(cooked.exit_code, 0) << cooked.output;
  EXPECT_NE(cooked.output.find("hullcook: warning: " + sheet.string() +
                               " (asset two.png/0): --max-pieces 1 cannot be kept"),
            std::string::npos)
      << cooked.output;
  EXPECT_EQ(cooked.output.find("two.png/1"), std::string::npos) << cooked.output;
  // An error: a staircase line 2 px wide in cell 1 of another sheet, under a weld of 3 px.
  std::vector<std::uint8_t> line(32 * 16 * 4, 0);
  for (int i = 0; i < 14; ++i) {
    line[(i * 32 + 16 + i) * 4 + 3] = 255, line[(i * 32 + 17 + i) * 4 + 3] = 255;
  }
  const fs::path lines = directory / "line.png";
  std::ofstream(lines, std::ios::binary) << test::make_png(32, 16, 6, line);
  auto refused = run_hullcook("cook " + lines.string() + " --grid 16 --weld 3 --tau 0.2 -q -o " +
                              (directory / "line.hcb").string());
  EXPECT_EQ(refused.exit_code, static_cast<int>(ExitCode::bad_input)) << refused.output;
  EXPECT_NE(
      refused.output.find("hullcook: error: " + lines.string() + " (asset line.png/1): a piece of"),
      std::string::npos)
      << refused.output;
}

TEST_F(GridCli, GridsThatCutNothingAreRefused) {
  const std::string sheet = (directory / "art/tiles/sheet.png").string();
  const std::string out = " -o " + (directory / "out.hcb").string();
  auto too_large = run_hullcook("cook " + sheet + " --grid 31x8" + out);
  EXPECT_EQ(too_large.exit_code, static_cast<int>(ExitCode::bad_input)) << too_large.output;
  EXPECT_NE(too_large.output.find(sheet + ": a 30x20 image holds no whole 31x8 cell"),
            std::string::npos)
      << too_large.output;
  std::ofstream(directory / "empty.png", std::ios::binary)
      << test::make_png(kWidth, kHeight, 6, std::vector<std::uint8_t>(kWidth * kHeight * 4, 0));
  auto empty = run_hullcook("cook " + (directory / "empty.png").string() + " --grid 8" + out);
  EXPECT_EQ(empty.exit_code, static_cast<int>(ExitCode::bad_input)) << empty.output;
  EXPECT_NE(empty.output.find("every cell of the grid is empty"), std::string::npos);
  // Among sheets that give assets, an empty one is a warning (a folder of tilesets was stopped
  // by a transparent overlay in it): the others are cooked as alone.
  std::ofstream(directory / "art/tiles/empty.png", std::ios::binary)
      << test::make_png(kWidth, kHeight, 6, std::vector<std::uint8_t>(kWidth * kHeight * 4, 0));
  auto among = run_hullcook("cook " + (directory / "art").string() +
                            " --grid 8 --margin 1 --spacing 2" + out);
  ASSERT_EQ(among.exit_code, 0) << among.output;
  EXPECT_NE(among.output.find("hullcook: warning: " + (directory / "art/tiles/empty.png").string() +
                              ": every cell of the grid is empty or holds only specks (--grid, "
                              "--alpha, --min-blob-area): the sheet "
                              "gives no asset"),
            std::string::npos)
      << among.output;
  fs::remove(directory / "art/tiles/empty.png");
  auto alone =
      run_hullcook("cook " + (directory / "art").string() + " --grid 8 --margin 1 --spacing 2 -o " +
                   (directory / "alone.hcb").string());
  ASSERT_EQ(alone.exit_code, 0) << alone.output;
  EXPECT_EQ(read_bytes(directory / "out.hcb"), read_bytes(directory / "alone.hcb"));
  fs::remove(directory / "out.hcb");
  // Every image too small for the grid is named (up to five) or counted, in name order, so that
  // one cook shows them all; a folder of nothing else is no "folder without images".
  const fs::path small = directory / "small";
  fs::create_directories(small / "sub");
  for (const char* name : {"e.png", "b.png", "sub/a.png", "d.png", "c.png", "g.png", "f.png"}) {
    std::ofstream(small / name, std::ios::binary)
        << test::make_png(4, 6, 6, std::vector<std::uint8_t>(4 * 6 * 4, 255));
  }
  auto misfits = run_hullcook("cook " + small.string() + " --grid 8" + out);
  EXPECT_EQ(misfits.exit_code, static_cast<int>(ExitCode::bad_input)) << misfits.output;
  EXPECT_NE(misfits.output.find(
                "hullcook: error: " + (small / "b.png").string() +
                ": a 4x6 image holds no whole 8x8 cell at margin 0 (--grid, --margin); nor do 6 "
                "more images: " +
                (small / "c.png").string() + " (4x6), " + (small / "d.png").string() + " (4x6), " +
                (small / "e.png").string() + " (4x6), " + (small / "f.png").string() + " (4x6), " +
                (small / "g.png").string() + " (4x6), ...\n"),
            std::string::npos)
      << misfits.output;
  // Broken sheets are decoded as the inputs are collected: the error names the first by name,
  // not the first the file system lists.
  const fs::path broken = directory / "broken";
  fs::create_directories(broken);
  for (const char* name : {"h.png", "c.png", "f.png", "b.png", "g.png", "e.png", "d.png"}) {
    std::ofstream(broken / name, std::ios::binary) << "not a png";
  }
  auto first_broken = run_hullcook("cook " + broken.string() + " --grid 8" + out);
  EXPECT_EQ(first_broken.exit_code, static_cast<int>(ExitCode::bad_input)) << first_broken.output;
  EXPECT_NE(first_broken.output.find("hullcook: error: " + (broken / "b.png").string() + ": "),
            std::string::npos)
      << first_broken.output;
  EXPECT_FALSE(fs::exists(directory / "out.hcb"));
  EXPECT_EQ(run_hullcook("cook " + sheet + " --margin 1" + out).exit_code,
            static_cast<int>(ExitCode::usage));
  EXPECT_EQ(run_hullcook("cook " + sheet + " --grid 8x" + out).exit_code,
            static_cast<int>(ExitCode::usage));
  EXPECT_FALSE(fs::exists(directory / "out.hcb"));
}

// A sheet one cell too narrow for its art, or cut with the wrong --grid, loses whatever lies
// beyond the last whole cell: the cook says how many opaque pixels, and where.
TEST_F(GridCli, OpaquePixelsBeyondTheLastWholeCellAreToldWithTheirCount) {
  // 100 x 80 px cut into 32 px cells: 3 columns and 2 rows, x >= 96 and y >= 64 left over.
  constexpr int kSheetWidth = 100, kSheetHeight = 80;
  auto sheet = [&](const std::vector<std::array<int, 4>>& rectangles) {
    std::vector<std::uint8_t> pixels(kSheetWidth * kSheetHeight * 4, 0);
    for (const std::array<int, 4>& r : rectangles) {
      for (int y = r[1]; y < r[3]; ++y) {
        for (int x = r[0]; x < r[2]; ++x) pixels[(y * kSheetWidth + x) * 4 + 3] = 255;
      }
    }
    return test::make_png(kSheetWidth, kSheetHeight, 6, pixels);
  };
  const fs::path partial = directory / "partial.png", beyond_only = directory / "beyond_only.png";
  // A sprite in cell 0; 3 x 10 px in the right strip and 10 x 16 in the bottom one, the corner
  // 4 x 4 counted once.
  std::ofstream(partial, std::ios::binary)
      << sheet({{4, 4, 28, 28}, {97, 10, 100, 20}, {10, 64, 20, 80}, {96, 76, 100, 80}});
  // The same with a frame in a 1 px margin: the left column, which no strip counts (a review
  // found the bottom strip counted it from x = 0).
  const fs::path framed = directory / "framed.png";
  std::ofstream(framed, std::ios::binary) << sheet(
      {{4, 4, 28, 28}, {97, 10, 100, 20}, {10, 64, 20, 80}, {96, 76, 100, 80}, {0, 0, 1, 80}});
  std::ofstream(beyond_only, std::ios::binary) << sheet({{97, 10, 100, 20}});
  const std::string out = " -o " + (directory / "out.hcb").string();
  auto warned = run_hullcook("cook " + partial.string() + " --grid 32 -q" + out);
  ASSERT_EQ(warned.exit_code, 0) << warned.output;
  EXPECT_NE(warned.output.find("hullcook: warning: " + partial.string() +
                               ": 206 opaque pixels lie beyond the last whole cell (x >= 96 or "
                               "y >= 64 of a 100x80 image), where --grid 32x32 --margin 0 "
                               "--spacing 0 fits 3 columns and 2 rows: they are in no asset"),
            std::string::npos)
      << warned.output;
  // With a margin the strips stop short of the far margin: 31 px cells at margin 1 and spacing 1
  // fit the same columns and rows, and the far margin's pixels (x = 99, y = 79) are no strip's.
  auto margin =
      run_hullcook("cook " + framed.string() + " --grid 31 --margin 1 --spacing 1 -q" + out);
  ASSERT_EQ(margin.exit_code, 0) << margin.output;
  // Right strip x 97..98 above y 65 (2 x 10), bottom strip y 65..78 across x 1..98 (10 x 14,
  // and 3 x 3 of the corner square): 20 + 140 + 9.
  EXPECT_NE(margin.output.find(": 169 opaque pixels lie beyond the last whole cell (x >= 97 or "
                               "y >= 65 of a 100x80 image), where --grid 31x31 --margin 1 "
                               "--spacing 1 fits 3 columns and 2 rows"),
            std::string::npos)
      << margin.output;
  // Every cell empty: the refusal says where the art is, and writes nothing.
  fs::remove(directory / "out.hcb");
  auto refused = run_hullcook("cook " + beyond_only.string() + " --grid 32" + out);
  EXPECT_EQ(refused.exit_code, static_cast<int>(ExitCode::bad_input)) << refused.output;
  EXPECT_NE(refused.output.find(beyond_only.string() +
                                ": every cell of the grid is empty or holds only specks (--grid, "
                                "--alpha, --min-blob-area); 30 opaque "
                                "pixels lie beyond the last whole cell (x >= 96 or y >= 64"),
            std::string::npos)
      << refused.output;
  EXPECT_FALSE(fs::exists(directory / "out.hcb"));
  // A grid that fits the art leaves nothing beyond: no warning.
  auto fitted = run_hullcook("cook " + partial.string() + " --grid 20 -q" + out);
  ASSERT_EQ(fitted.exit_code, 0) << fitted.output;
  EXPECT_EQ(fitted.output.find("beyond the last whole cell"), std::string::npos) << fitted.output;
}

}  // namespace
}  // namespace hullcook
