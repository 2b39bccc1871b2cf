// Errors the cooker reports to its user, each mapped to one of the documented exit codes.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace hullcook {

// The exit codes of the `hullcook` command, documented in the README.
enum class ExitCode : int { ok = 0, usage = 1, bad_input = 2, output_failed = 3, internal = 4 };

struct Error : std::runtime_error {
  Error(ExitCode exit_code, const std::string& message)
      : std::runtime_error(message), code(exit_code) {}
  ExitCode code;
};

// Something the user gave us is wrong. The message names the file and the problem.
struct InputError : Error {
  explicit InputError(const std::string& message) : Error(ExitCode::bad_input, message) {}
};

// An output could not be written. The message names the file and the reason.
struct OutputError : Error {
  explicit OutputError(const std::string& message) : Error(ExitCode::output_failed, message) {}
};

// The command line itself is wrong.
struct UsageError : Error {
  explicit UsageError(const std::string& message) : Error(ExitCode::usage, message) {}
};

// The cooker broke its own output contract (issue 16): a bug, caught before anything is written.
// The message names the asset and the first violation.
struct ContractError : Error {
  explicit ContractError(const std::string& message) : Error(ExitCode::internal, message) {}
};

// Throws InputError naming path when it exists but is neither a regular file (or a link to one)
// nor a directory: inputs are read whole, and a pipe or a device may block until written or never
// end. A path that is missing or a directory is left to the caller's own message.
void refuse_unless_regular_file(const std::filesystem::path& path);

}  // namespace hullcook
