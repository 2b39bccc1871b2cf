// Subcommands register themselves here, one file each (cmd_<name>.cpp), so main stays thin.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace hullcook::cli {

// Set by a subcommand's callback; main runs it after parsing and maps exceptions to exit codes.
// Returns the process exit code (0 on success).
using CommandAction = std::function<int()>;
using AddCommand = void (*)(CLI::App& root, CommandAction& action);

// Usage, in a cmd_<name>.cpp file:
//   static const CommandRegistration registered{20, "cook", add_cook};
// `order` fixes the order of subcommands in --help; `name` is the subcommand add() adds, so that
// a command line naming it sets up only its options (the cook's alone are about 1 M
// instructions, a quarter of a millisecond of every other command's start).
struct CommandRegistration {
  CommandRegistration(int order, const char* name, AddCommand add);
};

}  // namespace hullcook::cli
