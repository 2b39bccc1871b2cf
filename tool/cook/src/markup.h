// Internal to hullcook_cook: text put into SVG and HTML (asset names come from file names, images
// go in data: URIs).
#pragma once

#include <cstdint>
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

// bytes in base64 (RFC 4648, padded), as data: URIs hold images.
inline std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(std::uint8_t(bytes[i])); };
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = byte(i) << 16;
    if (i + 1 < bytes.size()) chunk |= byte(i + 1) << 8;
    if (i + 2 < bytes.size()) chunk |= byte(i + 2);
    text += kAlphabet[(chunk >> 18) & 63];
    text += kAlphabet[(chunk >> 12) & 63];
    text += i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
    text += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
  }
  return text;
}

}  // namespace hullcook
