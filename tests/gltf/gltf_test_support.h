// Reading back what the glTF writer wrote, independently of the writer's code.
#pragma once

#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

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

// The JSON of a written file, and its (first) buffer's bytes.
struct Parsed {
  nlohmann::json root;
  std::string buffer;
};

inline Parsed parse(const std::string& bytes, bool binary) {
  Parsed parsed;
  if (binary) {
    GlbChunks chunks = split_glb(bytes);
    parsed.root = nlohmann::json::parse(chunks.json);
    parsed.buffer = chunks.bin;
  } else {
    parsed.root = nlohmann::json::parse(bytes);
    if (parsed.root.contains("buffers")) {
      std::string uri = parsed.root["buffers"][0]["uri"];
      const std::string prefix = "data:application/octet-stream;base64,";
      EXPECT_EQ(uri.rfind(prefix, 0), 0u);
      parsed.buffer = decode_base64(uri.substr(prefix.size()));
    }
  }
  if (parsed.root.contains("buffers")) {
    std::size_t length = parsed.root["buffers"][0]["byteLength"];
    EXPECT_LE(length, parsed.buffer.size());
    EXPECT_LT(parsed.buffer.size() - length, 4u);  // at most the GLB chunk's padding
  }
  return parsed;
}

// A bufferView's bytes; one compressed with EXT_meshopt_compression is decoded by
// meshoptimizer's own decoder (the reference implementation of the extension).
inline std::string view_bytes(const Parsed& parsed, const nlohmann::json& view) {
  if (!view.contains("extensions")) {
    EXPECT_EQ(view["buffer"], 0);
    return parsed.buffer.substr(view.value("byteOffset", std::size_t{0}), view["byteLength"]);
  }
  const nlohmann::json& meshopt = view["extensions"]["EXT_meshopt_compression"];
  EXPECT_EQ(meshopt["buffer"], 0);
  const std::size_t count = meshopt["count"], stride = meshopt["byteStride"];
  EXPECT_EQ(count * stride, view["byteLength"].get<std::size_t>());
  const auto* data = reinterpret_cast<const unsigned char*>(parsed.buffer.data()) +
                     meshopt.value("byteOffset", std::size_t{0});
  const std::size_t size = meshopt["byteLength"];
  std::string out(count * stride, '\0');
  const int status = meshopt["mode"] == "TRIANGLES"
                         ? meshopt_decodeIndexBuffer(out.data(), count, stride, data, size)
                         : meshopt_decodeVertexBuffer(out.data(), count, stride, data, size);
  EXPECT_EQ(status, 0) << "meshopt decoding failed";
  return out;
}

// An accessor's values read straight from the buffer by the glTF rules (no writer code).
inline std::vector<double> accessor_values(const Parsed& parsed, const nlohmann::json& index) {
  const nlohmann::json& accessor = parsed.root["accessors"][index.get<std::size_t>()];
  const nlohmann::json& view =
      parsed.root["bufferViews"][accessor["bufferView"].get<std::size_t>()];
  const std::string bytes = view_bytes(parsed, view);
  const int component = accessor["componentType"];
  const std::size_t size = component == 5121 ? 1 : component == 5122 || component == 5123 ? 2 : 4;
  const std::string type = accessor["type"];
  const std::size_t components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : 3;
  const std::size_t stride = view.value("byteStride", size * components);
  const std::size_t start = accessor.value("byteOffset", std::size_t{0});
  const std::size_t count = accessor["count"];
  EXPECT_EQ((view.value("byteOffset", std::size_t{0}) + start) % size, 0u);
  EXPECT_LE(start + (count - 1) * stride + size * components, bytes.size());
  std::vector<double> values;
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t c = 0; c < components; ++c) {
      const char* at = bytes.data() + start + i * stride + c * size;
      if (component == 5126) {
        float v;
        std::memcpy(&v, at, 4);
        values.push_back(v);
      } else if (component == 5122) {
        std::int16_t v;
        std::memcpy(&v, at, 2);
        values.push_back(v);
      } else {
        std::uint32_t v = 0;
        std::memcpy(&v, at, size);  // little-endian host, as the build machines are
        values.push_back(v);
      }
    }
  }
  return values;
}

}  // namespace hullcook::test
