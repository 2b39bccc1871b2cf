#include "hullcook/cook/depfile.h"

#include "hullcook/core/error.h"

#include <set>
#include <utility>

namespace hullcook {
namespace {

// Make and Ninja escape a space, '#' and '$' alike, and nothing else the same way: a ':' made
// Make read a second rule ("target pattern contains no '%'"), a tab split the name for Ninja
// (which then rebuilt every time), and a backslash before an escaped space or '#' (or the space
// after the name) read as an escaped backslash: two names, or a comment (stop 60). Those are
// refused, as a line break is.
std::string escaped(const std::filesystem::path& path) {
  const std::string name = path.string();
  for (const auto& [c, what] : {std::pair{'\n', "a line break"}, std::pair{'\r', "a line break"},
                                std::pair{':', "a ':'"}, std::pair{'\t', "a tab"}}) {
    if (name.find(c) != std::string::npos) {
      throw UsageError(name + ": a depfile cannot name a path with " + what);
    }
  }
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (name[i] == '\\' && (i + 1 == name.size() || name[i + 1] == ' ' || name[i + 1] == '#')) {
      throw UsageError(name +
                       ": a depfile cannot name a path with a backslash before a space, a '#' "
                       "or its end");
    }
  }
  std::string text;
  for (char c : name) {
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
