// The names a folder walk saw, per directory: whether a sidecar beside an image exists is then a
// lookup, not a system call (a cook of 10,000 sprites asked the kernel 40,000 times for sidecars
// that were not there, 18 % of its time).
#pragma once

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace hullcook {

class ListedFiles {
 public:
  // Every entry of a walked directory, in any order; then seal() once, before any lookup.
  void add(const std::filesystem::path& entry);
  void seal();

  // Whether a file exists at path: false without a system call when the walk listed path's
  // directory and did not see it (a file created since is not seen); otherwise as
  // std::filesystem::exists (a listed name may be a broken link). Safe from several threads
  // once sealed.
  bool exists(const std::filesystem::path& path) const;

 private:
  // By directory, as the walk spelled it (parent_path's native string): its entries' names,
  // sorted.
  std::unordered_map<std::string, std::vector<std::string>> names_;
};

}  // namespace hullcook
