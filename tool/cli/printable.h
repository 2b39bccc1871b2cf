// What the commands print of text that comes from files (asset names, sources): bytes that a
// terminal takes as controls are shown as \xNN, so that a bundle, glTF or fragment whose name
// holds an escape sequence cannot drive the terminal that inspects it; UTF-8 is left as it is.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace hullcook::cli {

inline std::string printable(std::string_view text) {
  std::string shown;
  shown.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f || c == '\\') {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      shown += escaped;
    } else {
      shown += c;
    }
  }
  return shown;
}

}  // namespace hullcook::cli
