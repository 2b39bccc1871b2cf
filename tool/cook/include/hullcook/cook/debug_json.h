// The debug JSON writer (issue 3's schema): every asset's cleaned input, pieces, hulls and stats.
#pragma once

#include "hullcook/cook/asset.h"

#include <string>
#include <vector>

namespace hullcook {

// {"hullcook": 1, "assets": [...]} with coordinates in output units, printed with %.17g so they
// round-trip a double. Besides issue 3's fields, each asset carries "levels" ([{tau, hulls}],
// finest first, hulls after the engine limits), "pixels_per_unit" and "pivot", "image"
// ({width, height}) for traced images, "quantization_error" for hulls read back from a bundle,
// "physics" when the asset has properties, "warnings" when there are any, and
// stats.traced_vertices, stats.decode_ms, stats.trace_ms and stats.contract_ms. Deterministic but
// for the *_ms timings.
std::string debug_json(const std::vector<CookedAsset>& assets);

}  // namespace hullcook
