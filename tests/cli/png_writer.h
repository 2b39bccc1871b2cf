// A tiny PNG encoder for tests (stored deflate blocks, no compression), so that tests can make
// exactly the images they need, including broken ones, without an image library.
#pragma once

#include "hullcook/format/crc32.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hullcook::test {

inline void put_u32_be(std::string& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(value >> shift));
}

inline void put_chunk(std::string& png, const char* type, const std::string& data) {
  put_u32_be(png, static_cast<std::uint32_t>(data.size()));
  std::string typed = std::string(type, 4) + data;
  png += typed;
  put_u32_be(png, format::crc32(0, typed.data(), typed.size()));
}

// zlib stream of stored blocks.
inline std::string zlib_stored(const std::string& raw) {
  std::string out("\x78\x01", 2);
  std::size_t offset = 0;
  do {
    std::size_t size = std::min<std::size_t>(raw.size() - offset, 65535);
    bool last = offset + size == raw.size();
    out.push_back(last ? 1 : 0);
    out.push_back(static_cast<char>(size & 0xFF));
    out.push_back(static_cast<char>(size >> 8));
    out.push_back(static_cast<char>(~size & 0xFF));
    out.push_back(static_cast<char>((~size >> 8) & 0xFF));
    out.append(raw, offset, size);
    offset += size;
  } while (offset < raw.size());
  std::uint32_t a = 1, b = 0;
  for (unsigned char c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  put_u32_be(out, (b << 16) | a);
  return out;
}

// Only the signature and the IHDR chunk: enough to claim any size without its pixels.
inline std::string make_png_header(std::uint32_t width, std::uint32_t height) {
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put_u32_be(header, width);
  put_u32_be(header, height);
  header += std::string{8, 6, 0, 0, 0};
  put_chunk(png, "IHDR", header);
  return png;
}

// An 8-bit PNG: colour_type 6 (RGBA, 4 channels), 2 (RGB, 3) or 0 (grey, 1); pixels row-major.
inline std::string make_png(std::uint32_t width, std::uint32_t height, int colour_type,
                            const std::vector<std::uint8_t>& pixels) {
  int channels = colour_type == 6 ? 4 : colour_type == 2 ? 3 : colour_type == 4 ? 2 : 1;
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put_u32_be(header, width);
  put_u32_be(header, height);
  header += std::string{8, static_cast<char>(colour_type), 0, 0, 0};
  put_chunk(png, "IHDR", header);
  std::string raw;
  for (std::uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);  // filter: none
    for (std::uint32_t x = 0; x < width * static_cast<std::uint32_t>(channels); ++x) {
      std::size_t index = y * width * channels + x;
      raw.push_back(static_cast<char>(index < pixels.size() ? pixels[index] : 0));
    }
  }
  put_chunk(png, "IDAT", zlib_stored(raw));
  put_chunk(png, "IEND", "");
  return png;
}

}  // namespace hullcook::test
