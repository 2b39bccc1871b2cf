#include "listed_files.h"

#include <algorithm>
#include <system_error>

namespace hullcook {

void ListedFiles::add(const std::filesystem::path& entry) {
  names_[entry.parent_path().native()].push_back(entry.filename().native());
}

void ListedFiles::seal() {
  // Called after each directory input's walk: the earlier walks' names are sorted already.
  for (auto& [directory, names] : names_) {
    if (!std::is_sorted(names.begin(), names.end())) std::sort(names.begin(), names.end());
  }
}

bool ListedFiles::exists(const std::filesystem::path& path) const {
  const auto listed = names_.find(path.parent_path().native());
  if (listed != names_.end() &&
      !std::binary_search(listed->second.begin(), listed->second.end(), path.filename().native())) {
    return false;
  }
  std::error_code error;  // a link counts, broken or not (see asset_settings.cpp)
  return std::filesystem::exists(std::filesystem::symlink_status(path, error));
}

}  // namespace hullcook
