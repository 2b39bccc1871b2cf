#include "hullcook/cook/cook.h"
#include "hullcook/core/error.h"

#include <cstdio>
#include <cstdlib>

namespace hullcook {

std::array<std::uint8_t, 3> parse_color(const std::string& text) {
  std::string hex = text;
  if (!hex.empty() && hex[0] == '#') hex.erase(0, 1);
  const bool ok =
      hex.size() == 6 && hex.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos;
  if (!ok) throw UsageError("'" + text + "' is not a colour like #ff00ff");
  const unsigned long rgb = std::strtoul(hex.c_str(), nullptr, 16);
  return {static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8),
          static_cast<std::uint8_t>(rgb)};
}

std::string color_text(const std::array<std::uint8_t, 3>& rgb) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return text;
}

}  // namespace hullcook
