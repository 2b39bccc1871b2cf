#include "utf8_names.h"

#include "hullcook/core/error.h"

#include <map>

namespace hullcook {
namespace {

// The length of the valid UTF-8 sequence starting at text[i] (shortest form, no surrogates, at
// most U+10FFFF), or 0.
std::size_t utf8_sequence_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

// name with each byte that valid_utf8 would replace shown as \xNN, for a message.
std::string shown(const std::string& name) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string text;
  for (std::size_t i = 0; i < name.size();) {
    const std::size_t length = utf8_sequence_length(name, i);
    if (length == 0) {
      const auto byte = static_cast<unsigned char>(name[i++]);
      text += {'\\', 'x', kHex[byte >> 4], kHex[byte & 15]};
    } else {
      text.append(name, i, length);
      i += length;
    }
  }
  return text;
}

}  // namespace

std::string valid_utf8(const std::string& text) {
  std::string result;
  result.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) {
      result += "\xEF\xBF\xBD";  // U+FFFD
      ++i;
    } else {
      result.append(text, i, length);
      i += length;
    }
  }
  return result;
}

void refuse_names_alike_in_utf8(const std::vector<CookedAsset>& assets, std::string_view format) {
  std::map<std::string, const std::string*> written;  // valid_utf8 text -> the name
  for (const CookedAsset& asset : assets) {
    const auto [it, added] = written.emplace(valid_utf8(asset.name), &asset.name);
    if (!added && *it->second != asset.name) {
      throw OutputError(std::string(format) + ": assets '" + shown(*it->second) + "' and '" +
                        shown(asset.name) + "' would both be named '" + it->first +
                        "' (names there are UTF-8 text; a byte that is not becomes U+FFFD): rename "
                        "one of them, or write a bundle (.hcb)");
    }
  }
}

}  // namespace hullcook
