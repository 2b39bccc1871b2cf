// EXT_meshopt_compression and KHR_mesh_quantization for the glTF writer (gltf_writer.cpp): the
// grid an asset's coordinates are rounded to, and the compression of one bufferView.
#pragma once

#include "hullcook/cook/asset.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace hullcook {

// An asset's coordinates as 16-bit integers: x = origin.x + step * qx (and y alike). The step is
// the bundle's (formats/SPEC.md §9): sqrt(2) * max(0.01 tau, 1/64 px), coarser when the asset
// spans more than 65000 steps, finer (halved) while a hull would round to a line or a point, so
// each coordinate moves by at most step / 2.
struct Quantization {
  Vec2 origin{0.0, 0.0};  // [output units]
  double step = 1.0;      // [output units]

  // Throws OutputError naming the asset when the asset does not fit 16 bits, or when a hull is
  // too thin for every step that does (it would round to a line or a point).
  static Quantization of(const CookedAsset& asset);
  std::int16_t x(double value) const;
  std::int16_t y(double value) const;

  // hull (convex, counter-clockwise) without the vertices that rounding to the grid leaves
  // repeated, collinear or reflex: what is left rounds to a strictly convex counter-clockwise
  // ring of grid points that holds every rounded vertex. hull itself when rounding keeps it
  // convex, or when it flattens it to a line or a point (see flattens).
  Ring held(const Ring& hull) const;
  // Whether hull, counter-clockwise with an area, rounds to a line or a point on the grid (no
  // three of its rounded vertices turn left): a hull narrower than the step, or one that rounding
  // happens to align. of() chooses a step where no hull of the asset does.
  bool flattens(const Ring& hull) const;
};

// A bufferView's data compressed by meshoptimizer, as EXT_meshopt_compression decodes it.
enum class MeshoptMode { attributes, triangles };
std::string meshopt_compress(std::string_view data, std::size_t stride, MeshoptMode mode);

}  // namespace hullcook
