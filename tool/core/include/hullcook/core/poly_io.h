// The ACD authors' .poly format (samples/polygons/POLY_FORMAT.txt): reading, and writing for tests
// and tools.
#pragma once

#include "hullcook/core/polygon.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

// Parses .poly text: a chain count, then per chain "N out|in", N "x y" lines and a line of N
// 1-based indices giving the ring order. '#' starts a comment. Each "in" chain is a hole of the
// nearest preceding "out" chain. Throws InputError "source:line: problem" on malformed text.
// The result is not cleaned: pass it to clean_and_validate().
std::vector<Region> parse_poly(std::string_view text, std::string_view source);

// Reads, parses, cleans and validates a .poly file. Throws InputError naming the file.
std::vector<Region> read_poly_file(const std::filesystem::path& path);

// Writes regions as .poly text (coordinates round-trip exactly).
std::string format_poly(const std::vector<Region>& regions);

}  // namespace hullcook
