// Sprite sheets (TexturePacker hash and array JSON, Aseprite JSON): each frame is an asset named
// SHEET/FRAME, cooked exactly as its own untrimmed, unrotated image would be, with its pivot.
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
#include <optional>
#include <string>
#include <vector>

namespace hullcook {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::read_bytes;
using test::run_hullcook;

// One sprite as drawn: an untrimmed frame holding opaque rectangles [x0, x1) x [y0, y1), none of
// them symmetric, so that a frame turned the wrong way or placed off by a pixel cooks otherwise.
struct Sprite {
  std::string key;   // as the packer names it
  std::string name;  // the asset's name in the sheet
  int width, height;
  std::vector<std::array<int, 4>> rectangles;
  bool trim, rotate;
  std::optional<std::array<double, 2>> pivot;

  bool opaque(int x, int y) const {
    return std::any_of(rectangles.begin(), rectangles.end(), [&](const std::array<int, 4>& r) {
      return x >= r[0] && x < r[2] && y >= r[1] && y < r[3];
    });
  }
  // The trimmed rectangle: the opaque pixels' bounds, or the whole frame.
  std::array<int, 4> trimmed() const {
    if (!trim) return {0, 0, width, height};
    std::array<int, 4> b{width, height, 0, 0};
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (!opaque(x, y)) continue;
        b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x + 1), std::max(b[3], y + 1)};
      }
    }
    return b;
  }
  std::string png() const {
    std::vector<std::uint8_t> pixels(width * height * 4, 0);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) pixels[(y * width + x) * 4 + 3] = opaque(x, y) ? 255 : 0;
    }
    return test::make_png(width, height, 6, pixels);
  }
};

// An L trimmed to 7 x 6 at (2, 3); a Γ trimmed to 8 x 11 at (1, 2) and stored turned; an untrimmed
// frame with a pivot.
const std::vector<Sprite> kSprites = {
    {"walk/01.png", "walk/01", 12, 10, {{2, 3, 9, 5}, {2, 5, 4, 9}}, true, false, std::nullopt},
    {"jump.png", "jump", 10, 14, {{1, 2, 4, 13}, {4, 2, 9, 5}}, true, true, std::nullopt},
    {"idle",
     "idle",
     9,
     9,
     {{1, 1, 8, 6}, {1, 6, 3, 8}},
     false,
     false,
     std::array<double, 2>{0.25, 0.75}},
};

// The sprites packed in a row, 1 px apart, with opaque columns between them that no frame may
// take in; each sprite's frame entry (TexturePacker's fields) beside it.
struct Packed {
  std::string atlas_png;
  std::vector<json> entries;
};

Packed pack(const std::vector<Sprite>& sprites) {
  struct Placed {
    int x, w, h;
  };
  std::vector<Placed> placed;
  int width = 0, height = 0;
  for (const Sprite& sprite : sprites) {
    const std::array<int, 4> t = sprite.trimmed();
    const int w = t[2] - t[0], h = t[3] - t[1];
    placed.push_back({width + 1, sprite.rotate ? h : w, sprite.rotate ? w : h});
    width += 1 + placed.back().w;
    height = std::max(height, placed.back().h);
  }
  width += 1;
  std::vector<std::uint8_t> pixels(width * height * 4, 0);
  auto set = [&](int x, int y) { pixels[(y * width + x) * 4 + 3] = 255; };
  int gap = 0;
  Packed packed;
  for (std::size_t i = 0; i < sprites.size(); ++i) {
    for (int y = 0; y < height; ++y) set(gap, y);
    const Sprite& sprite = sprites[i];
    const std::array<int, 4> t = sprite.trimmed();
    const int w = t[2] - t[0], h = t[3] - t[1];
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (!sprite.opaque(t[0] + x, t[1] + y)) continue;
        // TexturePacker turns a rotated sprite 90° clockwise.
        if (sprite.rotate) {
          set(placed[i].x + h - 1 - y, x);
        } else {
          set(placed[i].x + x, y);
        }
      }
    }
    json entry = {{"frame", {{"x", placed[i].x}, {"y", 0}, {"w", w}, {"h", h}}},
                  {"rotated", sprite.rotate},
                  {"trimmed", sprite.trim},
                  {"spriteSourceSize", {{"x", t[0]}, {"y", t[1]}, {"w", w}, {"h", h}}},
                  {"sourceSize", {{"w", sprite.width}, {"h", sprite.height}}}};
    if (sprite.pivot) entry["pivot"] = {{"x", (*sprite.pivot)[0]}, {"y", (*sprite.pivot)[1]}};
    packed.entries.push_back(entry);
    gap = placed[i].x + placed[i].w;
  }
  for (int y = 0; y < height; ++y) set(width - 1, y);
  packed.atlas_png = test::make_png(width, height, 6, pixels);
  return packed;
}

const json kMeta = {{"app", "https://www.codeandweb.com/texturepacker"}, {"image", "atlas.png"}};

class SheetCli : public test::TestDirectory {
 protected:
  SheetCli() : TestDirectory("hullcook_sheet_cli_") {}
  void SetUp() override {
    TestDirectory::SetUp();
    const Packed packed = pack(kSprites);
    write("atlas.png", packed.atlas_png);
    json hash = {{"frames", json::object()}, {"meta", kMeta}};
    json array = {{"frames", json::array()}, {"meta", kMeta}};
    for (std::size_t i = 0; i < kSprites.size(); ++i) {
      hash["frames"][kSprites[i].key] = packed.entries[i];
      json entry = packed.entries[i];
      entry["filename"] = kSprites[i].key;
      array["frames"].push_back(entry);
    }
    write("hash.json", hash.dump());
    write("array.json", array.dump());
  }

  void write(const std::string& name, const std::string& bytes) {
    std::ofstream(directory / name, std::ios::binary) << bytes;
  }

  // The debug JSON's assets by name, of cooking `arguments`.
  std::map<std::string, json> cook(const std::string& arguments) {
    const fs::path out = directory / "out.json";
    fs::remove(out);
    auto result = run_hullcook("cook " + arguments + " -q -o " + out.string());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    std::map<std::string, json> assets;
    if (result.exit_code != 0) return assets;
    const json cooked = json::parse(read_bytes(out));
    for (const json& asset : cooked["assets"]) assets[asset["name"]] = asset;
    return assets;
  }

  // The one asset of the sprite cooked as its own untrimmed, unrotated image, with its pivot.
  json cook_alone(const Sprite& sprite, const std::string& options = "") {
    write("alone.png", sprite.png());
    std::string pivot;
    if (sprite.pivot) {
      pivot = " --pivot " + std::to_string((*sprite.pivot)[0]) + "," +
              std::to_string((*sprite.pivot)[1]);
    }
    const auto assets = cook((directory / "alone.png").string() + pivot + options);
    return assets.empty() ? json() : assets.begin()->second;
  }

  void expect_cooked_as_alone(const std::map<std::string, json>& assets, const std::string& name,
                              const Sprite& sprite, const std::string& options = "") {
    SCOPED_TRACE(name);
    ASSERT_TRUE(assets.count(name)) << "no asset " << name;
    const json& asset = assets.at(name);
    const json alone = cook_alone(sprite, options);
    ASSERT_FALSE(alone.is_null());
    EXPECT_EQ(asset["image"], alone["image"]);
    EXPECT_EQ(asset["pivot"], alone["pivot"]);
    ASSERT_FALSE(asset["levels"][0]["hulls"].empty());
    EXPECT_EQ(asset["levels"][0]["hulls"], alone["levels"][0]["hulls"]);
  }

  void expect_refused(const std::string& json_name, const std::string& text,
                      const std::string& problem) {
    SCOPED_TRACE(json_name);
    write(json_name, text);
    const fs::path sheet = directory / json_name;
    const fs::path out = directory / "refused.hcb";
    auto result = run_hullcook("cook " + sheet.string() + " -o " + out.string());
    EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::bad_input)) << result.output;
    EXPECT_NE(result.output.find("hullcook: error: " + sheet.string() + ": "), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find(problem), std::string::npos) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_FALSE(fs::exists(out));
  }
};

TEST_F(SheetCli, EachFrameOfAHashCooksAsItsOwnUntrimmedUnrotatedImage) {
  const auto assets = cook((directory / "hash.json").string());
  ASSERT_EQ(assets.size(), kSprites.size());
  for (const Sprite& sprite : kSprites) {
    expect_cooked_as_alone(assets, "hash/" + sprite.name, sprite);
  }
}

TEST_F(SheetCli, EachFrameOfAnArrayCooksAsItsOwnUntrimmedUnrotatedImage) {
  // y down and a coarse τ as well: the frames must follow every setting as a lone image does.
  const std::string options = " --y-down --tau 1 --ppu 4";
  const auto assets = cook((directory / "array.json").string() + options);
  ASSERT_EQ(assets.size(), kSprites.size());
  for (const Sprite& sprite : kSprites) {
    expect_cooked_as_alone(assets, "array/" + sprite.name, sprite, options);
  }
  EXPECT_EQ(assets.at("array/idle")["pivot"], json::array({0.25, 0.75}));
}

TEST_F(SheetCli, AsepriteSlicePivotsGoToTheirFramesInTheFilesOrder) {
  // Frame 0 is "z", frame 1 is "a": a reader that sorted the keys would move the pivot.
  const Packed packed = pack({kSprites[2], kSprites[0]});
  write("frames.png", packed.atlas_png);
  json entries[2] = {packed.entries[0], packed.entries[1]};
  entries[0].erase("pivot");
  // Ordered, as Aseprite writes it (json sorts its keys).
  nlohmann::ordered_json aseprite;
  aseprite["frames"]["z.aseprite"] = nlohmann::ordered_json::parse(entries[0].dump());
  aseprite["frames"]["a.aseprite"] = nlohmann::ordered_json::parse(entries[1].dump());
  aseprite["meta"] = nlohmann::ordered_json::parse(json{
      {"app", "https://www.aseprite.org/"},
      {"image", "frames.png"},
      {"slices",
       {{{"name", "origin"},
         {"keys",
          {{{"frame", 1},
            {"bounds", {{"x", 2}, {"y", 3}, {"w", 4}, {"h", 4}}},
            {"pivot", {{"x", 1}, {"y", 2}}}}}}}}}}.dump());
  write("anim.json", aseprite.dump());
  const auto assets = cook((directory / "anim.json").string());
  ASSERT_EQ(assets.size(), 2u);
  Sprite unpivoted = kSprites[2];
  unpivoted.pivot.reset();
  expect_cooked_as_alone(assets, "anim/z", unpivoted);
  // The pivot at (2 + 1, 3 + 2) px of a 12 x 10 frame.
  Sprite pivoted = kSprites[0];
  pivoted.pivot = {0.25, 0.5};
  expect_cooked_as_alone(assets, "anim/a", pivoted);
}

TEST_F(SheetCli, NameDepfileAndSidecarFollowTheSheet) {
  write("hash.physics.json", R"({"density": 3})");
  write("hash.hullcook.json", R"({"tau": 7})");
  const fs::path out = directory / "out.hcb", depfile = directory / "out.d";
  auto result = run_hullcook("cook " + (directory / "hash.json").string() +
                             " --name chars/hero -q -o " + out.string() + " --json " +
                             (directory / "out.json").string() + " --depfile " + depfile.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const json assets = json::parse(read_bytes(directory / "out.json"))["assets"];
  ASSERT_EQ(assets.size(), kSprites.size());
  for (const json& asset : assets) {
    EXPECT_EQ(asset["name"].get<std::string>().rfind("chars/hero/", 0), 0u) << asset["name"];
    EXPECT_EQ(asset["physics"]["density"], 3.0);
    EXPECT_EQ(asset["tau"], 7.0);
  }
  const std::string d = read_bytes(depfile);
  for (const char* read : {"hash.json", "atlas.png", "hash.physics.json", "hash.hullcook.json"}) {
    EXPECT_NE(d.find((directory / read).string()), std::string::npos) << read << "\n" << d;
  }
}

TEST_F(SheetCli, ASheetsFragmentLinksToTheBytesOfOneCook) {
  const std::string sheet = (directory / "hash.json").string();
  auto one = run_hullcook("cook " + sheet + " -q -o " + (directory / "one.hcb").string());
  ASSERT_EQ(one.exit_code, 0) << one.output;
  auto fragment = run_hullcook("cook " + sheet + " -q -o " + (directory / "hash.hcf").string());
  ASSERT_EQ(fragment.exit_code, 0) << fragment.output;
  auto linked = run_hullcook("link " + (directory / "hash.hcf").string() + " -q -o " +
                             (directory / "linked.hcb").string());
  ASSERT_EQ(linked.exit_code, 0) << linked.output;
  EXPECT_EQ(read_bytes(directory / "linked.hcb"), read_bytes(directory / "one.hcb"));
}

// "skip" keeps images out, never a sheet named as an input: hero.json shares its sidecar
// hero.hullcook.json with its atlas hero.png, which a folder's cook would take for an image.
TEST_F(SheetCli, SkippingTheAtlasKeepsTheSheet) {
  write("hullcook.json", R"({"assets": [{"match": "*", "skip": true}]})");
  auto folder =
      run_hullcook("cook " + directory.string() + " -q -o " + (directory / "folder.hcb").string());
  EXPECT_EQ(folder.exit_code, static_cast<int>(ExitCode::bad_input)) << folder.output;
  EXPECT_NE(folder.output.find("every image in this directory is skipped"), std::string::npos)
      << folder.output;
  const auto assets = cook((directory / "hash.json").string());
  EXPECT_EQ(assets.size(), kSprites.size());
}

TEST_F(SheetCli, DirectoriesAreSearchedForImagesOnly) {
  const auto assets = cook(directory.string());
  EXPECT_EQ(assets.size(), 1u);
  EXPECT_TRUE(assets.count("atlas.png"));
}

TEST_F(SheetCli, BadSheetsAreRefusedNamingTheFile) {
  auto sheet = [](const json& frames, const std::string& image = "atlas.png") {
    return json{{"frames", frames}, {"meta", {{"image", image}}}}.dump();
  };
  const json good = {{"frame", {{"x", 1}, {"y", 0}, {"w", 2}, {"h", 2}}}};
  auto merged = [&](const json& patch) {
    json entry = good;
    entry.update(patch);
    return entry;
  };
  auto with = [&](const char* key, const json& value) {
    return json{{"a", merged({{key, value}})}};
  };
  expect_refused("malformed.json", R"({"frames": {)",
                 "not valid JSON: parse error at line 1, column 13: syntax error");
  expect_refused("not_an_object.json", "[1, 2]", "not a JSON object");
  expect_refused("no_image.json", json{{"frames", {{"a", good}}}, {"meta", json::object()}}.dump(),
                 "meta: no 'image'");
  expect_refused("not_a_sheet.json", R"({"density": 2})", "not a sprite sheet");
  expect_refused("outside.json", sheet(with("frame", {{"x", 40}, {"y", 0}, {"w", 8}, {"h", 8}})),
                 "frame 'a': 8x8 at (40, 0) lies outside the");
  expect_refused("negative.json", sheet(with("frame", {{"x", 1}, {"y", 0}, {"w", -3}, {"h", 2}})),
                 "frame 'a': frame: 'w' is -3, out of range");
  expect_refused("missing_atlas.json", sheet({{"a", good}}, "nowhere.png"), "meta.image: ");
  expect_refused("duplicate.json",
                 sheet(json::array({merged({{"filename", "a.png"}}), merged({{"filename", "a"}})})),
                 "frame 'a': two frames have this name");
  expect_refused("huge.json", sheet(with("sourceSize", {{"w", 100000}, {"h", 100000}})),
                 "frame 'a': a 100000x100000 frame is too large");
  expect_refused("fraction.json", sheet(with("frame", {{"x", 0.5}, {"y", 0}, {"w", 2}, {"h", 2}})),
                 "'x' must be a whole number");
  expect_refused(
      "outside_source.json",
      sheet({{"a", merged({{"spriteSourceSize", {{"x", 9}, {"y", 0}, {"w", 2}, {"h", 2}}},
                           {"sourceSize", {{"w", 10}, {"h", 10}}}})}}),
      "the trimmed sprite does not lie inside sourceSize");
  // A pivot this far put no finite coordinate in the outline, refused as a broken outline.
  expect_refused("far_pivot.json", sheet(with("pivot", {{"x", 1e308}, {"y", 0.5}})),
                 "frame 'a': the pivot lies more than 1e6 sprite sizes from the sprite");
  expect_refused("nan_pivot.json", sheet(with("pivot", {{"x", "a"}, {"y", 0.5}})),
                 "frame 'a': pivot: 'x' must be a finite number");
}

// Stop 59's sheets (a helper's): a frame whose sizes an exporter writes with a point (20.0) was
// refused as "not a whole number", and an array frame whose 'filename' was a number was said to
// have none. 20.0 now reads as 20, the same assets as the integers; the name is told to be a
// string.
TEST_F(SheetCli, Stop61_WholeNumbersWrittenWithAPointAreWholeAndAFilenameMustBeAString) {
  json hash = json::parse(read_bytes(directory / "hash.json"));
  for (auto& [key, entry] : hash["frames"].items()) {
    for (const char* field : {"frame", "spriteSourceSize", "sourceSize"}) {
      if (!entry.contains(field)) continue;
      for (auto& [name, value] : entry[field].items()) {
        if (value.is_number_integer()) value = value.get<double>();
      }
    }
  }
  const std::string text = hash.dump();
  ASSERT_NE(text.find(".0"), std::string::npos) << text;
  write("points.json", text);
  const auto integers = cook((directory / "hash.json").string());
  auto with_points = cook((directory / "points.json").string());
  ASSERT_EQ(with_points.size(), integers.size());
  for (const auto& [name, asset] : integers) {
    SCOPED_TRACE(name);
    const std::string renamed = "points" + name.substr(name.find('/'));
    ASSERT_TRUE(with_points.count(renamed));
    EXPECT_EQ(with_points[renamed]["levels"], asset["levels"]);
    EXPECT_EQ(with_points[renamed]["image"], asset["image"]);
  }
  auto sheet = [](const json& frames) {
    return json{{"frames", frames}, {"meta", {{"image", "atlas.png"}}}}.dump();
  };
  const json frame = {{"x", 1}, {"y", 0}, {"w", 2}, {"h", 2}};
  expect_refused("numbered.json", sheet(json::array({{{"filename", 7}, {"frame", frame}}})),
                 "frame 0: 'filename' must be a string");
  expect_refused("unnamed.json", sheet(json::array({{{"frame", frame}}})),
                 "frame 0: no 'filename'");
  expect_refused("half.json",
                 sheet({{"a", {{"frame", {{"x", 1.5}, {"y", 0}, {"w", 2}, {"h", 2}}}}}}),
                 "'x' must be a whole number");
}

// Stop 58, a helper's hostile files: a hash that keys two frames alike lost one of them (the
// parsed object keeps one), where the README promises a refusal; and 'frames' nested 90,000
// deep crashed the cook (the ordered JSON copies a member's value whole, recursively).
TEST_F(SheetCli, Stop58_ADuplicateKeyOrADeepNestingIsRefusedNotLostOrACrash) {
  const std::string frame = R"({"frame": {"x": 1, "y": 0, "w": 2, "h": 2}})";
  expect_refused("same_key.json",
                 R"({"frames": {"f1.png": )" + frame + R"(, "f2.png": )" + frame +
                     R"(, "f1.png": )" + frame + R"(}, "meta": {"image": "atlas.png"}})",
                 "the key 'f1.png' appears twice in one object");
  expect_refused("deep.json",
                 R"({"frames": )" + std::string(100000, '[') + std::string(100000, ']') +
                     R"(, "meta": {"image": "atlas.png"}})",
                 "arrays and objects nested deeper than 256 levels");
  // Brackets inside a string are no nesting.
  write("brackets.json", R"({"frames": {")" + std::string(1000, '[') + R"(": )" + frame +
                             R"(}, "meta": {"image": "atlas.png"}})");
  EXPECT_EQ(cook((directory / "brackets.json").string()).size(), 1u);
}

}  // namespace
}  // namespace hullcook
