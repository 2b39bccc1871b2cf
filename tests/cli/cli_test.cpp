#include "run_command.h"

#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace hullcook {
namespace {

using test::run_hullcook;

TEST(Cli, VersionPrintsVersionAndExitsZero) {
  auto result = run_hullcook("--version");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("hullcook " HULLCOOK_VERSION_FOR_TEST), std::string::npos)
      << result.output;
}

TEST(Cli, HelpListsExitCodes) {
  auto result = run_hullcook("--help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("Exit codes"), std::string::npos) << result.output;
}

TEST(Cli, HelpListsEverySubcommand) {
  auto result = run_hullcook("--help");
  for (const char* name : {"cook", "link", "decompose", "preview", "inspect"}) {
    EXPECT_NE(result.output.find(std::string("\n  ") + name + " "), std::string::npos)
        << name << "\n"
        << result.output;
  }
}

// A command line naming a subcommand sets up only that one (issue 22: start-up); each still
// parses its own options, its help and its usage errors as when all were set up.
TEST(Cli, Issue22_EachSubcommandAloneHasItsHelpAndOptions) {
  const struct {
    const char* name;
    const char* option;
  } commands[] = {{"cook", "--max-verts"},
                  {"link", "--output"},
                  {"decompose", "--measure"},
                  {"preview", "OUT.png or OUT.svg"},
                  {"inspect", "--json"}};
  for (const auto& command : commands) {
    auto help = run_hullcook(std::string(command.name) + " --help");
    EXPECT_EQ(help.exit_code, 0) << command.name;
    EXPECT_NE(help.output.find(command.option), std::string::npos) << command.name << "\n"
                                                                   << help.output;
    auto wrong = run_hullcook(std::string(command.name) + " --no-such-option");
    EXPECT_EQ(wrong.exit_code, static_cast<int>(ExitCode::usage)) << command.name;
  }
}

TEST(Cli, UnknownOptionIsUsageError) {
  auto result = run_hullcook("--no-such-option");
  EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::usage)) << result.output;
}

TEST(Cli, UnknownSubcommandIsUsageError) {
  auto result = run_hullcook("no-such-command");
  EXPECT_EQ(result.exit_code, static_cast<int>(ExitCode::usage)) << result.output;
}

class AtomicWrite : public ::testing::Test {
 protected:
  void SetUp() override {
    directory =
        std::filesystem::temp_directory_path() /
        ("hullcook_atomic_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
  }
  void TearDown() override { std::filesystem::remove_all(directory); }
  std::filesystem::path directory;
};

TEST_F(AtomicWrite, WritesExactBytesAndLeavesNoTemporary) {
  std::string bytes("a\0b\nc", 5);
  write_file_atomically(directory / "out.bin", bytes);
  std::ifstream in(directory / "out.bin", std::ios::binary);
  std::stringstream read;
  read << in.rdbuf();
  EXPECT_EQ(read.str(), bytes);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory),
                          std::filesystem::directory_iterator{}),
            1);
}

TEST_F(AtomicWrite, MissingDirectoryThrowsOutputErrorNamingTheFile) {
  auto target = directory / "missing" / "out.bin";
  try {
    write_file_atomically(target, "x");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    EXPECT_EQ(e.code, ExitCode::output_failed);
  }
  EXPECT_FALSE(std::filesystem::exists(target));
}

TEST_F(AtomicWrite, ExistingFileIsReplacedWhole) {
  write_file_atomically(directory / "out.bin", std::string(1000, 'x'));
  write_file_atomically(directory / "out.bin", "short");
  EXPECT_EQ(std::filesystem::file_size(directory / "out.bin"), 5u);
}

}  // namespace
}  // namespace hullcook
