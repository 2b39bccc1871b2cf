// Writing outputs without ever leaving a partial file behind, and never over an input.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hullcook {

// Throws OutputError naming path if the directory it would be written in does not exist, or if
// the path holds what a rename must not replace (see check_replaceable).
void check_directory_of(const std::filesystem::path& path);

// Throws OutputError naming path when something that a rename must not replace is there: a
// directory, a device, a pipe or a socket (a regular file or a link is replaced; nothing, fine).
void check_replaceable(const std::filesystem::path& path);

// Writes bytes to a temporary file beside path, then renames it over path.
// Throws OutputError naming the file and the reason; on failure nothing is left behind.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// One file of an output: its bytes, or, for a file too large to hold in memory (a streamed
// bundle), a function that writes it into the open temporary file and throws OutputError when it
// cannot.
struct OutputFile {
  std::filesystem::path path;
  std::string bytes;
  std::function<void(std::FILE* out)> write = {};  // when set, written instead of bytes
};

// Writes several files as one output: every file is written to its temporary first, and the
// renames follow only once all are written, so a file that cannot be written leaves none of them
// (only a rename failing after earlier ones succeeded could leave those). Throws OutputError
// naming the file.
void write_files_atomically(const std::vector<OutputFile>& files);

// Removes the temporary files of the writes under way, from a signal handler (async-signal-safe:
// it only unlinks the names registered when each temporary was created). A process stopped by
// SIGINT or SIGTERM leaves none; one killed outright (SIGKILL) leaves its temporaries, which the
// next write of the same output removes once their process is gone (their names carry its pid).
void remove_pending_temporaries() noexcept;

// Throws UsageError naming both if output is an existing file among inputs (the same file by
// any path or link): a command never overwrites what it reads.
void check_not_an_input(const std::filesystem::path& output,
                        const std::vector<std::filesystem::path>& inputs);

// check_not_an_input against one input (output is known to exist; no error if input does not).
void check_not_the_input(const std::filesystem::path& output, const std::filesystem::path& input);

// check_not_the_input for many inputs, the output looked at once (a cook of 10,000 images checks
// every file it read).
class OutputGuard {
 public:
  explicit OutputGuard(const std::filesystem::path& output);
  // Whether the output exists: else no input can be it.
  bool output_exists() const { return exists_; }
  // Throws UsageError naming both if input is the output, by any path or link.
  void check(const std::filesystem::path& input) const;

 private:
  std::filesystem::path output_;
  bool exists_ = false;
  std::uint64_t device_ = 0, inode_ = 0;
};

}  // namespace hullcook
