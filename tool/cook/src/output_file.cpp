#include "hullcook/cook/output_file.h"

#include "hullcook/core/error.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <system_error>

namespace hullcook {
namespace {

// The temporaries being written or awaiting their rename, for remove_pending_temporaries: a slot
// holds a name (malloc'ed, so that a signal handler reads a plain C string) or null.
constexpr std::size_t kPendingSlots = 64;
std::array<std::atomic<char*>, kPendingSlots> pending_temporaries{};

// A registered temporary name; unregistered (and freed) when it goes out of scope.
class PendingTemporary {
 public:
  explicit PendingTemporary(const std::filesystem::path& path) {
    name_ = strdup(path.c_str());
    for (std::atomic<char*>& slot : pending_temporaries) {
      char* empty = nullptr;
      if (name_ && slot.compare_exchange_strong(empty, name_)) {
        slot_ = &slot;
        break;
      }
    }
  }
  ~PendingTemporary() {
    if (slot_) slot_->store(nullptr);
    std::free(name_);
  }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

 private:
  char* name_ = nullptr;
  std::atomic<char*>* slot_ = nullptr;
};

// The prefix of path's temporaries: ".NAME.tmp", NAME cut to the bytes that leave room for the
// PID and the random number within a file name's 255 bytes: an output named with 235 to 255
// bytes, which the file system takes, could not be written (stop 60).
std::string temporary_prefix(const std::filesystem::path& path) {
  constexpr std::size_t kNameMax = 255, kAround = 1 + 4 + 10 + 1 + 10;  // ".", ".tmp", PID-RANDOM
  const std::string name = path.filename().string();
  return "." + name.substr(0, kNameMax - kAround) + ".tmp";
}

// Removes the temporaries of path that a killed process left: their names are
// ".NAME.tmpPID-RANDOM", and PID no longer runs. Those of a live process (another cook writing
// the same output) are kept.
void remove_stale_temporaries(const std::filesystem::path& directory,
                              const std::filesystem::path& path) {
  const std::string prefix = temporary_prefix(path);
  std::error_code error;
  for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const char* digits = name.c_str() + prefix.size();
    char* stop = nullptr;
    const long pid = std::strtol(digits, &stop, 10);
    if (stop == digits || *stop != '-' || pid <= 0) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH) {
      std::filesystem::remove(it->path(), error);
      error.clear();
    }
  }
}

// Writes file to a new temporary file beside its path (same directory, so that the rename is
// atomic) and returns its name. Throws OutputError naming the path; on failure nothing is left.
std::filesystem::path write_temporary(const OutputFile& output,
                                      std::vector<std::unique_ptr<PendingTemporary>>& pending) {
  const std::filesystem::path& path = output.path;
  check_directory_of(path);
  std::filesystem::path directory = path.parent_path();
  if (directory.empty()) directory = ".";
  remove_stale_temporaries(directory, path);
  std::random_device entropy;
  std::filesystem::path temporary =
      directory /
      (temporary_prefix(path) + std::to_string(::getpid()) + "-" + std::to_string(entropy()));
  pending.push_back(std::make_unique<PendingTemporary>(temporary));
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) {
    throw OutputError(path.string() + ": cannot write: " + std::strerror(errno));
  }
  std::string problem;
  if (output.write) {
    try {
      output.write(file);
      if (std::ferror(file)) problem = std::strerror(errno);
    } catch (const OutputError& e) {
      problem = e.what();
    } catch (...) {
      std::fclose(file);
      std::remove(temporary.c_str());
      throw;
    }
  } else if (std::fwrite(output.bytes.data(), 1, output.bytes.size(), file) !=
             output.bytes.size()) {
    problem = std::strerror(errno);
  }
  const int close_errno = std::fclose(file) == 0 ? 0 : errno;
  if (problem.empty() && close_errno != 0) problem = std::strerror(close_errno);
  if (!problem.empty()) {
    std::remove(temporary.c_str());
    throw OutputError(path.string() + ": cannot write: " + problem);
  }
  return temporary;
}

}  // namespace

void remove_pending_temporaries() noexcept {
  for (std::atomic<char*>& slot : pending_temporaries) {
    if (const char* name = slot.load()) ::unlink(name);
  }
}

void check_directory_of(const std::filesystem::path& path) {
  std::filesystem::path directory = path.parent_path();
  if (directory.empty()) directory = ".";
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error)) {
    throw OutputError(path.string() + ": cannot write: directory " + directory.string() +
                      " does not exist");
  }
  check_replaceable(path);
}

void check_replaceable(const std::filesystem::path& path) {
  // The rename replaces what is there: a device or a pipe (--depfile /dev/null, run as root,
  // turned /dev/null into a file: stop 58) is refused. A link is replaced, its target untouched.
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) return;
  if (S_ISREG(status.st_mode) || S_ISLNK(status.st_mode)) return;
  throw OutputError(path.string() + ": cannot write: " +
                    (S_ISDIR(status.st_mode) ? "it is a directory"
                                             : "it is not a regular file (a device or a pipe): "
                                               "outputs are written to a new file and renamed "
                                               "over the old one"));
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  write_files_atomically({{path, std::string(bytes)}});
}

void write_files_atomically(const std::vector<OutputFile>& files) {
  std::vector<std::filesystem::path> temporaries;
  std::vector<std::unique_ptr<PendingTemporary>> pending;  // until renamed or removed
  auto remove_temporaries = [&](std::size_t from) {
    for (std::size_t k = from; k < temporaries.size(); ++k) std::remove(temporaries[k].c_str());
  };
  try {
    for (const OutputFile& file : files) temporaries.push_back(write_temporary(file, pending));
  } catch (...) {
    remove_temporaries(0);
    throw;
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::error_code error;
    try {
      check_replaceable(files[k].path);
    } catch (...) {
      remove_temporaries(k);
      throw;
    }
    std::filesystem::rename(temporaries[k], files[k].path, error);
    if (error) {
      remove_temporaries(k);
      throw OutputError(files[k].path.string() + ": cannot write: " + error.message());
    }
  }
}

// As std::filesystem::equivalent: the same device and inode, links followed.
OutputGuard::OutputGuard(const std::filesystem::path& output) : output_(output) {
  struct stat status {};
  exists_ = ::stat(output.c_str(), &status) == 0;
  device_ = static_cast<std::uint64_t>(status.st_dev);
  inode_ = static_cast<std::uint64_t>(status.st_ino);
}

void OutputGuard::check(const std::filesystem::path& input) const {
  if (!exists_) return;
  struct stat status {};
  if (::stat(input.c_str(), &status) != 0) return;
  if (static_cast<std::uint64_t>(status.st_dev) == device_ &&
      static_cast<std::uint64_t>(status.st_ino) == inode_) {
    throw UsageError(output_.string() + ": this output would replace an input (" + input.string() +
                     "); write it elsewhere");
  }
}

void check_not_the_input(const std::filesystem::path& output, const std::filesystem::path& input) {
  OutputGuard(output).check(input);
}

void check_not_an_input(const std::filesystem::path& output,
                        const std::vector<std::filesystem::path>& inputs) {
  const OutputGuard guard(output);
  for (const std::filesystem::path& input : inputs) guard.check(input);
}

}  // namespace hullcook
