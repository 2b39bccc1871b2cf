// The .hcb bundle writer (formats/SPEC.md): cooked assets to the bytes the runtime reads.
#pragma once

#include "hullcook/cook/asset.h"

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

}  // namespace hullcook
