// Reading a glTF file's binary data for `hullcook inspect`: the buffers of a .gltf (base64 data:
// URIs) or a .glb (its BIN chunk), bufferViews compressed with EXT_meshopt_compression, and
// accessors into them, checked against every bound so that a damaged file gives a message and
// never a read past the end.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook::cli {

// The file is not a readable hullcook glTF; the message says why.
struct BadGltf : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An accessor's elements, `components` numbers per element (1 for SCALAR ... 4 for VEC4).
struct AccessorData {
  int component_type = 0;
  std::size_t components = 0;
  std::vector<double> values;  // element after element; a float exactly, as a double
};

class GltfData {
 public:
  // `glb_bin` is the BIN chunk of a .glb (empty for a .gltf). Throws BadGltf when a buffer is
  // neither a base64 data: URI nor the GLB's chunk.
  GltfData(const nlohmann::json& root, std::string glb_bin);

  // Reads accessor `index`; throws BadGltf naming `where` and the problem.
  AccessorData accessor(const nlohmann::json& index, const std::string& where) const;

 private:
  // The bytes of bufferView `index` and their size; decodes (once) a compressed one.
  std::string_view view_bytes(std::size_t index, const std::string& where) const;

  const nlohmann::json& root_;
  std::vector<std::string> buffers_;
  mutable std::map<std::size_t, std::string> decoded_;
};

}  // namespace hullcook::cli
