// Rounding an asset's hulls to the bundle's integer grid within its error bound (SPEC §9).
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/format/bundle_layout.h"

#include <string>
#include <vector>

namespace hullcook {

struct QuantizedHull {
  format::HullRecord record{};
  std::vector<format::VertexRecord> vertices;
};

struct QuantizedAsset {
  float step = 0.0f;                               // [output units] the asset's quant_step
  std::vector<std::vector<QuantizedHull>> levels;  // as the asset's levels, hull for hull
};

// Throws OutputError "bundle: asset 'NAME': problem".
[[noreturn]] void bundle_asset_error(const std::string& name, const std::string& problem);
[[noreturn]] inline void bundle_asset_error(const CookedAsset& asset, const std::string& problem) {
  bundle_asset_error(asset.name, problem);
}

// Every hull of levels on one grid whose step is the largest that stores each hull strictly
// convex, in 16-bit deltas from its base, within the bound readers report (SPEC §9); throws
// OutputError when no step does.
QuantizedAsset quantize_asset(const CookedAsset& asset, const std::vector<CookedLevel>& levels);

}  // namespace hullcook
