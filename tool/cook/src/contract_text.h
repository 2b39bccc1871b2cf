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

// What the rounding slack of an outline's outer rings is made of (see contract_slack in
// contract.h): the larger side of their bounding box and their largest coordinate.
struct CoordinateReach {
  double extent = 0.0;
  double largest = 0.0;
};
CoordinateReach coordinate_reach(const std::vector<const Ring*>& rings);
CoordinateReach coordinate_reach(const std::vector<Region>& outline);
double slack_for(CoordinateReach reach);

// The rounding slack of every length compared: slack_for(coordinate_reach(outline)).
double rounding_slack(const std::vector<Region>& outline);

// The diagonal of the ring's bounding box: a piece's length, to the sliver test.
double length_of(const Ring& ring);

// A sliver (is_contract_sliver), described as "area A over a length of L"; nullopt otherwise.
std::optional<std::string> sliver_defect(const Region& region, double slack);

}  // namespace hullcook::detail
