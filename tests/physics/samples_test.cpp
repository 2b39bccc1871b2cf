// The drop samples (samples/physics) on a bundle written here: every sprite comes to rest on the
// terrain at the height its silhouette predicts, in both engines.
#include "physics_scene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace hullcook {
namespace {

std::string run(const std::string& command, int& exit_code) {
  std::string output;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return output;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  const int status = pclose(pipe);
  exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return output;
}

// The rest height printed for name, or NaN.
double rest_y(const std::string& output, const std::string& name) {
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(name + ":", 0) != 0) continue;
    const auto at = line.find("rest at (");
    double x = 0, y = 0;
    if (at != std::string::npos &&
        std::sscanf(line.c_str() + at, "rest at (%lf, %lf)", &x, &y) == 2)
      return y;
  }
  return std::nan("");
}

class DropSample : public ::testing::TestWithParam<const char*> {};

TEST_P(DropSample, SpritesComeToRestOnTheTerrain) {
  const std::filesystem::path dir = std::filesystem::path(HULLCOOK_BINARY_DIR) / "tests/physics";
  std::filesystem::create_directories(dir);
  // One file per engine: ctest runs the two cases in parallel.
  const std::filesystem::path bundle =
      dir / ("drop_scene_" + std::filesystem::path(GetParam()).filename().string() + ".hcb");
  std::ofstream(bundle, std::ios::binary) << test::scene_bundle();
  int exit_code = -1;
  const std::string output = run(std::string(GetParam()) + " " + bundle.string(), exit_code);
  ASSERT_EQ(exit_code, 0) << output;
  // Both sprites have their lowest point 0.5 m below their origin; the terrain's top is y = 0.
  for (const char* name : {"props/house.png", "props/ell.png"})
    EXPECT_NEAR(rest_y(output, name), 0.5, test::kTau + 0.015) << output;
  EXPECT_NE(output.find("0 hulls altered"), std::string::npos) << output;

  const std::string bad =
      run(std::string(GetParam()) + " " + (dir / "missing.hcb").string(), exit_code);
  EXPECT_EQ(exit_code, 2) << bad;
}

INSTANTIATE_TEST_SUITE_P(Engines, DropSample,
                         ::testing::Values(HULLCOOK_DROP_BOX2D, HULLCOOK_DROP_CHIPMUNK));

}  // namespace
}  // namespace hullcook
