#include "progress.h"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace hullcook::cli {

namespace {
constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(50);
}  // namespace

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled) {}

ProgressBar::~ProgressBar() { finish(); }

bool ProgressBar::stdout_is_terminal() { return ::isatty(STDOUT_FILENO) == 1; }

void ProgressBar::advance(std::size_t count) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!enabled_) return;
  ++done_;
  const auto now = std::chrono::steady_clock::now();
  if (done_ < count && drawn_ && now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  draw(count);
}

void ProgressBar::draw(std::size_t count) {
  const std::size_t filled = count ? done_ * kBarWidth / count : kBarWidth;
  std::string bar(kBarWidth, ' ');
  for (std::size_t i = 0; i < filled && i < bar.size(); ++i) bar[i] = '=';
  if (filled < bar.size()) bar[filled] = '>';
  // \r and the erase-line sequence: the bar replaces itself in place.
  std::printf("\r\033[2Khullcook: [%s] %zu/%zu assets", bar.c_str(), done_, count);
  std::fflush(stdout);
  drawn_ = true;
}

void ProgressBar::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (enabled_ && drawn_) {
    std::printf("\r\033[2K");
    std::fflush(stdout);
  }
  enabled_ = false;
}

}  // namespace hullcook::cli
