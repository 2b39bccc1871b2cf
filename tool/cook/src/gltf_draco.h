// KHR_draco_mesh_compression of one triangle mesh, for the glTF writer (gltf_writer.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hullcook {

// A triangle list: x, y, z per vertex and three vertex indices per triangle.
struct TriangleMesh {
  std::vector<float> positions;
  std::vector<std::uint32_t> indices;
};

// A Draco-encoded mesh and what its decoder gives back: the accessors of a Draco primitive
// without fallback describe the decoded data, which Draco deduplicates, reorders and quantizes.
struct DracoMesh {
  std::string bytes;
  std::size_t decoded_points = 0;
  std::size_t decoded_faces = 0;
  std::array<float, 3> min{}, max{};
  std::uint32_t position_id = 0;  // the Draco attribute's unique id
};

// Encodes the mesh (edgebreaker, positions quantized to `position_bits`) and decodes it again to
// measure it. Throws OutputError naming `name` when Draco fails, or when the Draco module
// (hullcook_draco.so, loaded on first use: see draco_module.cpp) cannot be loaded.
DracoMesh draco_encode(const TriangleMesh& mesh, int position_bits, const std::string& name);

// The Draco module's entry point, extern "C": bool (const TriangleMesh*, int position_bits,
// const std::string* name, DracoMesh* out, std::string* error), false with *error set on failure.
inline constexpr const char* kDracoEntryPoint = "hullcook_draco_encode";
using DracoEntryPoint = bool (*)(const TriangleMesh*, int, const std::string*, DracoMesh*,
                                 std::string*) noexcept;

}  // namespace hullcook
