// Other programs that a benchmark runs: a long-lived one it talks to a line at a time, or one
// run to the end whose output it reads.
#pragma once

#include <sys/types.h>

#include <cstdio>
#include <string>
#include <vector>

namespace hullcook::bench {

// A child process reading requests on its stdin and answering each with one line on its stdout
// (its stderr is ours). Throws std::runtime_error when it cannot be started or stops answering.
class LineChild {
 public:
  explicit LineChild(const std::vector<std::string>& argv);
  ~LineChild();  // closes its stdin and waits for it
  LineChild(const LineChild&) = delete;
  LineChild& operator=(const LineChild&) = delete;

  std::string ask(const std::string& request);

 private:
  pid_t pid_ = -1;
  std::FILE* to_child_ = nullptr;
  std::FILE* from_child_ = nullptr;
  std::string name_;
};

// Runs argv to its end and returns what it wrote on stdout; throws std::runtime_error naming it
// unless it exits with status 0.
std::string run_for_output(const std::vector<std::string>& argv);

}  // namespace hullcook::bench
