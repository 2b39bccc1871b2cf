// Runs the hullcook executable in tests and captures what it printed.
#pragma once

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <string>

namespace hullcook::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr, interleaved
};

// Runs `hullcook <arguments>` through the shell; arguments are passed verbatim.
inline CommandResult run_hullcook(const std::string& arguments) {
  CommandResult result;
  std::string command = std::string(HULLCOOK_EXE) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace hullcook::test
