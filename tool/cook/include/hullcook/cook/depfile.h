// Depfiles in Make's syntax (which Ninja reads too), as `cc -MD` writes them, so that a build
// system re-runs a cook when a file it read changes, though its command line names only some.
#pragma once

#include "hullcook/cook/cook.h"

#include <filesystem>
#include <string>
#include <vector>

namespace hullcook {

// `target...: dependency...`, one path a line, paths as given, with spaces, '#' and '$'
// escaped. Throws UsageError for a path Make cannot express (one with a newline).
std::string depfile_text(const std::vector<std::filesystem::path>& targets,
                         const std::vector<std::filesystem::path>& dependencies);

// What a cook of inputs depends on: every file it read (files_read), and every directory it
// searched for images (one being added or removed changes the directory), each once.
std::vector<std::filesystem::path> cook_dependencies(
    const CookResult& result, const std::vector<std::filesystem::path>& inputs);

}  // namespace hullcook
