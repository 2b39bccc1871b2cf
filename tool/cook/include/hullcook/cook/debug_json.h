// The debug JSON writer (issue 3's schema): every asset's cleaned input, pieces, hulls and stats.
#pragma once

#include "hullcook/cook/asset.h"

#include <string>
#include <vector>

namespace hullcook {

// {"hullcook": 1, "assets": [...]} with coordinates in output units, printed with %.17g so they
// round-trip a double. Deterministic: the same assets give the same bytes.
std::string debug_json(const std::vector<CookedAsset>& assets);

}  // namespace hullcook
