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

// Refuses before any work a --depfile, a --report or an --html page (each may be empty: not
// asked for) that cannot be written, a report not .json, a page not .html, or one naming another
// file written or read.
void check_side_outputs(const std::string& depfile, const std::string& report,
                        std::vector<std::filesystem::path> outputs,
                        const std::vector<std::filesystem::path>& inputs,
                        const std::string& html = {});

}  // namespace hullcook::cli
