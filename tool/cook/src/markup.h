// Internal to hullcook_cook: text put into SVG and HTML (asset names come from file names).
#pragma once

#include <string>
#include <string_view>

namespace hullcook {

// text with the characters markup gives a meaning to (<, >, &, both quotes) as entities: safe in
// element content and in quoted attribute values alike.
inline std::string markup_escaped(std::string_view text) {
  std::string result;
  result.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '<':
        result += "&lt;";
        break;
      case '>':
        result += "&gt;";
        break;
      case '&':
        result += "&amp;";
        break;
      case '"':
        result += "&quot;";
        break;
      case '\'':
        result += "&#39;";
        break;
      default:
        result += c;
    }
  }
  return result;
}

}  // namespace hullcook
