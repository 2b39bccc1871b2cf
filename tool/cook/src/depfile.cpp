#include "hullcook/cook/depfile.h"

#include "hullcook/core/error.h"

#include <set>

namespace hullcook {
namespace {

std::string escaped(const std::filesystem::path& path) {
  std::string text;
  for (char c : path.string()) {
    if (c == '\n' || c == '\r') {
      throw UsageError(path.string() + ": a depfile cannot name a path with a line break");
    }
    if (c == ' ' || c == '#') text += '\\';
    if (c == '$') text += '$';
    text += c;
  }
  return text;
}

}  // namespace

std::string depfile_text(const std::vector<std::filesystem::path>& targets,
                         const std::vector<std::filesystem::path>& dependencies) {
  std::string text;
  for (std::size_t i = 0; i < targets.size(); ++i) text += (i ? " " : "") + escaped(targets[i]);
  text += ':';
  for (const std::filesystem::path& dependency : dependencies) {
    text += " \\\n  " + escaped(dependency);
  }
  text += '\n';
  return text;
}

std::vector<std::filesystem::path> cook_dependencies(
    const CookResult& result, const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::filesystem::path> dependencies;
  std::set<std::filesystem::path> seen;
  auto add = [&](const std::filesystem::path& path) {
    if (seen.insert(path).second) dependencies.push_back(path);
  };
  for (const std::filesystem::path& file : files_read(result)) add(file);
  for (const std::filesystem::path& input : inputs) {
    std::error_code error;
    if (!std::filesystem::is_directory(input, error)) continue;
    add(input);
    for (auto it = std::filesystem::recursive_directory_iterator(input, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
      std::error_code entry_error;
      if (it->is_directory(entry_error)) add(it->path());
    }
  }
  return dependencies;
}

}  // namespace hullcook
