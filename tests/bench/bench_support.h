// Text, statistics and docs/benchmarks.md sections shared by the benchmarks' reports.
#pragma once

#include <time.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace hullcook::bench {

inline std::string tau_label(double tau) {
  std::ostringstream out;
  out << tau;
  return out.str();
}

inline std::string fixed(double value, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

// Milliseconds with three significant digits.
inline std::string ms_text(std::optional<double> ms) {
  if (!ms) return "—";
  double value = *ms;
  int digits = value >= 100 ? 0 : value >= 10 ? 1 : value >= 1 ? 2 : value >= 0.1 ? 3 : 4;
  return fixed(value, digits);
}

inline std::string ratio_text(double ratio) {
  return fixed(ratio, ratio >= 100 ? 0 : ratio >= 10 ? 1 : 2) + "×";
}

inline std::string percent_text(double fraction) { return tau_label(fraction * 100) + "%"; }

inline std::string upper(const char* text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// The middle value (the mean of the two middle ones for an even count); values must not be empty.
inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// [ms] CPU time of the calling thread: what one single-threaded decomposition costs, whatever
// else the machine runs (it still slows us through shared caches, hence the load average).
inline double thread_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

// Replaces the text of page between "<!-- NAME: generated from here -->" (and its line end) and
// "<!-- NAME: generated up to here -->" with generated; false, the page untouched, when the
// markers are missing.
inline bool replace_generated_section(const std::filesystem::path& page, const std::string& name,
                                      const std::string& generated) {
  std::string text;
  if (std::ifstream in(page, std::ios::binary); in) {
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string begin = "<!-- " + name + ": generated from here -->\n";
  const std::string end = "<!-- " + name + ": generated up to here -->";
  const std::size_t from = text.find(begin), to = text.find(end);
  if (from == std::string::npos || to == std::string::npos || to < from) return false;
  text.replace(from + begin.size(), to - from - begin.size(), generated);
  std::ofstream(page, std::ios::binary) << text;
  return true;
}

}  // namespace hullcook::bench
