#include "hullcook/cook/output_file.h"

#include "hullcook/core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <system_error>

namespace hullcook {

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path directory = path.parent_path();
  if (directory.empty()) directory = ".";
  if (!std::filesystem::is_directory(directory)) {
    throw OutputError(path.string() + ": cannot write: directory " + directory.string() +
                      " does not exist");
  }
  // A unique name in the same directory, so that the final rename is atomic.
  std::random_device entropy;
  std::filesystem::path temporary =
      directory / ("." + path.filename().string() + ".tmp" + std::to_string(entropy()));
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) {
    throw OutputError(path.string() + ": cannot write: " + std::strerror(errno));
  }
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  int write_errno = errno;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) {
    std::remove(temporary.c_str());
    throw OutputError(path.string() + ": cannot write: " + std::strerror(write_errno));
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    throw OutputError(path.string() + ": cannot write: " + error.message());
  }
}

}  // namespace hullcook
