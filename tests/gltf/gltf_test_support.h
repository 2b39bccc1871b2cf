// Reading back what the glTF writer wrote, independently of the writer's code.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hullcook::test {

inline std::uint32_t read_u32(std::string_view bytes, std::size_t offset) {
  if (offset + 4 > bytes.size()) throw std::runtime_error("read past the end");
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<std::uint8_t>(bytes[offset + i]);
  return value;
}

// The chunks of a GLB, as the container specification lays them out (glTF 2.0, §4.4).
struct GlbChunks {
  std::string json;  // with its padding
  std::string bin;   // with its padding; empty when there is no BIN chunk
};

// Parses a GLB; throws std::runtime_error on any structural fault.
inline GlbChunks split_glb(std::string_view bytes) {
  if (bytes.size() < 20) throw std::runtime_error("shorter than a GLB header and chunk header");
  if (read_u32(bytes, 0) != 0x46546C67) throw std::runtime_error("bad magic");
  if (read_u32(bytes, 4) != 2) throw std::runtime_error("bad version");
  if (read_u32(bytes, 8) != bytes.size()) throw std::runtime_error("length != file size");
  GlbChunks chunks;
  std::size_t offset = 12;
  int index = 0;
  while (offset < bytes.size()) {
    std::uint32_t length = read_u32(bytes, offset);
    std::uint32_t type = read_u32(bytes, offset + 4);
    if (length % 4 != 0) throw std::runtime_error("chunk length not a multiple of 4");
    if (offset + 8 + length > bytes.size()) throw std::runtime_error("chunk past the end");
    std::string data(bytes.substr(offset + 8, length));
    if (index == 0 && type == 0x4E4F534A) {
      chunks.json = std::move(data);
    } else if (index == 1 && type == 0x004E4942) {
      chunks.bin = std::move(data);
    } else {
      throw std::runtime_error("unexpected chunk " + std::to_string(index));
    }
    offset += 8 + length;
    ++index;
  }
  if (index == 0) throw std::runtime_error("no JSON chunk");
  return chunks;
}

inline std::string decode_base64(std::string_view text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  std::uint32_t group = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    int v = value(c);
    if (v < 0) throw std::runtime_error("bad base64");
    group = (group << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((group >> bits) & 0xFF);
    }
  }
  return out;
}

}  // namespace hullcook::test
