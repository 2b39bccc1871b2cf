#include "child_process.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace hullcook::bench {
namespace {

struct Pipe {
  int read = -1, write = -1;
  Pipe() {
    int ends[2];
    if (::pipe(ends) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    read = ends[0], write = ends[1];
  }
};

// Starts argv with its stdin and stdout on the given pipe ends (-1: inherited).
pid_t start(const std::vector<std::string>& argv, int child_stdin, int child_stdout,
            const std::vector<int>& close_in_child) {
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("cannot start " + argv.at(0) + ": " + std::strerror(errno));
  if (pid == 0) {
    if (child_stdin >= 0) ::dup2(child_stdin, 0);
    if (child_stdout >= 0) ::dup2(child_stdout, 1);
    for (int fd : close_in_child) ::close(fd);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

LineChild::LineChild(const std::vector<std::string>& argv) : name_(argv.at(0)) {
  Pipe requests, answers;
  pid_ = start(argv, requests.read, answers.write,
               {requests.read, requests.write, answers.read, answers.write});
  ::close(requests.read);
  ::close(answers.write);
  to_child_ = ::fdopen(requests.write, "w");
  from_child_ = ::fdopen(answers.read, "r");
}

LineChild::~LineChild() {
  if (to_child_) std::fclose(to_child_);
  if (from_child_) std::fclose(from_child_);
  if (pid_ > 0) wait_for(pid_);
}

std::string LineChild::ask(const std::string& request) {
  if (std::fputs((request + "\n").c_str(), to_child_) < 0 || std::fflush(to_child_) != 0)
    throw std::runtime_error(name_ + " does not read its requests");
  std::string line;
  for (int c; (c = std::fgetc(from_child_)) != EOF && c != '\n';) line += static_cast<char>(c);
  if (line.empty()) throw std::runtime_error(name_ + " stopped answering");
  return line;
}

std::string run_for_output(const std::vector<std::string>& argv) {
  Pipe output;
  const pid_t pid = start(argv, -1, output.write, {output.read, output.write});
  ::close(output.write);
  std::string text;
  char buffer[4096];
  for (ssize_t got; (got = ::read(output.read, buffer, sizeof buffer)) != 0;) {
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) break;
    text.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(output.read);
  const int status = wait_for(pid);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(argv.at(0) + " failed (status " + std::to_string(status) + ")");
  return text;
}

}  // namespace hullcook::bench
