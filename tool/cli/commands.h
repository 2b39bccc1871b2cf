// Subcommands register themselves here, one file each (cmd_<name>.cpp), so main stays thin.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace hullcook::cli {

// Set by a subcommand's callback; main runs it after parsing and maps exceptions to exit codes.
// Returns the process exit code (0 on success).
using CommandAction = std::function<int()>;
using AddCommand = void (*)(CLI::App& root, CommandAction& action);

// Usage, in a cmd_<name>.cpp file:  static const CommandRegistration registered{20, add_cook};
// `order` fixes the order of subcommands in --help.
struct CommandRegistration {
  CommandRegistration(int order, AddCommand add);
};

}  // namespace hullcook::cli
