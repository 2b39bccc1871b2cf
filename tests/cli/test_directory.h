// A fresh temporary directory per test, named after it and removed after it, and whole-file
// reads: what the command-line tests that write files share.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace hullcook::test {

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

// Fixture: `directory` is /tmp/<prefix><test name>, empty at the start of each test.
class TestDirectory : public ::testing::Test {
 protected:
  explicit TestDirectory(const std::string& prefix) : prefix_(prefix) {}
  void SetUp() override {
    directory = std::filesystem::temp_directory_path() /
                (prefix_ + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
  }
  void TearDown() override { std::filesystem::remove_all(directory); }

  std::filesystem::path directory;

 private:
  std::string prefix_;
};

}  // namespace hullcook::test
