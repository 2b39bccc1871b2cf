#include "hullcook/core/error.h"

#include <system_error>

namespace hullcook {

void refuse_unless_regular_file(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status) || std::filesystem::is_regular_file(status) ||
      std::filesystem::is_directory(status)) {
    return;
  }
  throw InputError(path.string() + ": not a regular file or a directory");
}

}  // namespace hullcook
