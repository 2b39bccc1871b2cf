// A progress bar for long commands on a terminal: one line redrawn in place on stdout, as
// "hullcook: [=========>          ] 412/1000 assets", and gone once the command ends (its table
// or error is printed on a clean line).
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>

namespace hullcook::cli {

class ProgressBar {
 public:
  // Draws only when enabled: callers pass whether stdout is a terminal and the command is not
  // quiet, so that pipes, logs and CI see no bar.
  explicit ProgressBar(bool enabled);
  ~ProgressBar();  // clears the line
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // One more of count items done; safe to call from several threads. Redraws at most every
  // 50 ms, and when the last item is done.
  void advance(std::size_t count);

  // Clears the bar's line (if drawn) and draws no more.
  void finish();

  // Whether stdout is a terminal.
  static bool stdout_is_terminal();

 private:
  void draw(std::size_t count);

  bool enabled_;
  bool drawn_ = false;
  std::size_t done_ = 0;
  std::chrono::steady_clock::time_point last_draw_{};
  std::mutex mutex_;
};

}  // namespace hullcook::cli
