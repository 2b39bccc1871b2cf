// Internal: what the output contract's checks (contract.cpp) and the refusal of regions too thin
// for it (thin_regions.cpp) share: their numbers' and points' text, the rounding slack and the
// sliver test's description.
#pragma once

#include "hullcook/core/polygon.h"

#include <optional>
#include <string>
#include <vector>

namespace hullcook::detail {

std::string number(double value);  // "%.6g"
std::string point(Vec2 p);         // "(x, y)"

// The rounding slack of every length compared (see contract_slack in contract.h).
double rounding_slack(const std::vector<Region>& outline);

// The diagonal of the ring's bounding box: a piece's length, to the sliver test.
double length_of(const Ring& ring);

// A sliver (is_contract_sliver), described as "area A over a length of L"; nullopt otherwise.
std::optional<std::string> sliver_defect(const Region& region, double slack);

}  // namespace hullcook::detail
