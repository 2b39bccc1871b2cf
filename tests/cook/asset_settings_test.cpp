// Issue 18: per-asset settings without a GUI. A project file hullcook.json maps globs to settings,
// a sidecar NAME.hullcook.json sets one image's; each asset cooks as if its settings had been
// given on the command line for it alone, whether its folder or the image itself is cooked, and
// both files are dependencies of the output.
#include "asset_settings.h"  // tool/cook/src
#include "listed_files.h"

#include "../cli/png_writer.h"

#include "hullcook/cook/cook.h"
#include "hullcook/core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {
namespace {

namespace fs = std::filesystem;

TEST(Glob, StarsStayInAFolderDoubleStarsCrossThem) {
  EXPECT_TRUE(glob_matches("*.png", "hero.png"));
  EXPECT_FALSE(glob_matches("*.png", "tiles/grass.png"));
  EXPECT_TRUE(glob_matches("tiles/*.png", "tiles/grass.png"));
  EXPECT_TRUE(glob_matches("**/*.png", "hero.png"));
  EXPECT_TRUE(glob_matches("**/*.png", "a/b/c/hero.png"));
  EXPECT_TRUE(glob_matches("a/**", "a/b/c.png"));
  EXPECT_FALSE(glob_matches("a/**", "b/a/c.png"));
  EXPECT_TRUE(glob_matches("h?ro.png", "hero.png"));
  EXPECT_FALSE(glob_matches("h?ro.png", "heero.png"));
  EXPECT_TRUE(glob_matches("**/enemies/bat*", "world/enemies/bat_2.png"));
  EXPECT_FALSE(glob_matches("tiles/*", "tiles"));
}

// Stop 57: globs matched by trying every split at every star took exponential time: a rule
// "*a*a*a*a*a*a*a*a*a*b" against a name of 64 a's, or twelve "**" against a path 30 folders deep,
// did not finish in 120 s. The greedy walk answers as that recursion (kept here as the reference)
// on 20,000 random globs and names, and the two cases at once.
bool reference_segment(std::string_view glob, std::string_view name) {
  if (glob.empty()) return name.empty();
  if (glob.front() == '*') {
    for (std::size_t skip = 0; skip <= name.size(); ++skip) {
      if (reference_segment(glob.substr(1), name.substr(skip))) return true;
    }
    return false;
  }
  return !name.empty() && (glob.front() == '?' || glob.front() == name.front()) &&
         reference_segment(glob.substr(1), name.substr(1));
}

bool reference_path(const std::vector<std::string>& glob, std::size_t g,
                    const std::vector<std::string>& name, std::size_t n) {
  if (g == glob.size()) return n == name.size();
  if (glob[g] == "**") {
    for (std::size_t skip = n; skip <= name.size(); ++skip) {
      if (reference_path(glob, g + 1, name, skip)) return true;
    }
    return false;
  }
  return n < name.size() && reference_segment(glob[g], name[n]) &&
         reference_path(glob, g + 1, name, n + 1);
}

TEST(Glob, Stop57_ManyStarsMatchAsTheRecursionDidWithoutItsBacktracking) {
  std::mt19937 random(57);
  auto pick = [&](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
  auto segment = [&](const char* alphabet, int letters, int most) {
    std::string text;
    for (int k = pick(most + 1); k > 0; --k) text += alphabet[pick(letters)];
    return text;
  };
  auto join = [](const std::vector<std::string>& parts) {
    std::string path;
    for (std::size_t i = 0; i < parts.size(); ++i) path += (i ? "/" : "") + parts[i];
    return path;
  };
  int matched = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<std::string> glob, name;
    for (int k = 1 + pick(3); k > 0; --k)
      glob.push_back(pick(5) == 0 ? "**" : segment("ab*?", 4, 5));
    for (int k = 1 + pick(3); k > 0; --k) name.push_back(segment("ab", 2, 6));
    const bool expected = reference_path(glob, 0, name, 0);
    ASSERT_EQ(glob_matches(join(glob), join(name)), expected) << join(glob) << " " << join(name);
    matched += expected;
  }
  EXPECT_GT(matched, 1000);
  EXPECT_FALSE(glob_matches("*a*a*a*a*a*a*a*a*a*b", std::string(64, 'a')));
  EXPECT_TRUE(glob_matches("*a*a*a*a*a*a*a*a*a*b", std::string(64, 'a') + "b"));
  std::string deep = "x.png", doubles = "y.png";
  for (int level = 0; level < 30; ++level) deep = "d/" + deep;
  for (int star = 0; star < 12; ++star) doubles = "**/" + doubles;
  EXPECT_FALSE(glob_matches(doubles, deep));
  EXPECT_TRUE(glob_matches(doubles.substr(0, doubles.size() - 5) + "x.png", deep));
}

// The names a folder walk listed answer whether a sidecar exists: a name the walk did not see in a
// directory it listed is absent (even if created since), a directory it did not list is asked of
// the file system, and a listed name is checked there too (a broken link is no file).
TEST(ListedFiles, ListedDirectoriesAnswerWithoutTheFileSystem) {
  const fs::path root = fs::temp_directory_path() / "hullcook_listed_files";
  fs::remove_all(root);
  fs::create_directories(root / "walked");
  fs::create_directories(root / "other");
  std::ofstream(root / "walked/hero.png") << "x";
  std::ofstream(root / "other/hero.physics.json") << "{}";
  fs::create_symlink(root / "nowhere.json", root / "walked/broken.hullcook.json");
  ListedFiles listed;
  for (const fs::directory_entry& entry : fs::directory_iterator(root / "walked"))
    listed.add(entry.path());
  listed.seal();
  EXPECT_TRUE(listed.exists(root / "walked/hero.png"));
  std::ofstream(root / "walked/hero.hullcook.json") << "{}";  // after the walk
  EXPECT_FALSE(listed.exists(root / "walked/hero.hullcook.json"));
  // A broken link is there (stop 58): reading it is then refused, not skipped as absent.
  EXPECT_TRUE(listed.exists(root / "walked/broken.hullcook.json"));
  EXPECT_TRUE(listed.exists(root / "other/hero.physics.json"));
  EXPECT_FALSE(listed.exists(root / "other/hero.hullcook.json"));
  fs::remove_all(root);
}

class ProjectSettings : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::temp_directory_path() /
           ("hullcook_asset_settings_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root);
    fs::create_directories(root / "art/tiles");
    fs::create_directories(root / "art/enemies");
    const fs::path sprites = fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";
    fs::copy_file(sprites / "teeworlds__mapres__grass_main.png", root / "art/tiles/grass.png");
    fs::copy_file(sprites / "pingus__groundpieces__ground__foliage__oak1.png",
                  root / "art/enemies/bat.png");
    fs::copy_file(sprites / "pingus__groundpieces__ground__foliage__oak1.png",
                  root / "art/hero.png");
    write(root / "art/hullcook.json",
          R"({"assets": [{"match": "tiles/*.png", "tau": 8, "max_verts": 4},
                         {"match": "**/hero.png", "physics": {"density": 3}}]})");
    write(root / "art/enemies/bat.hullcook.json", R"({"alpha": 200, "lods": ["16"]})");
  }
  void TearDown() override { fs::remove_all(root); }

  static void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

  // Writes text to file and expects the cook of art/ refused, naming the file and the problem.
  void expect_refused(const fs::path& file, const std::string& text, const std::string& problem) {
    write(file, text);
    Settings settings;
    settings.threads = 1;
    try {
      cook({root / "art"}, settings);
      ADD_FAILURE() << text << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
    }
  }

  static const CookedAsset& named(const CookResult& result, const std::string& name) {
    for (const CookedAsset& asset : result.assets) {
      if (asset.name == name) return asset;
    }
    throw std::runtime_error("no asset " + name);
  }

  // Whether the cook lists path among the files it read (its dependencies).
  static bool reads(const CookResult& result, const fs::path& path) {
    for (const fs::path& file : files_read(result)) {
      if (fs::equivalent(file, path)) return true;
    }
    return false;
  }

  static void expect_same_levels(const CookedAsset& a, const CookedAsset& b) {
    ASSERT_EQ(a.levels.size(), b.levels.size()) << a.name;
    for (std::size_t l = 0; l < a.levels.size(); ++l) {
      EXPECT_EQ(a.levels[l].tau, b.levels[l].tau) << a.name;
      EXPECT_EQ(a.levels[l].hulls, b.levels[l].hulls) << a.name << " level " << l;
    }
  }

  fs::path root;
};

TEST_F(ProjectSettings, Issue18_EachAssetCooksAsWithItsSettingsOnTheCommandLine) {
  Settings settings;
  settings.threads = 2;
  const CookResult folder = cook({root / "art"}, settings);
  ASSERT_EQ(folder.assets.size(), 3u);

  Settings tiles = settings;
  tiles.tau = Tolerance{8.0, false};
  tiles.max_verts = 4;
  const CookResult tile_alone = cook({root / "art/tiles/grass.png"}, tiles);
  const CookedAsset& grass = named(folder, "tiles/grass.png");
  expect_same_levels(grass, tile_alone.assets.at(0));
  for (const Ring& hull : grass.levels.at(0).hulls) EXPECT_LE(hull.size(), 4u);

  Settings bat = settings;
  bat.alpha = 200;
  bat.lods = {Tolerance{16.0, false}};
  expect_same_levels(named(folder, "enemies/bat.png"),
                     cook({root / "art/enemies/bat.png"}, bat).assets.at(0));
  EXPECT_EQ(named(folder, "enemies/bat.png").levels.size(), 2u);

  const CookedAsset& hero = named(folder, "hero.png");
  ASSERT_TRUE(hero.physics.has_value());
  EXPECT_EQ(hero.physics->density, 3.0f);
  EXPECT_FALSE(named(folder, "enemies/bat.png").physics.has_value());
  expect_same_levels(hero, cook({root / "art/hero.png"}, settings).assets.at(0));
}

// "merge" (stop 50) cooks an asset as --merge does, in a folder's cook and cooked alone; the
// other assets keep their hulls.
TEST_F(ProjectSettings, MergeIsASettingPerAsset) {
  Settings settings;
  settings.threads = 2;
  const CookResult before = cook({root / "art"}, settings);
  write(root / "art/hero.hullcook.json", R"({"merge": true})");
  const CookResult after = cook({root / "art"}, settings);
  EXPECT_LT(named(after, "hero.png").levels.at(0).hulls.size(),
            named(before, "hero.png").levels.at(0).hulls.size());
  expect_same_levels(named(after, "hero.png"),
                     cook({root / "art/hero.png"}, settings).assets.at(0));
  expect_same_levels(named(after, "enemies/bat.png"), named(before, "enemies/bat.png"));
  expect_same_levels(named(after, "tiles/grass.png"), named(before, "tiles/grass.png"));
}

// Cooked alone (as a fragment build cooks each image), an image finds the nearest project file up
// from it and gets the settings it gets when its folder is cooked.
TEST_F(ProjectSettings, Issue18_AnImageCookedAloneGetsItsFolderCooksSettings) {
  Settings settings;
  settings.threads = 1;
  const CookResult folder = cook({root / "art"}, settings);
  expect_same_levels(named(folder, "tiles/grass.png"),
                     cook({root / "art/tiles/grass.png"}, settings).assets.at(0));
  expect_same_levels(named(folder, "enemies/bat.png"),
                     cook({root / "art/enemies/bat.png"}, settings).assets.at(0));
}

TEST_F(ProjectSettings, Issue18_TheSettingsFilesAreDependencies) {
  Settings settings;
  settings.threads = 1;
  const CookResult result = cook({root / "art"}, settings);
  EXPECT_TRUE(reads(result, root / "art/hullcook.json"));
  EXPECT_TRUE(reads(result, root / "art/enemies/bat.hullcook.json"));
  EXPECT_TRUE(reads(result, root / "art/tiles/grass.png"));
}

TEST_F(ProjectSettings, Issue18_MalformedSettingsAreBadInputNamingTheFile) {
  Settings settings;
  settings.threads = 1;
  const fs::path project = root / "art/hullcook.json", sidecar = root / "art/hero.hullcook.json";
  expect_refused(project, "{\"assets\": [\n  {\"match\": \"*\"}\n  {}]}",
                 "not valid JSON: parse error at line 3, column 3: syntax error");
  expect_refused(project, "[]", "not a JSON object of project settings");
  expect_refused(project, R"({"assets": [{"match": "*", "tau": 1e400}]})",
                 "not valid JSON: number overflow parsing '1e400'");
  expect_refused(project, R"({"asset": []})", "unknown key 'asset'");
  expect_refused(project, R"({"assets": [{"tau": 2}]})", "needs a \"match\" glob");
  expect_refused(project, R"({"assets": [{"match": "*", "alpha": 300}]})", "'alpha'");
  write(project, R"({"assets": []})");
  expect_refused(sidecar, R"({"tau": "fast"})", "'tau'");
  expect_refused(sidecar, R"({"max_verts": 2})", "'max_verts'");
  expect_refused(sidecar, R"({"measure": "l2"})", "'measure'");
  expect_refused(sidecar, R"({"merge": "yes"})", "'merge'");
  expect_refused(sidecar, R"({"physics": {"density": -1}})", "'density'");
  expect_refused(sidecar, R"({"simplify": 1})", "unknown setting 'simplify'");
  write(sidecar, R"({"lods": ["2%"]})");
  EXPECT_THROW(cook({root / "art"}, settings), InputError);
}

// Stop 59, a helper's project files: a key given twice in one object (hullcook.json's rule, a
// sidecar, a physics sidecar) kept its last value silently, where a sprite sheet's duplicate key
// is refused; and nesting no settings file has is refused before parsing, as a sheet's is.
TEST_F(ProjectSettings, Stop59_AKeyTwiceInOneObjectIsRefusedNamingIt) {
  Settings settings;
  settings.threads = 1;
  auto expect_refused_once = [&](const fs::path& file, const std::string& text,
                                 const std::string& problem) {
    expect_refused(file, text, ": " + problem);
    fs::remove(file);
  };
  const fs::path project = root / "art/hullcook.json", sidecar = root / "art/hero.hullcook.json",
                 physics = root / "art/hero.physics.json";
  expect_refused_once(project, R"({"assets": [{"match": "*", "tau": 3, "tau": 4}]})",
                      "the key 'tau' appears twice in one object");
  expect_refused_once(project, R"({"assets": [], "assets": [{"match": "*", "tau": 4}]})",
                      "the key 'assets' appears twice in one object");
  expect_refused_once(sidecar, R"({"max_verts": 6, "physics": {"density": 1, "density": 2}})",
                      "the key 'density' appears twice in one object");
  expect_refused_once(physics, R"({"friction": 0.5, "friction": 0.2})",
                      "the key 'friction' appears twice in one object");
  expect_refused_once(project,
                      "{\"assets\": " + std::string(300, '[') + std::string(300, ']') + "}",
                      "arrays and objects nested deeper than 256 levels");
  // The same keys in different objects are no duplicates.
  write(project, R"({"assets": [{"match": "*", "tau": 3}, {"match": "hero*", "tau": 4}]})");
  EXPECT_NO_THROW(cook({root / "art"}, settings));
}

// A folder of sprites with alpha and of opaque RGB tiles (keyed with magenta) cooks in one command
// when a rule gives the tiles their colour key; before, the first tile stopped the cook, and only
// --color-key for every image could let it through.
TEST_F(ProjectSettings, AColourKeyPerAssetLetsAMixedFolderCook) {
  // A 24x16 RGB tile: magenta but for a 12x8 block of brown in its lower left.
  constexpr std::uint32_t kWidth = 24, kHeight = 16;
  std::vector<std::uint8_t> rgb;
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const bool solid = x < 12 && y >= 8;
      rgb.insert(rgb.end(), {std::uint8_t(solid ? 120 : 255), std::uint8_t(solid ? 80 : 0),
                             std::uint8_t(solid ? 40 : 255)});
    }
  }
  std::ofstream(root / "art/tiles/dirt.png", std::ios::binary)
      << test::make_png(kWidth, kHeight, 2, rgb);
  Settings settings;
  settings.threads = 1;
  try {
    cook({root / "art"}, settings);
    ADD_FAILURE() << "an opaque image without a colour key was cooked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dirt.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"color_key\""), std::string::npos) << e.what();
  }

  write(root / "art/hullcook.json",
        R"({"assets": [{"match": "tiles/*.png", "tau": 8, "max_verts": 4},
                       {"match": "tiles/dirt.png", "color_key": "#FF00ff"},
                       {"match": "**/hero.png", "physics": {"density": 3}}]})");
  const CookResult folder = cook({root / "art"}, settings);
  ASSERT_EQ(folder.assets.size(), 4u);
  Settings keyed = settings;
  keyed.tau = Tolerance{8.0, false};
  keyed.max_verts = 4;
  keyed.color_key = std::array<std::uint8_t, 3>{255, 0, 255};
  const CookedAsset& dirt = named(folder, "tiles/dirt.png");
  expect_same_levels(dirt, cook({root / "art/tiles/dirt.png"}, keyed).assets.at(0));
  // The block, not the whole image: its hull spans 12 x 8 px (within tau), not 24 x 16.
  ASSERT_EQ(dirt.levels.at(0).hulls.size(), 1u);
  double area = 0.0;
  const Ring& hull = dirt.levels[0].hulls[0];
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    area += 0.5 * (a.x * b.y - a.y * b.x);
  }
  EXPECT_NEAR(std::abs(area), 12.0 * 8.0, 12.0);
  // The sprites with alpha are as before: the key applies to the tile alone.
  expect_same_levels(named(folder, "hero.png"),
                     cook({root / "art/hero.png"}, settings).assets.at(0));

  // A sidecar's null takes back the key its project rule (or the command line) gave.
  write(root / "art/tiles/dirt.hullcook.json", R"({"color_key": null})");
  for (const bool on_the_command_line : {false, true}) {
    Settings given = settings;
    if (on_the_command_line) given.color_key = std::array<std::uint8_t, 3>{255, 0, 255};
    EXPECT_THROW(cook({root / "art"}, given), InputError);
  }
  fs::remove(root / "art/tiles/dirt.hullcook.json");

  write(root / "art/hero.hullcook.json", R"({"color_key": "#ff00f"})");
  EXPECT_THROW(cook({root / "art"}, settings), InputError);
  write(root / "art/hero.hullcook.json", R"({"color_key": 16711935})");
  EXPECT_THROW(cook({root / "art"}, settings), InputError);
}

// "skip": the image is no asset, in a folder's cook and cooked alone (a fragment build then links
// the folder's bytes), and the rule that skips it is a dependency, so that taking it back cooks
// the image again.
TEST_F(ProjectSettings, SkippedImagesAreNoAssetsButTheirSettingsAreRead) {
  write(root / "art/hullcook.json",
        R"({"assets": [{"match": "tiles/*.png", "tau": 8, "max_verts": 4},
                       {"match": "enemies/**", "skip": true}]})");
  Settings settings;
  settings.threads = 2;
  const CookResult folder = cook({root / "art"}, settings);
  ASSERT_EQ(folder.assets.size(), 2u);
  EXPECT_EQ(folder.assets[0].name, "hero.png");
  EXPECT_EQ(folder.assets[1].name, "tiles/grass.png");
  ASSERT_EQ(folder.skipped.size(), 1u);
  EXPECT_TRUE(fs::equivalent(folder.skipped[0], root / "art/enemies/bat.png"));
  EXPECT_TRUE(reads(folder, root / "art/hullcook.json"));
  EXPECT_TRUE(reads(folder, root / "art/enemies/bat.hullcook.json"));

  const CookResult alone = cook({root / "art/enemies/bat.png"}, settings);
  EXPECT_TRUE(alone.assets.empty());
  EXPECT_EQ(alone.skipped.size(), 1u);
  EXPECT_TRUE(reads(alone, root / "art/hullcook.json"));

  // The sidecar comes after the rules: false takes the skip back.
  write(root / "art/enemies/bat.hullcook.json", R"({"alpha": 200, "skip": false})");
  EXPECT_EQ(cook({root / "art"}, settings).assets.size(), 3u);

  // A folder whose every image is skipped is refused, as a folder without images is.
  write(root / "art/enemies/bat.hullcook.json", R"({"skip": true})");
  try {
    cook({root / "art/enemies"}, settings);
    ADD_FAILURE() << "a folder of skipped images was cooked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("every image in this directory is skipped"),
              std::string::npos)
        << e.what();
  }
  write(root / "art/enemies/bat.hullcook.json", R"({"skip": "yes"})");
  EXPECT_THROW(cook({root / "art"}, settings), InputError);
}

// Images that the same rules match, without a sidecar, share one copy of their settings: a rule
// for "**" must not give a cook of 10,000 images 10,000 copies (issue 19's memory).
TEST_F(ProjectSettings, ImagesOfTheSameRulesShareTheirSettings) {
  fs::copy_file(root / "art/tiles/grass.png", root / "art/tiles/sand.png");
  AssetSettings settings;
  const auto grass = settings.for_input(root / "art/tiles/grass.png");
  const auto sand = settings.for_input(root / "art/tiles/sand.png");
  ASSERT_TRUE(grass);
  EXPECT_EQ(grass.get(), sand.get());
  EXPECT_EQ(grass->max_verts, 4u);
  EXPECT_NE(settings.for_input(root / "art/hero.png").get(), grass.get());
  // A sidecar makes the image's own.
  write(root / "art/tiles/sand.hullcook.json", R"({"alpha": 10})");
  const auto own = settings.for_input(root / "art/tiles/sand.png");
  EXPECT_NE(own.get(), grass.get());
  EXPECT_EQ(own->alpha, 10);
  EXPECT_EQ(own->max_verts, 4u);
}

// Stop 61: whole numbers written with a point (20.0, as some exporters write every number) read
// as the whole numbers they are, in settings files as in sprite sheets (stop 59's sheet hunt
// found a sheet's 20.0 refused; settings refused 200.0 alike). A fraction is still refused.
TEST_F(ProjectSettings, Stop61_WholeNumbersWrittenWithAPointAreWhole) {
  AssetSettings settings;
  write(root / "art/tiles/grass.hullcook.json",
        R"({"alpha": 200.0, "max_verts": 5.0, "physics": {"category": 6.0, "mask": 1e2}})");
  const auto pointed = settings.for_input(root / "art/tiles/grass.png");
  ASSERT_TRUE(pointed);
  EXPECT_EQ(pointed->alpha, 200);
  EXPECT_EQ(pointed->max_verts, 5u);
  ASSERT_TRUE(pointed->physics);
  EXPECT_EQ(pointed->physics->category_bits, 6);
  EXPECT_EQ(pointed->physics->mask_bits, 100);
  const fs::path sidecar = root / "art/hero.hullcook.json";
  expect_refused(sidecar, R"({"alpha": 200.5})", "'alpha' must be an integer in 0..255");
  expect_refused(sidecar, R"({"max_verts": 4.25})", "'max_verts'");
  expect_refused(sidecar, R"({"physics": {"category": 1e10}})", "'category' must be an integer");
  expect_refused(sidecar, R"({"alpha": -0.5})", "'alpha'");
}

}  // namespace
}  // namespace hullcook
