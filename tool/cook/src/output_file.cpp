#include "hullcook/cook/output_file.h"

#include "hullcook/core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <system_error>

namespace hullcook {
namespace {

// Writes bytes to a new temporary file beside path (same directory, so that the rename is
// atomic) and returns its name. Throws OutputError naming path; on failure nothing is left.
std::filesystem::path write_temporary(const std::filesystem::path& path, std::string_view bytes) {
  check_directory_of(path);
  std::filesystem::path directory = path.parent_path();
  if (directory.empty()) directory = ".";
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
  return temporary;
}

}  // namespace

void check_directory_of(const std::filesystem::path& path) {
  std::filesystem::path directory = path.parent_path();
  if (directory.empty()) directory = ".";
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error)) {
    throw OutputError(path.string() + ": cannot write: directory " + directory.string() +
                      " does not exist");
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  write_files_atomically({{path, std::string(bytes)}});
}

void write_files_atomically(
    const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
  std::vector<std::filesystem::path> temporaries;
  auto remove_temporaries = [&](std::size_t from) {
    for (std::size_t k = from; k < temporaries.size(); ++k) std::remove(temporaries[k].c_str());
  };
  try {
    for (const auto& [path, bytes] : files) temporaries.push_back(write_temporary(path, bytes));
  } catch (...) {
    remove_temporaries(0);
    throw;
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::error_code error;
    std::filesystem::rename(temporaries[k], files[k].first, error);
    if (error) {
      remove_temporaries(k);
      throw OutputError(files[k].first.string() + ": cannot write: " + error.message());
    }
  }
}

void check_not_an_input(const std::filesystem::path& output,
                        const std::vector<std::filesystem::path>& inputs) {
  std::error_code error;
  if (!std::filesystem::exists(output, error)) return;
  for (const std::filesystem::path& input : inputs) {
    if (std::filesystem::equivalent(output, input, error)) {
      throw UsageError(output.string() + ": this output would replace an input (" + input.string() +
                       "); write it elsewhere");
    }
  }
}

}  // namespace hullcook
