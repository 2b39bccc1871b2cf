// Issue 18: a progress bar on a terminal, and none in a pipe or with -q. The terminal is a
// pseudo-terminal from util-linux's `script` (Debian's essential bsdutils).
#include "run_command.h"
#include "test_directory.h"

#include <gtest/gtest.h>

#include <string>

namespace hullcook {
namespace {

namespace fs = std::filesystem;

class ProgressCli : public test::TestDirectory {
 protected:
  ProgressCli() : TestDirectory("hullcook_progress_cli_") {}

  // Runs `hullcook arguments` with stdout on a pseudo-terminal; what the terminal received.
  test::CommandResult run_on_terminal(const std::string& arguments) {
    const std::string command = std::string(HULLCOOK_EXE) + " " + arguments;
    test::CommandResult result;
    const std::string shell = "script -qec '" + command + "' /dev/null";
    FILE* pipe = popen(shell.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
  }

  const std::string sprites = (fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites").string();
};

TEST_F(ProgressCli, Issue18_ATerminalSeesTheBarCountUpToEveryAssetThenTheTable) {
  const auto result =
      run_on_terminal("cook " + sprites + " --threads 2 -o " + (directory / "out.hcb").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::size_t last = result.output.rfind("hullcook: [");
  ASSERT_NE(last, std::string::npos) << "no progress bar on a terminal";
  EXPECT_NE(result.output.find("] 43/43 assets", last), std::string::npos) << result.output;
  // Cleared before the table, which starts on a clean line.
  const std::size_t table = result.output.find("asset ", last);
  ASSERT_NE(table, std::string::npos);
  EXPECT_NE(result.output.rfind("\r\033[2K", table), std::string::npos);
  EXPECT_GT(table, result.output.rfind("\r\033[2K", table));
}

TEST_F(ProgressCli, Issue18_NoBarInAPipeOrWhenQuiet) {
  const auto piped =
      test::run_hullcook("cook " + sprites + " -o " + (directory / "piped.hcb").string());
  ASSERT_EQ(piped.exit_code, 0) << piped.output;
  EXPECT_EQ(piped.output.find("hullcook: ["), std::string::npos) << "a bar in a pipe";
  EXPECT_NE(piped.output.find("pieces"), std::string::npos) << "the table is still printed";

  const auto quiet =
      run_on_terminal("cook " + sprites + " -q -o " + (directory / "quiet.hcb").string());
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("hullcook: ["), std::string::npos) << "a bar with -q";
}

// A cook that fails on a terminal leaves its error on a clean line, not after the bar.
TEST_F(ProgressCli, Issue18_AnErrorIsPrintedOnACleanLine) {
  fs::create_directories(directory / "in");
  fs::copy_file(fs::path(sprites) / "teeworlds__mapres__grass_main.png", directory / "in/a.png");
  std::ofstream(directory / "in/b.png") << "not a png";
  const auto result = run_on_terminal("cook " + (directory / "in").string() + " --threads 1 -o " +
                                      (directory / "out.hcb").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  const std::size_t error = result.output.find("hullcook: error:");
  ASSERT_NE(error, std::string::npos) << result.output;
  const std::size_t bar = result.output.rfind("hullcook: [", error);
  if (bar != std::string::npos) {
    EXPECT_NE(result.output.substr(bar, error - bar).find("\r\033[2K"), std::string::npos)
        << "the bar was not cleared before the error";
  }
  EXPECT_FALSE(fs::exists(directory / "out.hcb"));
}

}  // namespace
}  // namespace hullcook
