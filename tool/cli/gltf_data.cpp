#include "gltf_data.h"

#include "shortest.h"

#include "hullcook/cook/meshopt_library.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string_view>

namespace hullcook::cli {
namespace {

using json = nlohmann::json;

constexpr std::string_view kBase64Prefix = "data:application/octet-stream;base64,";
constexpr std::string_view kBase64PrefixGltf = "data:application/gltf-buffer;base64,";

std::string decode_base64(std::string_view text, const std::string& where) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  out.reserve(text.size() / 4 * 3);
  std::uint32_t group = 0;
  int bits = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '=') {
      if (text.find_first_not_of('=', i) != std::string_view::npos) {
        throw BadGltf(where + ": base64 data continues after its padding");
      }
      break;
    }
    const int v = value(text[i]);
    if (v < 0) throw BadGltf(where + ": not base64 data");
    group = (group << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((group >> bits) & 0xFF);
    }
  }
  return out;
}

// A non-negative integer property, `fallback` when absent.
std::size_t size_property(const json& object, const char* key, std::size_t fallback,
                          const std::string& where) {
  auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned()) {
    throw BadGltf(where + ": \"" + key + "\" is not a non-negative integer");
  }
  return it->get<std::size_t>();
}

const json& element(const json& root, const char* array, const json& index,
                    const std::string& where) {
  if (!index.is_number_unsigned()) throw BadGltf(where + ": not an index into " + array);
  const std::size_t i = index.get<std::size_t>();
  if (!root.contains(array) || !root[array].is_array() || i >= root[array].size() ||
      !root[array][i].is_object()) {
    throw BadGltf(where + ": " + array + "[" + std::to_string(i) + "] does not exist");
  }
  return root[array][i];
}

std::size_t component_size(int type) {
  switch (type) {
    case 5120:  // BYTE
    case 5121:  // UNSIGNED_BYTE
      return 1;
    case 5122:  // SHORT
    case 5123:  // UNSIGNED_SHORT
      return 2;
    case 5125:  // UNSIGNED_INT
    case 5126:  // FLOAT
      return 4;
    default:
      return 0;
  }
}

std::size_t component_count(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  return 0;
}

double read_component(const char* at, int type) {
  switch (type) {
    case 5120: {
      std::int8_t v;
      std::memcpy(&v, at, 1);
      return v;
    }
    case 5121:
      return static_cast<std::uint8_t>(*at);
    case 5122: {
      std::int16_t v;
      std::memcpy(&v, at, 2);
      return v;
    }
    case 5123: {
      std::uint16_t v;
      std::memcpy(&v, at, 2);
      return v;
    }
    case 5125: {
      std::uint32_t v;
      std::memcpy(&v, at, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, at, 4);
      return v;
    }
  }
}

}  // namespace

GltfData::GltfData(const json& root, std::string glb_bin) : root_(root) {
  if (!root.contains("buffers")) return;
  if (!root["buffers"].is_array()) throw BadGltf("\"buffers\" is not an array");
  for (std::size_t b = 0; b < root["buffers"].size(); ++b) {
    const std::string where = "buffers[" + std::to_string(b) + "]";
    const json& buffer = root["buffers"][b];
    if (!buffer.is_object()) throw BadGltf(where + " is not an object");
    const std::size_t length = size_property(buffer, "byteLength", 0, where);
    std::string bytes;
    if (!buffer.contains("uri")) {
      if (b != 0 || glb_bin.empty()) {
        // A buffer without data (a fallback of EXT_meshopt_compression) reads as nothing.
        buffers_.emplace_back();
        continue;
      }
      bytes = std::move(glb_bin);
    } else {
      if (!buffer["uri"].is_string()) throw BadGltf(where + ": \"uri\" is not a string");
      std::string_view uri = buffer["uri"].get_ref<const std::string&>();
      if (uri.rfind(kBase64Prefix, 0) == 0) {
        bytes = decode_base64(uri.substr(kBase64Prefix.size()), where);
      } else if (uri.rfind(kBase64PrefixGltf, 0) == 0) {
        bytes = decode_base64(uri.substr(kBase64PrefixGltf.size()), where);
      } else {
        throw BadGltf(where + ": external or non-base64 buffer (" + std::string(uri.substr(0, 40)) +
                      ") is not read");
      }
    }
    if (bytes.size() < length) {
      throw BadGltf(where + ": byteLength " + std::to_string(length) + " but only " +
                    std::to_string(bytes.size()) + " bytes of data");
    }
    buffers_.push_back(std::move(bytes));
  }
}

std::string_view GltfData::view_bytes(std::size_t index, const std::string& where_in) const {
  const json& view = root_["bufferViews"][index];
  const std::string where = where_in + ": bufferView " + std::to_string(index);
  const json* source = &view;
  auto compressed = view.find("extensions");
  const bool meshopt = compressed != view.end() && compressed->is_object() &&
                       compressed->contains("EXT_meshopt_compression");
  if (meshopt) {
    source = &(*compressed)["EXT_meshopt_compression"];
    if (!source->is_object()) throw BadGltf(where + ": EXT_meshopt_compression is not an object");
  }
  const std::size_t offset = size_property(*source, "byteOffset", 0, where);
  const std::size_t length = size_property(*source, "byteLength", 0, where);
  if (!source->contains("buffer") || !(*source)["buffer"].is_number_unsigned() ||
      (*source)["buffer"].get<std::size_t>() >= buffers_.size()) {
    throw BadGltf(where + ": names no buffer");
  }
  const std::string& buffer = buffers_[(*source)["buffer"].get<std::size_t>()];
  if (offset > buffer.size() || length > buffer.size() - offset) {
    throw BadGltf(where + ": runs past the end of its buffer");
  }
  const std::string_view stored(buffer.data() + offset, length);
  if (!meshopt) return stored;

  if (auto it = decoded_.find(index); it != decoded_.end()) return it->second;
  const std::size_t count = size_property(*source, "count", 0, where);
  const std::size_t stride = size_property(*source, "byteStride", 0, where);
  const std::size_t decoded_length = size_property(view, "byteLength", 0, where);
  const std::string mode = source->value("mode", "");
  if (source->contains("filter") && (*source)["filter"] != "NONE") {
    throw BadGltf(where + ": meshopt filters are not read");
  }
  if (stride == 0 || stride > 256 || count > (std::size_t{1} << 28) ||
      count * stride != decoded_length) {
    throw BadGltf(where + ": meshopt count * byteStride does not match its byteLength");
  }
  std::string problem;
  const MeshoptLibrary* codecs = meshopt_library(&problem);
  if (codecs == nullptr) throw BadGltf(where + ": cannot decode meshopt data: " + problem);
  std::string out(decoded_length, '\0');
  const auto* input = reinterpret_cast<const unsigned char*>(stored.data());
  int status = -1;
  if (mode == "ATTRIBUTES" && stride % 4 == 0) {
    status = codecs->decodeVertexBuffer(out.data(), count, stride, input, stored.size());
  } else if (mode == "TRIANGLES" && (stride == 2 || stride == 4) && count % 3 == 0) {
    status = codecs->decodeIndexBuffer(out.data(), count, stride, input, stored.size());
  } else if (mode == "INDICES" && (stride == 2 || stride == 4)) {
    status = codecs->decodeIndexSequence(out.data(), count, stride, input, stored.size());
  } else {
    throw BadGltf(where + ": unknown meshopt mode or byteStride");
  }
  if (status != 0) throw BadGltf(where + ": the meshopt data does not decode");
  return decoded_.emplace(index, std::move(out)).first->second;
}

AccessorData GltfData::accessor(const json& index, const std::string& where_in) const {
  const json& accessor = element(root_, "accessors", index, where_in);
  const std::string where = where_in + " (accessor " + index.dump() + ")";
  AccessorData data;
  if (!accessor.contains("componentType") || !accessor["componentType"].is_number_integer()) {
    throw BadGltf(where + ": no componentType");
  }
  data.component_type = accessor["componentType"].get<int>();
  const std::size_t size = component_size(data.component_type);
  if (size == 0) throw BadGltf(where + ": unknown componentType");
  if (!accessor.contains("type") || !accessor["type"].is_string()) {
    throw BadGltf(where + ": no type");
  }
  data.components = component_count(accessor["type"].get<std::string>());
  if (data.components == 0) throw BadGltf(where + ": unsupported type");
  if (accessor.contains("sparse")) throw BadGltf(where + ": sparse accessors are not read");
  if (!accessor.contains("count")) throw BadGltf(where + ": no count");
  const std::size_t count = size_property(accessor, "count", 0, where);
  if (count == 0) throw BadGltf(where + ": count 0");
  if (!accessor.contains("bufferView")) throw BadGltf(where + ": no bufferView");
  const json& view = element(root_, "bufferViews", accessor["bufferView"], where);
  const std::string_view bytes = view_bytes(accessor["bufferView"].get<std::size_t>(), where);
  const std::size_t view_length = bytes.size();
  const std::size_t element_size = size * data.components;
  const std::size_t stride = size_property(view, "byteStride", element_size, where + ".bufferView");
  const std::size_t offset = size_property(accessor, "byteOffset", 0, where);
  if (stride < element_size || stride > std::numeric_limits<std::uint32_t>::max() ||
      count > std::numeric_limits<std::uint32_t>::max() || offset > view_length ||
      (count - 1) * stride + element_size > view_length - offset) {
    throw BadGltf(where + ": its data runs past the end of its bufferView");
  }
  data.values.reserve(count * data.components);
  const char* start = bytes.data() + offset;
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t c = 0; c < data.components; ++c) {
      const double value = read_component(start + i * stride + c * size, data.component_type);
      if (!std::isfinite(value)) throw BadGltf(where + ": a value is not finite");
      data.values.push_back(value);
    }
  }
  return data;
}

}  // namespace hullcook::cli
