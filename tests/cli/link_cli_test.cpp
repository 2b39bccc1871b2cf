// `hullcook cook X -o x.hcf` then `hullcook link`: the same bundle as one `cook DIR`, fragments
// that do not depend on where their input was, and bad fragments refused with exit code 2.
#include "run_command.h"
#include "test_directory.h"

#include "hullcook/core/error.h"
#include "hullcook/format/fragment_layout.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace hullcook {
namespace {

namespace fs = std::filesystem;
using test::read_bytes;
using test::run_hullcook;

const fs::path kSprites = fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

class LinkCli : public test::TestDirectory {
 protected:
  LinkCli() : TestDirectory("hullcook_link_cli_") {}

  // A nested folder of sprites, one with a physics sidecar; returns the names cook gives them.
  std::vector<std::string> make_sprite_folder(const fs::path& root) {
    const std::vector<std::pair<std::string, std::string>> files = {
        {"frozen-bubble__balls__bubble-1-mini.png", "bubble.png"},
        {"pingus__groundpieces__bridge__space__grid1.png", "level/grid.png"},
        {"pingus__groundpieces__ground__signposts__danger.png", "level/signs/danger.png"},
        {"frozen-bubble__balls__stick_effect_2.png", "a_stick.png"}};
    std::vector<std::string> names;
    for (const auto& [sample, name] : files) {
      fs::create_directories((root / name).parent_path());
      fs::copy_file(kSprites / sample, root / name);
      names.push_back(name);
    }
    write_bytes(root / "level/grid.physics.json", R"({"density": 3, "sensor": true})");
    return names;
  }

  std::string cook_fragment(const fs::path& input, const fs::path& fragment,
                            const std::string& extra) {
    auto result = run_hullcook("cook " + input.string() + " -o " + fragment.string() + " " + extra);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_bytes(fragment);
  }
};

const char* const kOptions = "-q --tau 1.5 --lod 6 --ppu 32 --friction 0.4";

TEST_F(LinkCli, CookThenLinkWritesTheBytesOfOneCook) {
  const fs::path sprites = directory / "sprites";
  const std::vector<std::string> names = make_sprite_folder(sprites);
  auto one = run_hullcook("cook " + sprites.string() + " -o " + (directory / "one.hcb").string() +
                          " " + kOptions);
  ASSERT_EQ(one.exit_code, 0) << one.output;
  // Fragments given in reverse order, named by --name after their path in the folder.
  std::string fragments;
  for (std::size_t i = names.size(); i-- > 0;) {
    const fs::path fragment = directory / ("f" + std::to_string(i) + ".hcf");
    cook_fragment(sprites / names[i], fragment, std::string(kOptions) + " --name " + names[i]);
    fragments += " " + fragment.string();
  }
  auto linked =
      run_hullcook("link" + fragments + " -o " + (directory / "linked.hcb").string() + " -q");
  ASSERT_EQ(linked.exit_code, 0) << linked.output;
  EXPECT_EQ(linked.output, "");
  const std::string one_bytes = read_bytes(directory / "one.hcb");
  ASSERT_GT(one_bytes.size(), 64u);
  EXPECT_EQ(read_bytes(directory / "linked.hcb"), one_bytes);
  // The other writers take fragments too.
  auto other = run_hullcook("link" + fragments + " -o " + (directory / "linked.glb").string() +
                            " --json " + (directory / "linked.json").string());
  EXPECT_EQ(other.exit_code, 0) << other.output;
  EXPECT_NE(other.output.find("linked 4 assets from 4 fragments"), std::string::npos);
  EXPECT_NE(read_bytes(directory / "linked.json").find("\"level/signs/danger.png\""),
            std::string::npos);
  EXPECT_GT(fs::file_size(directory / "linked.glb"), 0u);
  // One of each, in the singular.
  auto single = run_hullcook("link " + (directory / "f0.hcf").string() + " -o " +
                             (directory / "single.hcb").string());
  EXPECT_NE(single.output.find("linked 1 asset from 1 fragment into"), std::string::npos)
      << single.output;
}

// A skipped image (a project rule's "skip") cooked alone gives a fragment without assets, so
// that a fragment build of every image links the folder's bytes.
TEST_F(LinkCli, ASkippedImageLinksToNothing) {
  const fs::path sprites = directory / "sprites";
  const std::vector<std::string> names = make_sprite_folder(sprites);
  write_bytes(sprites / "hullcook.json", R"({"assets": [{"match": "level/**", "skip": true}]})");
  auto one = run_hullcook("cook " + sprites.string() + " -o " + (directory / "one.hcb").string() +
                          " " + kOptions);
  ASSERT_EQ(one.exit_code, 0) << one.output;
  std::string fragments;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const fs::path fragment = directory / ("f" + std::to_string(i) + ".hcf");
    cook_fragment(sprites / names[i], fragment, std::string(kOptions) + " --name " + names[i]);
    fragments += " " + fragment.string();
  }
  auto linked = run_hullcook("link" + fragments + " -o " + (directory / "linked.hcb").string());
  ASSERT_EQ(linked.exit_code, 0) << linked.output;
  EXPECT_NE(linked.output.find("linked 2 assets from 4 fragments"), std::string::npos)
      << linked.output;
  EXPECT_EQ(read_bytes(directory / "linked.hcb"), read_bytes(directory / "one.hcb"));
  // Cooked alone to a bundle, it says why the bundle is empty.
  auto alone = run_hullcook("cook " + (sprites / "level/grid.png").string() + " -q -o " +
                            (directory / "grid.hcb").string());
  EXPECT_EQ(alone.exit_code, 0) << alone.output;
  EXPECT_NE(alone.output.find("every input is skipped"), std::string::npos) << alone.output;
}

// What remote execution needs: the same input cooked in two places, one named by an absolute
// path and one by a relative path from another working directory, gives the same fragment.
TEST_F(LinkCli, AFragmentDoesNotDependOnWhereItsInputWas) {
  make_sprite_folder(directory / "a/deep/er");
  make_sprite_folder(directory / "b");
  const std::string here =
      cook_fragment(directory / "a/deep/er/level/grid.png", directory / "a.hcf",
                    std::string(kOptions) + " --threads 1");
  // run_hullcook runs `hullcook ARGS` in a shell: a harmless first command, then the cook from
  // the sprite's own directory.
  auto there = run_hullcook("-h >/dev/null; cd " + (directory / "b/level").string() + " && " +
                            HULLCOOK_EXE + " cook grid.png -o ../../b.hcf --threads 2 " + kOptions);
  ASSERT_EQ(there.exit_code, 0) << there.output;
  ASSERT_GT(here.size(), 64u);
  EXPECT_EQ(read_bytes(directory / "b.hcf"), here);
  // And it does depend on the settings and the sidecar.
  EXPECT_NE(cook_fragment(directory / "b/level/grid.png", directory / "c.hcf", "--tau 1.5"), here);
  fs::remove(directory / "b/level/grid.physics.json");
  EXPECT_NE(cook_fragment(directory / "b/level/grid.png", directory / "d.hcf", kOptions), here);
}

class BadFragment : public LinkCli {
 protected:
  // Links fragment (with a good one) and expects exit code 2 naming it, and no output left.
  void expect_refused(const std::string& bytes, const std::string& problem) {
    const fs::path good = directory / "good.hcf";
    if (!fs::exists(good))
      cook_fragment(kSprites / "frozen-bubble__balls__bubble-1-mini.png", good, "");
    const fs::path bad = directory / "bad.hcf";
    write_bytes(bad, bytes);
    const fs::path output = directory / "game.hcb";
    auto result =
        run_hullcook("link " + good.string() + " " + bad.string() + " -o " + output.string());
    EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::bad_input)) << result.output;
    EXPECT_NE(result.output.find(bad.string() + ": "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(problem), std::string::npos) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_FALSE(fs::exists(output));
    std::size_t left = std::distance(fs::directory_iterator(directory), fs::directory_iterator{});
    EXPECT_EQ(left, 2u) << "temporary files were left behind";
  }

  std::string fragment() {
    return cook_fragment(kSprites / "frozen-bubble__balls__stick_effect_2.png",
                         directory / "stick.hcf", "--lod 4");
  }
};

TEST_F(BadFragment, AnotherToolVersion) {
  std::string bytes = fragment();
  fs::remove(directory / "stick.hcf");
  bytes[offsetof(format::FragmentHeader, tool_version)] = '7';
  expect_refused(bytes, "cooked by hullcook 7");
}

TEST_F(BadFragment, AnotherFormatVersion) {
  std::string bytes = fragment();
  fs::remove(directory / "stick.hcf");
  bytes[offsetof(format::FragmentHeader, format_version)] = 9;
  expect_refused(bytes, "fragment format version 9");
}

TEST_F(BadFragment, Truncated) {
  const std::string bytes = fragment();
  fs::remove(directory / "stick.hcf");
  for (std::size_t size : {std::size_t{0}, std::size_t{3}, std::size_t{63}, std::size_t{64},
                           bytes.size() / 2, bytes.size() - 1}) {
    SCOPED_TRACE(size);
    expect_refused(bytes.substr(0, size), "truncated fragment");
  }
}

TEST_F(BadFragment, NotAFragment) {
  expect_refused(read_bytes(kSprites / "frozen-bubble__balls__stick_effect_2.png"),
                 "not a hullcook fragment");
}

TEST_F(BadFragment, AnAssetNameInTwoFragments) {
  const fs::path twin = directory / "twin.hcf";
  const std::string bytes =
      cook_fragment(kSprites / "frozen-bubble__balls__bubble-1-mini.png", twin, "--tau 3");
  fs::remove(twin);
  expect_refused(bytes, "asset 'frozen-bubble__balls__bubble-1-mini.png' is also in");
}

TEST_F(LinkCli, NameIsForOneInputFile) {
  auto folder = run_hullcook("cook " + kSprites.string() + " -o " + (directory / "x.hcf").string() +
                             " --name x");
  EXPECT_EQ(folder.exit_code, static_cast<int>(ExitCode::usage)) << folder.output;
  auto empty =
      run_hullcook("cook " + (kSprites / "frozen-bubble__balls__stick_effect_2.png").string() +
                   " -o " + (directory / "x.hcf").string() + " --name ''");
  EXPECT_EQ(empty.exit_code, static_cast<int>(ExitCode::usage)) << empty.output;
  EXPECT_FALSE(fs::exists(directory / "x.hcf"));
}

TEST_F(LinkCli, LinkWritesNoFragment) {
  const fs::path fragment = directory / "stick.hcf";
  cook_fragment(kSprites / "frozen-bubble__balls__stick_effect_2.png", fragment, "");
  auto result =
      run_hullcook("link " + fragment.string() + " -o " + (directory / "all.hcf").string());
  EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::usage)) << result.output;
  EXPECT_FALSE(fs::exists(directory / "all.hcf"));
}

}  // namespace
// Stop 58, a helper's hostile files: a name holding terminal controls (an escape sequence in an
// image's file name, kept in the bundle and glTF) was printed raw by inspect and by cook's table,
// driving the terminal. Controls are shown as \xNN; the name itself is kept as it was.
TEST_F(LinkCli, Stop59_ControlBytesInANameArePrintedEscaped) {
  const std::string name = std::string("red\x1b[31mtext\x07.png");
  fs::copy_file(kSprites / "frozen-bubble__balls__bubble-1-mini.png", directory / name);
  for (const char* extension : {".hcb", ".glb"}) {
    SCOPED_TRACE(extension);
    const fs::path output = directory / (std::string("out") + extension);
    const test::CommandResult cooked =
        test::run_hullcook("cook '" + (directory / name).string() + "' -o " + output.string());
    ASSERT_EQ(cooked.exit_code, 0) << cooked.output;
    EXPECT_EQ(cooked.output.find('\x1b'), std::string::npos) << cooked.output;
    EXPECT_NE(cooked.output.find("red\\x1b[31mtext\\x07.png"), std::string::npos) << cooked.output;
    const test::CommandResult inspected = test::run_hullcook("inspect " + output.string());
    ASSERT_EQ(inspected.exit_code, 0) << inspected.output;
    EXPECT_EQ(inspected.output.find('\x1b'), std::string::npos) << inspected.output;
    EXPECT_EQ(inspected.output.find('\x07'), std::string::npos) << inspected.output;
    EXPECT_NE(inspected.output.find("asset \"red\\x1b[31mtext\\x07.png\""), std::string::npos)
        << inspected.output;
  }
}

}  // namespace hullcook
