// The glTF 2.0 writer (.gltf and .glb). The schema of what it writes is docs/gltf-extras.md.
#pragma once

#include "hullcook/cook/asset.h"

#include <string>
#include <vector>

namespace hullcook {

struct GltfOptions {
  // true: a .glb (binary container, the buffer in its BIN chunk); false: a .gltf (JSON with the
  // buffer embedded as a base64 data: URI, so the file is self-contained).
  bool binary = false;
  // true: the hull meshes are compressed with KHR_draco_mesh_compression (no uncompressed
  // fallback, so the extension is listed in extensionsRequired). The 2D hulls in each node's
  // extras are never compressed and stay authoritative.
  bool draco = false;
  // true: the buffer's views are compressed with EXT_meshopt_compression (as gltfpack does) and
  // every coordinate is rounded to a 16-bit grid per asset (KHR_mesh_quantization; the asset
  // node's translation and scale map the grid to output units), both extensions required.
  // Exclusive with draco.
  bool meshopt = false;
};

// The version of the extras schema written (docs/gltf-extras.md). Version 1 held the hulls as
// JSON numbers and a prism mesh per hull; version 2 holds them in the buffer, one mesh per asset.
inline constexpr int kGltfExtrasVersion = 2;

// Quantization of the Draco-compressed positions [bits per coordinate]: the worst error of a
// decoded vertex is (largest side of the mesh's bounding box) / (2^bits - 1) / 2 per coordinate.
inline constexpr int kGltfDracoPositionBits = 16;

// Returns the bytes of a glTF 2.0 file holding the assets: one node per asset (name = asset name)
// whose extras point at every level of its 2D hulls [output units] in the buffer, and whose mesh
// (flat, z = 0: its finest level's hulls as triangle fans) carries the KHR_physics_rigid_bodies and
// OMI_physics_body/OMI_physics_shape colliders. Deterministic: the same assets always give the
// same bytes.
// Throws OutputError if an asset holds a non-finite coordinate or its Draco encoding fails.
std::string write_gltf(const std::vector<CookedAsset>& assets, const GltfOptions& options);

}  // namespace hullcook
