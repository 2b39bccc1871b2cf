// Internal: the concavity of holes (the paper's §5.2): Eq. 5 for every hole, from its antipodal
// pair and the vertex of another ring closest to it.
#pragma once

#include "decomposition_types.h"

namespace hullcook::detail {

// Eq. 5 for every hole. Fills ends (per hole) with the antipodal pair and the nearest vertices,
// taking those of inherited (per hole, or empty) that are known.
std::vector<HoleConcavity> measure_holes(const Region& region, const OuterConcavity& outer,
                                         const std::vector<HoleEnds>& inherited,
                                         std::vector<HoleEnds>& ends);

}  // namespace hullcook::detail
