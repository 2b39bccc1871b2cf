#include "hullcook/core/poly_io.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace hullcook {
namespace {

class Tokenizer {
 public:
  Tokenizer(std::string_view text, std::string_view source) : text_(text), source_(source) {}

  // The next token, or an empty view at the end of the text.
  std::string_view next() {
    skip_space();
    const std::size_t start = position_;
    while (position_ < text_.size() && !is_space(text_[position_]) && text_[position_] != '#') {
      ++position_;
    }
    token_line_ = line_;
    return text_.substr(start, position_ - start);
  }

  bool at_end() {
    skip_space();
    return position_ >= text_.size();
  }

  [[noreturn]] void fail(const std::string& problem) const {
    std::string message = std::string(source_) + ":" + std::to_string(token_line_) + ": " + problem;
    // The format reads numbers whatever the lines: one missing shifts every later one, and the
    // error surfaces far from it.
    if (split_point_line_ != 0 && split_point_line_ < token_line_) {
      message += " (line " + std::to_string(split_point_line_) +
                 " holds a vertex's x without its y: is a number missing there?)";
    }
    throw InputError(message);
  }

  int token_line() const { return token_line_; }
  // A vertex read: where its x lay, and whether its y lay on another line. The first split one
  // after a whole one is noted (a file that splits every vertex does so on purpose).
  void note_point(int x_line, bool split) {
    if (!split) {
      whole_point_seen_ = true;
    } else if (whole_point_seen_ && split_point_line_ == 0) {
      split_point_line_ = x_line;
    }
  }

  // what() names the value expected, for the error message only: built when a token is wrong,
  // since building it for every number was most of a file's parsing time.
  template <class What>
  long long integer(const What& what) {
    const std::string_view token = next();
    if (token.empty()) fail("file ends where " + what() + " was expected");
    long long value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
      fail("expected " + what() + ", found '" + std::string(token) + "'");
    }
    return value;
  }

  template <class What>
  double real(const What& what) {
    std::string_view token = next();
    if (token.empty()) fail("file ends where " + what() + " was expected");
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range) {
      value = std::numeric_limits<double>::infinity();
    } else if (error != std::errc() || end != digits.data() + digits.size()) {
      fail("expected " + what() + ", found '" + std::string(token) + "'");
    }
    return value;
  }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f' || c == ',';
  }

  void skip_space() {
    while (position_ < text_.size()) {
      const char c = text_[position_];
      if (c == '\n') {
        ++line_;
        ++position_;
      } else if (is_space(c)) {
        ++position_;
      } else if (c == '#') {
        while (position_ < text_.size() && text_[position_] != '\n') ++position_;
      } else {
        break;
      }
    }
  }

  std::string_view text_;
  std::string_view source_;
  std::size_t position_ = 0;
  int line_ = 1;
  int token_line_ = 1;
  int split_point_line_ = 0;
  bool whole_point_seen_ = false;
};

}  // namespace

std::vector<Region> parse_poly(std::string_view text, std::string_view source) {
  // Editors on Windows start a UTF-8 file with a byte order mark.
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) {
    text.remove_prefix(kByteOrderMark.size());
  }
  Tokenizer tokens(text, source);
  if (tokens.at_end()) {
    throw InputError(std::string(source) + ": empty file: no polygon");
  }
  const long long chains = tokens.integer([] { return std::string("the number of chains"); });
  if (chains <= 0) tokens.fail("the number of chains must be positive");
  if (chains > 10'000'000) tokens.fail("implausible number of chains");
  std::vector<Region> regions;
  for (long long chain = 1; chain <= chains; ++chain) {
    const std::string chain_name = "chain " + std::to_string(chain);
    const long long count = tokens.integer([&] { return "the vertex count of " + chain_name; });
    if (count < 0) tokens.fail("negative vertex count for " + chain_name);
    if (count > 100'000'000) tokens.fail("implausible vertex count for " + chain_name);
    const std::string_view tag = tokens.next();
    if (tag != "out" && tag != "in") {
      tokens.fail(chain_name + ": expected 'out' or 'in' after the vertex count, found '" +
                  std::string(tag) + "'");
    }
    Ring points;
    points.reserve(static_cast<std::size_t>(count));
    for (long long i = 0; i < count; ++i) {
      const double x =
          tokens.real([&] { return "x of vertex " + std::to_string(i + 1) + " of " + chain_name; });
      const int x_line = tokens.token_line();
      const double y =
          tokens.real([&] { return "y of vertex " + std::to_string(i + 1) + " of " + chain_name; });
      tokens.note_point(x_line, tokens.token_line() != x_line);
      points.push_back({x, y});
    }
    Ring ring;
    ring.reserve(points.size());
    std::vector<bool> used(points.size(), false);
    for (long long i = 0; i < count; ++i) {
      const long long index = tokens.integer(
          [&] { return "index " + std::to_string(i + 1) + " of the order of " + chain_name; });
      if (index < 1 || index > count) {
        tokens.fail(chain_name + ": order index " + std::to_string(index) + " is not in 1.." +
                    std::to_string(count) + " (do the counts match?)");
      }
      if (used[static_cast<std::size_t>(index - 1)]) {
        tokens.fail(chain_name + ": order index " + std::to_string(index) + " appears twice");
      }
      used[static_cast<std::size_t>(index - 1)] = true;
      ring.push_back(points[static_cast<std::size_t>(index - 1)]);
    }
    if (tag == "out") {
      regions.push_back(Region{std::move(ring), {}});
    } else {
      if (regions.empty()) tokens.fail(chain_name + " is a hole ('in') before any outer boundary");
      regions.back().holes.push_back(std::move(ring));
    }
  }
  if (!tokens.at_end()) {
    const std::string_view extra = tokens.next();
    tokens.fail("unexpected '" + std::string(extra) + "' after the last of " +
                std::to_string(chains) + " chains (does the chain count match?)");
  }
  return regions;
}

std::vector<Region> read_poly_file(const std::filesystem::path& path) {
  refuse_unless_regular_file(path);
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw InputError(path.string() + ": cannot read: " + std::strerror(errno));
  }
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad()) throw InputError(path.string() + ": cannot read");
  const std::string source = path.string();
  std::vector<Region> regions = parse_poly(contents.str(), source);
  refuse_tiny_rings(regions, source);
  return clean_and_validate(std::move(regions), source);
}

std::string format_poly(const std::vector<Region>& regions) {
  std::string out;
  std::size_t chains = 0;
  for (const Region& region : regions) chains += 1 + region.holes.size();
  out += std::to_string(chains) + "\n";
  char buffer[64];
  auto write_ring = [&](const Ring& ring, const char* tag) {
    out += std::to_string(ring.size()) + " " + tag + "\n";
    for (Vec2 p : ring) {
      std::snprintf(buffer, sizeof buffer, "%.17g %.17g\n", p.x, p.y);
      out += buffer;
    }
    for (std::size_t i = 0; i < ring.size(); ++i) {
      out += std::to_string(i + 1);
      out += i + 1 < ring.size() ? " " : "\n";
    }
  };
  for (const Region& region : regions) {
    write_ring(region.outer, "out");
    for (const Ring& hole : region.holes) write_ring(hole, "in");
  }
  return out;
}

}  // namespace hullcook
