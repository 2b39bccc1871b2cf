// Issue 19: a cook of many assets holds no more than one of few. `hullcook cook` streams its
// bundle (each asset's hulls spilled as it is cooked), so that cooking 1,000 sprites in nested
// folders gives the bundle a library cook of the same files writes whole, in a peak memory close
// to that of cooking 100. (scripts/bench-scale measures 100, 1,000 and 10,000.)
#include "test_directory.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/cook.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

extern char** environ;

namespace hullcook {
namespace {

namespace fs = std::filesystem;

class ScaleCli : public test::TestDirectory {
 protected:
  ScaleCli() : TestDirectory("hullcook_scale_cli_") {}

  // count sprites under directory/NAME, 100 to a folder and 10 to a subfolder, as hard links
  // (copies where links fail) to the five smallest samples, so that the test cooks quickly.
  fs::path make_sprites(const std::string& name, int count) {
    std::vector<fs::path> samples;
    for (const auto& entry :
         fs::directory_iterator(fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites")) {
      if (entry.path().extension() == ".png") samples.push_back(entry.path());
    }
    std::sort(samples.begin(), samples.end(), [](const fs::path& a, const fs::path& b) {
      return std::make_pair(fs::file_size(a), a) < std::make_pair(fs::file_size(b), b);
    });
    samples.resize(5);
    const fs::path root = directory / name;
    for (int i = 0; i < count; ++i) {
      char folder[64];
      std::snprintf(folder, sizeof folder, "g%03d/h%d", i / 100, (i / 10) % 10);
      fs::create_directories(root / folder);
      char file[32];
      std::snprintf(file, sizeof file, "a%05d_", i);
      const fs::path& sample = samples[static_cast<std::size_t>(i) % samples.size()];
      const fs::path to = root / folder / (file + sample.filename().string());
      std::error_code error;
      fs::create_hard_link(sample, to, error);
      if (error) fs::copy_file(sample, to);
    }
    return root;
  }

  // Runs `hullcook cook input -q -o output --threads 2`; its exit code and peak resident memory.
  static std::pair<int, long> cook_process(const fs::path& input, const fs::path& output) {
    std::vector<std::string> arguments{HULLCOOK_EXE, "cook",          input.string(), "-q",
                                       "-o",         output.string(), "--threads",    "2"};
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return {-1, 0};
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_maxrss};
  }
};

TEST_F(ScaleCli, Issue19_AThousandSpritesStreamIntoTheBundleOfAWholeCook) {
  const fs::path hundred = make_sprites("hundred", 100), thousand = make_sprites("thousand", 1000);
  const auto [hundred_exit, hundred_kb] = cook_process(hundred, directory / "hundred.hcb");
  const auto [thousand_exit, thousand_kb] = cook_process(thousand, directory / "thousand.hcb");
  ASSERT_EQ(hundred_exit, 0);
  ASSERT_EQ(thousand_exit, 0);

  // The streamed bundle is the one the whole result gives, names in order from nested folders.
  Settings settings;
  settings.threads = 2;
  const CookResult whole = cook({thousand}, settings);
  ASSERT_EQ(whole.assets.size(), 1000u);
  EXPECT_EQ(whole.assets[999].name.substr(0, 15), "g009/h9/a00999_");
  EXPECT_TRUE(test::read_bytes(directory / "thousand.hcb") == write_bundle(whole.assets))
      << "the streamed bundle differs from write_bundle's";

  std::printf("peak resident memory: 100 sprites %ld KB, 1,000 sprites %ld KB (%.2fx)\n",
              hundred_kb, thousand_kb, static_cast<double>(thousand_kb) / hundred_kb);
#if !defined(__SANITIZE_ADDRESS__)
  // Held whole, the hulls of 1,000 sprites doubled the peak; streamed, it grows by the assets'
  // names and records alone (AddressSanitizer's quarantine holds freed memory, so it is not
  // measured there).
  EXPECT_LT(thousand_kb, 3 * hundred_kb / 2);
#endif
}

}  // namespace
}  // namespace hullcook
