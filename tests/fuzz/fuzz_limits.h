// What the fuzz targets and their seed maker share: the caps that keep every input fast (seeds
// beyond them would be refused).
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hullcook::fuzz {

// Larger polygons are the business of the benchmarks and scripts/stress: here every input must
// run in milliseconds so that the fuzzer tries many shapes.
inline constexpr std::size_t kMaxPolyVertices = 64;

// Larger images are refused before decoding (the header's size against max_pixels), so every
// input decodes and traces in milliseconds; the hostile-image tests cover big ones.
inline constexpr std::uint64_t kMaxImagePixels = 128 * 128;

inline std::size_t vertex_count(const std::vector<Region>& regions) {
  std::size_t count = 0;
  for (const Region& region : regions) {
    count += region.outer.size();
    for (const Ring& hole : region.holes) count += hole.size();
  }
  return count;
}

}  // namespace hullcook::fuzz
