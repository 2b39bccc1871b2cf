// Helpers for the tracing tests: an even-odd rasteriser of traced regions, ring checks, and a
// hand-written PNG encoder for the forms OpenCV cannot write (grey + alpha, palette + tRNS).
#pragma once

#include "hullcook/core/geometry.h"
#include "hullcook/core/polygon.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hullcook::test {

inline std::filesystem::path sprites_dir() {
  return std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples" / "sprites";
}

inline std::vector<std::filesystem::path> all_sprites() {
  std::vector<std::filesystem::path> sprites;
  for (const auto& entry : std::filesystem::directory_iterator(sprites_dir())) {
    if (entry.path().extension() == ".png") sprites.push_back(entry.path());
  }
  std::sort(sprites.begin(), sprites.end());
  return sprites;
}

// A fresh directory for one test's files.
inline std::filesystem::path scratch_dir(const std::string& name) {
  std::filesystem::path dir = std::filesystem::path(HULLCOOK_BINARY_DIR) / "test-scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

inline std::vector<const Ring*> all_rings(const std::vector<Region>& regions) {
  std::vector<const Ring*> rings;
  for (const Region& region : regions) {
    rings.push_back(&region.outer);
    for (const Ring& hole : region.holes) rings.push_back(&hole);
  }
  return rings;
}

// Even-odd fill of every ring, sampled at pixel centres: 1 inside, 0 outside, row-major.
inline std::vector<std::uint8_t> rasterize(const std::vector<Region>& regions, int width,
                                           int height) {
  std::vector<std::uint8_t> image(static_cast<std::size_t>(width) * height, 0);
  std::vector<std::vector<double>> crossings(height);
  for (const Ring* ring : all_rings(regions)) {
    for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
      Vec2 a = (*ring)[i], b = (*ring)[(i + 1) % n];
      if (a.y > b.y) std::swap(a, b);
      // Rows whose centre y + 0.5 lies in [a.y, b.y).
      int first = std::max(0, static_cast<int>(std::ceil(a.y - 0.5)));
      int last = std::min(height - 1, static_cast<int>(std::ceil(b.y - 0.5)) - 1);
      for (int y = first; y <= last; ++y) {
        double cy = y + 0.5;
        crossings[y].push_back(a.x + (b.x - a.x) * (cy - a.y) / (b.y - a.y));
      }
    }
  }
  for (int y = 0; y < height; ++y) {
    std::vector<double>& xs = crossings[y];
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      int from = std::max(0, static_cast<int>(std::ceil(xs[k] - 0.5)));
      int to = std::min(width, static_cast<int>(std::ceil(xs[k + 1] - 0.5)));
      for (int x = from; x < to; ++x) image[static_cast<std::size_t>(y) * width + x] = 1;
    }
  }
  return image;
}

inline double ring_area(const Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) twice += cross(ring[i], ring[(i + 1) % n]);
  return twice / 2;
}

inline double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  Vec2 ab = b - a;
  double length2 = glm::dot(ab, ab);
  double t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

// Closed segments share at least one point (or come within 1e-9 px).
inline bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  auto side = [](Vec2 p, Vec2 q, Vec2 r) { return cross(q - p, r - p); };
  double d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  const double touch = 1e-9;
  return point_segment_distance(a, c, d) < touch || point_segment_distance(b, c, d) < touch ||
         point_segment_distance(c, a, b) < touch || point_segment_distance(d, a, b) < touch;
}

inline bool point_in_ring(Vec2 p, const Ring& ring) {
  bool inside = false;
  for (std::size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
    const Vec2 &a = ring[i], &b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (b.x - a.x) * (p.y - a.y) / (b.y - a.y)) {
      inside = !inside;
    }
  }
  return inside;
}

// Distance from p to the nearest edge of any ring.
inline double distance_to_rings(Vec2 p, const std::vector<const Ring*>& rings) {
  double best = 1e300;
  for (const Ring* ring : rings) {
    for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
      best = std::min(best, point_segment_distance(p, (*ring)[i], (*ring)[(i + 1) % n]));
    }
  }
  return best;
}

// ---- A minimal PNG encoder: stored (uncompressed) deflate blocks, filter 0 on every row. ----

inline std::uint32_t png_crc(const std::string& data) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char c : data) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
  }
  return ~crc;
}

inline std::string big_endian(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}

inline std::string png_chunk(const std::string& type, const std::string& data) {
  return big_endian(static_cast<std::uint32_t>(data.size())) + type + data +
         big_endian(png_crc(type + data));
}

inline std::string png_ihdr(std::uint32_t width, std::uint32_t height, int bit_depth,
                            int color_type) {
  std::string data = big_endian(width) + big_endian(height);
  data += static_cast<char>(bit_depth);
  data += static_cast<char>(color_type);
  data += std::string(3, '\0');  // deflate, adaptive filtering, no interlace
  return png_chunk("IHDR", data);
}

// rows: the raw scanlines (without filter bytes), each of the same length.
inline std::string encode_png(int width, int height, int bit_depth, int color_type,
                              const std::vector<std::string>& rows, const std::string& palette = {},
                              const std::string& transparency = {}) {
  std::string raw;
  for (const std::string& row : rows) raw += '\0' + row;
  std::string zlib = "\x78\x01";
  std::uint32_t s1 = 1, s2 = 0;
  for (unsigned char c : raw) s1 = (s1 + c) % 65521, s2 = (s2 + s1) % 65521;
  for (std::size_t at = 0; at < raw.size() || at == 0; at += 65535) {
    std::size_t length = std::min<std::size_t>(65535, raw.size() - at);
    bool final = at + length >= raw.size();
    zlib += static_cast<char>(final ? 1 : 0);
    zlib += static_cast<char>(length & 0xFF);
    zlib += static_cast<char>(length >> 8);
    zlib += static_cast<char>(~length & 0xFF);
    zlib += static_cast<char>((~length >> 8) & 0xFF);
    zlib += raw.substr(at, length);
    if (raw.empty()) break;
  }
  zlib += big_endian(s2 << 16 | s1);
  std::string png = "\x89PNG\r\n\x1a\n";
  png += png_ihdr(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), bit_depth,
                  color_type);
  if (!palette.empty()) png += png_chunk("PLTE", palette);
  if (!transparency.empty()) png += png_chunk("tRNS", transparency);
  png += png_chunk("IDAT", zlib);
  png += png_chunk("IEND", "");
  return png;
}

}  // namespace hullcook::test
