// --depfile: cook and link list every file their outputs depend on, in a syntax Make and Ninja
// read, written with the outputs or not at all.
#include "run_command.h"
#include "test_directory.h"

#include "hullcook/core/error.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>

namespace hullcook {
namespace {

namespace fs = std::filesystem;
using test::read_bytes;
using test::run_hullcook;

const fs::path kSprites = fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";
const char* const kSmall = "frozen-bubble__balls__stick_effect_2.png";

// The targets and the dependencies of a depfile, unescaped as Make reads them.
struct Rule {
  std::set<std::string> targets, dependencies;
};

Rule parse_depfile(const std::string& text) {
  Rule rule;
  std::string word;
  bool after_colon = false;
  auto finish = [&] {
    if (!word.empty()) (after_colon ? rule.dependencies : rule.targets).insert(word);
    word.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\\' && i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '#')) {
      word += text[++i];
    } else if (c == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
      ++i;
      finish();
    } else if (c == '$' && i + 1 < text.size() && text[i + 1] == '$') {
      word += text[++i];
    } else if (c == ':' && !after_colon && (i + 1 == text.size() || text[i + 1] == ' ')) {
      finish();
      after_colon = true;
    } else if (c == ' ' || c == '\n') {
      finish();
    } else {
      word += c;
    }
  }
  finish();
  return rule;
}

class DepfileCli : public test::TestDirectory {
 protected:
  DepfileCli() : TestDirectory("hullcook depfile cli ") {}
  void SetUp() override {
    TestDirectory::SetUp();
    fs::create_directories(directory / "sprites/with space");
    fs::copy_file(kSprites / kSmall, directory / "sprites/a#1.png");
    fs::copy_file(kSprites / kSmall, directory / "sprites/with space/b$.png");
    std::ofstream(directory / "sprites/with space/b$.physics.json") << R"({"density": 2})";
  }

  std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }
};

TEST_F(DepfileCli, CookListsEveryFileReadAndDirectorySearched) {
  const fs::path sprites = directory / "sprites";
  auto result = run_hullcook("cook " + quoted(sprites) + " -o " + quoted(directory / "out.hcb") +
                             " --json " + quoted(directory / "out.json") + " --depfile " +
                             quoted(directory / "out.d") + " -q");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const Rule rule = parse_depfile(read_bytes(directory / "out.d"));
  EXPECT_EQ(rule.targets, (std::set<std::string>{(directory / "out.hcb").string(),
                                                 (directory / "out.json").string()}));
  EXPECT_EQ(rule.dependencies,
            (std::set<std::string>{(sprites / "a#1.png").string(),
                                   (sprites / "with space/b$.png").string(),
                                   (sprites / "with space/b$.physics.json").string(),
                                   sprites.string(), (sprites / "with space").string()}))
      << read_bytes(directory / "out.d");
}

TEST_F(DepfileCli, LinkListsItsFragments) {
  const fs::path fragment = directory / "a 1.hcf";
  ASSERT_EQ(
      run_hullcook("cook " + quoted(directory / "sprites/a#1.png") + " -o " + quoted(fragment))
          .exit_code,
      0);
  auto result = run_hullcook("link " + quoted(fragment) + " -o " + quoted(directory / "g.hcb") +
                             " --depfile " + quoted(directory / "g.d") + " -q");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const Rule rule = parse_depfile(read_bytes(directory / "g.d"));
  EXPECT_EQ(rule.targets, std::set<std::string>{(directory / "g.hcb").string()});
  EXPECT_EQ(rule.dependencies, std::set<std::string>{fragment.string()});
}

TEST_F(DepfileCli, WrittenWithTheOutputsOrNotAtAll) {
  std::ofstream(directory / "sprites/broken.png") << "not a png";
  auto result =
      run_hullcook("cook " + quoted(directory / "sprites") + " -o " +
                   quoted(directory / "out.hcb") + " --depfile " + quoted(directory / "out.d"));
  EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::bad_input)) << result.output;
  EXPECT_FALSE(fs::exists(directory / "out.d"));
  auto same =
      run_hullcook("cook " + quoted(directory / "sprites/a#1.png") + " -o " +
                   quoted(directory / "out.hcb") + " --depfile " + quoted(directory / "out.hcb"));
  EXPECT_EQ(same.exit_code, static_cast<int>(ExitCode::usage)) << same.output;
  auto nowhere = run_hullcook("cook " + quoted(directory / "sprites/a#1.png") + " -o " +
                              quoted(directory / "out.hcb") + " --depfile " +
                              quoted(directory / "missing/out.d"));
  EXPECT_EQ(nowhere.exit_code, static_cast<int>(ExitCode::output_failed)) << nowhere.output;
  EXPECT_FALSE(fs::exists(directory / "out.hcb"));
}

// Stop 60, a helper's hunt: a ':' in a file name made Make read the depfile as a second rule
// ("target pattern contains no '%'. Stop."), and a tab split the name in two for Ninja, which then
// rebuilt every time. Neither can be escaped for both: refused, as a line break is, naming the
// file, before anything is written.
TEST_F(DepfileCli, Stop60_ANameWithAColonOrATabIsRefusedNotWrittenUnreadable) {
  for (const std::string name : {"co:lon.png", "tab\tx.png", "back\\", "a\\ b.png", "a\\#b.png"}) {
    const fs::path folder = directory / "odd";
    fs::remove_all(folder);
    fs::create_directories(folder);
    fs::copy_file(kSprites / kSmall, folder / "a.png");
    const fs::path odd = name == "back\\" ? folder / name / "b.png" : folder / name;
    fs::create_directories(odd.parent_path());
    fs::copy_file(kSprites / kSmall, odd);
    auto result = run_hullcook("cook " + quoted(folder) + " -o " + quoted(directory / "out.hcb") +
                               " --depfile " + quoted(directory / "out.d") + " -q");
    EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::usage)) << result.output;
    EXPECT_NE(result.output.find("a depfile cannot name a path"), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(directory / "out.d"));
    EXPECT_FALSE(fs::exists(directory / "out.hcb"));
  }
}

// Stop 58, a helper's hostile files: --depfile and --report over a file the cook reads (an image
// found in a folder, a sidecar) replaced it with exit 0, where -o was refused; and an output that
// is a pipe or a device was renamed over (--depfile /dev/null, run as root, made it a file).
TEST_F(DepfileCli, Stop58_SideOutputsNeverReplaceAnInputOrAPipe) {
  const fs::path image = directory / "sprites/a#1.png";
  const fs::path sidecar = directory / "sprites/with space/b$.physics.json";
  const std::string image_bytes = read_bytes(image), sidecar_bytes = read_bytes(sidecar);
  for (const std::string& side : {"--depfile " + quoted(image), "--report " + quoted(sidecar),
                                  "--depfile " + quoted(sidecar)}) {
    SCOPED_TRACE(side);
    auto result = run_hullcook("cook " + quoted(directory / "sprites") + " -o " +
                               quoted(directory / "out.hcb") + " -q " + side);
    EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::usage)) << result.output;
    EXPECT_NE(result.output.find("this output would replace an input"), std::string::npos)
        << result.output;
    EXPECT_EQ(read_bytes(image), image_bytes);
    EXPECT_EQ(read_bytes(sidecar), sidecar_bytes);
    EXPECT_FALSE(fs::exists(directory / "out.hcb"));
  }
  const fs::path pipe_output = directory / "pipe.hcb", pipe_depfile = directory / "pipe.d";
  for (const fs::path& pipe : {pipe_output, pipe_depfile}) {
    ASSERT_EQ(std::system(("mkfifo " + quoted(pipe)).c_str()), 0);
  }
  for (const std::string& outputs :
       {"-o " + quoted(pipe_output),
        "-o " + quoted(directory / "out.hcb") + " --depfile " + quoted(pipe_depfile)}) {
    SCOPED_TRACE(outputs);
    auto result = run_hullcook("cook " + quoted(image) + " -q " + outputs);
    EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::output_failed)) << result.output;
    EXPECT_NE(result.output.find("it is not a regular file"), std::string::npos) << result.output;
    EXPECT_TRUE(fs::is_fifo(pipe_output));
    EXPECT_TRUE(fs::is_fifo(pipe_depfile));
    EXPECT_FALSE(fs::exists(directory / "out.hcb"));
  }
}

// Stop 58, a helper's hostile files: a broken link named hullcook.json, NAME.hullcook.json or
// NAME.physics.json was taken as no file (the cook used the defaults and its depfile did not name
// the link), where a broken link to an image is an error. It is refused, naming the link.
TEST_F(DepfileCli, Stop58_ABrokenLinkWhereASettingsFileIsLookedForIsRefused) {
  for (const char* name : {"hullcook.json", "a#1.hullcook.json", "a#1.physics.json"}) {
    SCOPED_TRACE(name);
    const fs::path link = directory / "sprites" / name;
    fs::create_symlink(directory / "nowhere.json", link);
    auto result = run_hullcook("cook " + quoted(directory / "sprites") + " -o " +
                               quoted(directory / "out.hcb") + " -q --depfile " +
                               quoted(directory / "out.d"));
    EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::bad_input)) << result.output;
    EXPECT_NE(result.output.find(link.string() + ": a broken link"), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(directory / "out.hcb"));
    EXPECT_FALSE(fs::exists(directory / "out.d"));
    fs::remove(link);
  }
}

// GNU Make itself reads the depfile: a change to the physics sidecar, which the rule does not
// name, makes the fragment out of date; nothing else does.
TEST_F(DepfileCli, MakeRebuildsWhenASidecarChanges) {
  if (std::system("make --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "GNU make not found";
  std::ofstream(directory / "Makefile")
      << "b.hcf: sprites/with\\ space/b$$.png\n"
      << "\t" << HULLCOOK_EXE << " cook 'sprites/with space/b$$.png' -o b.hcf --depfile b.d -q\n"
      << "-include b.d\n";
  const std::string make = "make -C " + quoted(directory) + " ";
  // Times set in the past, so that coarse file system clocks cannot blur the order.
  const fs::path image = directory / "sprites/with space/b$.png";
  const fs::path sidecar = directory / "sprites/with space/b$.physics.json";
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(image, now - std::chrono::seconds(100));
  fs::last_write_time(sidecar, now - std::chrono::seconds(100));
  ASSERT_EQ(std::system((make + "-s >/dev/null").c_str()), 0);
  ASSERT_TRUE(fs::exists(directory / "b.hcf"));
  EXPECT_EQ(std::system((make + "-q").c_str()), 0) << "up to date after a build";
  // The sidecar changed after the fragment was cooked.
  fs::last_write_time(directory / "b.hcf", now - std::chrono::seconds(60));
  fs::last_write_time(sidecar, now - std::chrono::seconds(50));
  EXPECT_NE(std::system((make + "-q").c_str()), 0) << "the sidecar changed";
  ASSERT_EQ(std::system((make + "-s >/dev/null").c_str()), 0);
  EXPECT_EQ(std::system((make + "-q").c_str()), 0);
}

}  // namespace
}  // namespace hullcook
