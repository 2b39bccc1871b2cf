// hullcook: the command line. Parsing and exit codes only; the work is in hullcook::cook.
#include "commands.h"

#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <exception>
#include <iostream>
#include <new>
#include <string_view>
#include <utility>
#include <vector>

namespace hullcook::cli {
namespace {

struct RegisteredCommand {
  int order;
  const char* name;
  AddCommand add;
};

std::vector<RegisteredCommand>& registered_commands() {
  static std::vector<RegisteredCommand> commands;
  return commands;
}

// SIGINT (Ctrl-C), SIGTERM and SIGHUP stop a command at once, leaving no temporary file: the
// outputs are either the old files or the new ones. Exit 128 + the signal's number (130 for
// SIGINT), as a shell reports it.
extern "C" void stop_on_signal(int signal_number) {
  remove_pending_temporaries();
  static const char message[] = "hullcook: interrupted\n";
  [[maybe_unused]] const ssize_t written = ::write(2, message, sizeof message - 1);
  ::_exit(128 + signal_number);
}

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = stop_on_signal;
  sigemptyset(&action.sa_mask);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal_number, &action, nullptr);
}

}  // namespace

CommandRegistration::CommandRegistration(int order, const char* name, AddCommand add) {
  registered_commands().push_back({order, name, add});
}

}  // namespace hullcook::cli

int main(int argc, char** argv) {
  using namespace hullcook;
  // First, so that a Ctrl-C during start-up or parsing also exits 130 as the shell expects.
  cli::install_signal_handlers();
  CLI::App app{
      "hullcook " HULLCOOK_VERSION
      ": traces sprite silhouettes, splits them into approximately convex pieces (Lien-Amato ACD)\n"
      "and writes their convex hulls for 2D physics engines.\n\n"
      "Exit codes: 0 success, 1 usage error, 2 bad input, 3 output could not be written,\n"
      "4 internal error (such as an output that breaks its own contract; nothing is written).",
      "hullcook"};
  app.set_version_flag("--version", "hullcook " HULLCOOK_VERSION);
  app.require_subcommand(0, 1);

  cli::CommandAction action;
  auto commands = cli::registered_commands();
  std::stable_sort(commands.begin(), commands.end(),
                   [](const auto& a, const auto& b) { return a.order < b.order; });
  // The root takes no option but --help and --version, so a first argument naming a subcommand
  // is that subcommand: only it is set up. Anything else (help, a typo) sees them all.
  const auto named = std::find_if(commands.begin(), commands.end(), [&](const auto& command) {
    return argc > 1 && std::string_view(argv[1]) == command.name;
  });
  if (named != commands.end()) {
    named->add(app, action);
  } else {
    for (const auto& command : commands) command.add(app, action);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return static_cast<int>(ExitCode::usage);
  }
  if (!action) {
    std::cout << app.help();
    return app.get_subcommands().empty() && argc > 1 ? static_cast<int>(ExitCode::usage) : 0;
  }
  try {
    return action();
  } catch (const Error& e) {
    std::cerr << "hullcook: error: " << e.what() << "\n";
    return static_cast<int>(e.code);
  } catch (const std::bad_alloc&) {
    std::cerr << "hullcook: error: out of memory\n";
    return static_cast<int>(ExitCode::internal);
  } catch (const std::exception& e) {
    std::cerr << "hullcook: internal error: " << e.what() << "\n";
    return static_cast<int>(ExitCode::internal);
  }
}
