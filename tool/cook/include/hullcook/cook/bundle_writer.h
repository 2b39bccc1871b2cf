// The .hcb bundle writer (formats/SPEC.md): cooked assets to the bytes the runtime reads.
#pragma once

#include "hullcook/cook/asset.h"

#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

namespace hullcook {

// Serializes assets, in the given order, into a bundle of format version 1.0 and returns its
// bytes (deterministic: the same assets give the same bytes).
//
// Per asset it stores the name, image size, pixels per unit, pivot, physics properties when set,
// and every level of `levels` (finest first, τ in [output units]; an asset without levels gets
// one empty level at `tau`). Hull vertices are quantized on a per-asset grid so that every
// stored hull is strictly convex, counter-clockwise, and within the error bound
// E = max(1 % of levels[0].tau, 1/64 px) of the cooked hull (two-sided Hausdorff distance,
// SPEC §9): vertices that rounding makes repeated, collinear or reflex are dropped.
//
// Throws OutputError naming the asset and the problem when it cannot be stored: an empty,
// duplicate or over-long (> 65535 bytes) name, an image side > 65535 px, a non-positive
// pixels-per-unit, unordered or negative τ, a hull with fewer than 3 vertices or non-finite
// coordinates, a hull too large for 16-bit deltas at precision E, or names so many of which share
// their 32-bit hash that no sane name table meets the readers' probe budget (SPEC §6).
std::string write_bundle(const std::vector<CookedAsset>& assets);

// The largest image side a bundle stores [px].
inline constexpr int kBundleLargestImageSide = 0xFFFF;

// Throws write_bundle's OutputError for asset `name` when its image of width x height px (read
// from source) has a side a bundle cannot store.
void check_bundle_image_size(const std::string& name, const std::string& source, int width,
                             int height);

// How an asset's records are laid out in a bundle.
struct AssetShape {
  float step = 0.0f;                       // [output units] the quantization grid's step
  std::vector<float> level_taus;           // [output units] finest first
  std::vector<std::uint32_t> level_hulls;  // hulls per level
  std::uint32_t hull_count = 0, vertex_count = 0;
};

// A bundle written as a cook goes, so that a cook of 10,000 assets holds no more hulls than one
// of 100 (issue 19): each asset's hulls are quantized and spilled to an anonymous temporary file
// (std::tmpfile: gone with the process, however it ends) as soon as it is cooked, and write()
// assembles the bundle from the spill. The bytes equal write_bundle's of the same assets.
class BundleStream {
 public:
  // Throws OutputError when the temporary file cannot be created.
  BundleStream();
  ~BundleStream();
  BundleStream(const BundleStream&) = delete;
  BundleStream& operator=(const BundleStream&) = delete;

  // Quantizes asset's levels (as write_bundle does) and spills them under key; safe to call from
  // several threads. Throws OutputError naming the asset when it cannot be stored.
  void add(std::size_t key, const CookedAsset& asset);

  // Writes the bundle of assets, in this order, to out at its current position: the levels of
  // assets[i] are those added under keys[i] (its other fields, the name included, are read from
  // assets[i]). Throws OutputError (duplicate names, a failed write).
  void write(std::FILE* out, const std::vector<CookedAsset>& assets,
             const std::vector<std::size_t>& keys) const;

 private:
  struct Stored {
    AssetShape shape;
    std::size_t offset = 0;  // [bytes] in the spill: hull records, then vertex records
    bool added = false;
  };
  std::FILE* spill_ = nullptr;
  std::size_t spilled_ = 0;
  std::vector<Stored> stored_;
  mutable std::mutex mutex_;
};

}  // namespace hullcook
