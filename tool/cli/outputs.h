// The outputs of the commands that write (cook, link): -o and --json, checked before any work.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hullcook::cli {

// The output paths given with -o and --json, refused before any work (UsageError or
// OutputError) when there is none, --json is not .json, one cannot be written (an unknown
// extension, a directory, a missing directory) or both name the same file: a long cook must not
// end in a usage error.
std::vector<std::filesystem::path> checked_outputs(const std::string& command,
                                                   const std::string& output,
                                                   const std::string& json);

// Refuses before any work a --depfile that cannot be written, or that names an output or an input.
void check_depfile(const std::filesystem::path& depfile,
                   const std::vector<std::filesystem::path>& outputs,
                   const std::vector<std::filesystem::path>& inputs);

}  // namespace hullcook::cli
