// Bundles as bytes for the format's tests: the golden files' folder, files read whole, and
// buffers aligned as a reader may ask.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hullcook::test {

inline const std::filesystem::path kGoldenDir =
    std::filesystem::path(HULLCOOK_SOURCE_DIR) / "tests/formats/golden";

// A 4-byte aligned copy of bytes (std::string's buffer is, but copies made here are explicit).
struct AlignedBytes {
  explicit AlignedBytes(const std::string& bytes) : words((bytes.size() + 3) / 4 + 1) {
    std::memcpy(words.data(), bytes.data(), bytes.size());
    size = bytes.size();
  }
  const void* data() const { return words.data(); }
  std::vector<std::uint32_t> words;
  std::size_t size = 0;
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

}  // namespace hullcook::test
