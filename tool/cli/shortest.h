// Numbers as inspect prints them: the shortest decimal text that reads back as the same value.
#pragma once

#include <array>
#include <charconv>
#include <cstdlib>
#include <string>

namespace hullcook::cli {

// The shortest text that parses back to value ("0.6" for 0.6f, not "0.60000002384185791").
template <typename Number>
std::string shortest_text(Number value) {
  std::array<char, 32> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::string(text.data(), result.ptr);
}

// A float as the double of its shortest decimal form, so that 0.6f prints as 0.6 and parsing
// the printed text gives the float back.
inline double shortest_double(float value) {
  return std::strtod(shortest_text(value).c_str(), nullptr);
}

}  // namespace hullcook::cli
