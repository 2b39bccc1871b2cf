// Reading the JSON that users write (sprite sheets, hullcook.json, NAME.hullcook.json,
// NAME.physics.json) strictly: an object that holds a key twice keeps only one of them, which
// lost a sheet's frame or a setting silently, so the readers refuse it; and nesting beyond any
// such file's is refused before it is parsed.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

// Far beyond any sheet's or settings file's nesting (TexturePacker and Aseprite nest 4 deep).
inline constexpr std::size_t kDeepestJsonNesting = 256;

// Whether text nests arrays and objects deeper than limit (brackets inside strings skipped).
// Parsed, an ordered_json copies a member's value whole, recursively, when its object grows (a
// pair with a const key has no non-throwing move): 90,000 levels overflowed the stack (stop 58).
inline bool nests_deeper_than(std::string_view text, std::size_t limit) {
  std::size_t depth = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return false;
}

// Parses text, or nothing (discarded) when it is not JSON; sets duplicate to the first key that
// an object holds twice (the parsed object keeps one of them).
template <typename Json>
Json parse_noting_duplicates(std::string_view text, std::optional<std::string>& duplicate) {
  std::vector<std::set<std::string>> keys;  // per object open: the keys read so far
  auto note = [&](int, nlohmann::detail::parse_event_t event, Json& parsed) {
    using Event = nlohmann::detail::parse_event_t;
    if (event == Event::object_start) {
      keys.emplace_back();
    } else if (event == Event::object_end) {
      if (!keys.empty()) keys.pop_back();
    } else if (event == Event::key && !keys.empty() &&
               !keys.back().insert(parsed.template get<std::string>()).second && !duplicate) {
      duplicate = parsed.template get<std::string>();
    }
    return true;
  };
  return Json::parse(text, note, false);
}

// Parses text as a JSON object strictly: refusal is set (and nothing parsed) when it nests deeper
// than kDeepestJsonNesting, or when it is an object holding a key twice; the caller refuses what
// is discarded or no object, as its file's kind says.
template <typename Json>
Json parse_strict(std::string_view text, std::string& refusal) {
  if (nests_deeper_than(text, kDeepestJsonNesting)) {
    refusal =
        "arrays and objects nested deeper than " + std::to_string(kDeepestJsonNesting) + " levels";
    return Json(nlohmann::detail::value_t::discarded);
  }
  std::optional<std::string> duplicate;
  Json json = parse_noting_duplicates<Json>(text, duplicate);
  if (duplicate && json.is_object()) {
    refusal = "the key '" + *duplicate + "' appears twice in one object";
  }
  if (json.is_discarded()) {
    // Where and why, as the parser says it ("parse error at line 3, column 5: ..."): "not a JSON
    // object" left a user to find a missing comma in a project file alone.
    try {
      const Json reparsed = Json::parse(text);  // throws: it was discarded above
      (void)reparsed;
    } catch (const nlohmann::json::exception& error) {
      std::string why = error.what();  // "[json.exception.parse_error.101] parse error at ..."
      const std::size_t tag_end = why.find("] ");
      if (why.rfind("[json.exception", 0) == 0 && tag_end != std::string::npos) {
        why.erase(0, tag_end + 2);
      }
      refusal = "not valid JSON: " + why;
    }
  }
  return json;
}

// The value of a whole number in JSON users write: an integer, or a number with a point whose
// value is whole (20.0, as some exporters write every number); nullopt for anything else, and
// for a magnitude beyond 2^62 (beyond every field's range: refused as out of range).
template <typename Json>
std::optional<long long> whole_number(const Json& value) {
  constexpr long long kLargest = 1ll << 62;
  if (value.is_number_unsigned()) {
    return static_cast<long long>(
        std::min<unsigned long long>(value.template get<unsigned long long>(), kLargest));
  }
  if (value.is_number_integer()) {
    return std::clamp<long long>(value.template get<long long>(), -kLargest, kLargest);
  }
  if (!value.is_number_float()) return std::nullopt;
  const double number = value.template get<double>();
  if (!std::isfinite(number) || std::trunc(number) != number) return std::nullopt;
  return static_cast<long long>(
      std::clamp(number, -static_cast<double>(kLargest), static_cast<double>(kLargest)));
}

}  // namespace hullcook
