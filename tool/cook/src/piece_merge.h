// The union of two pieces of one decomposition, for a piece too small for the engine's weld.
#pragma once

#include "hullcook/core/polygon.h"

#include <optional>

namespace hullcook {

// The union of components a and b when their outer rings share one stretch of boundary: the
// same vertices in opposite directions, as a cut leaves them (a vertex of one lying inside an
// edge of the other is inserted into that edge first). The result is a simple counter-clockwise
// outer ring, without repeated or exactly collinear vertices, with the holes of both. nullopt
// when they share no edge, share more than one stretch (the union would enclose a hole), or
// touch or cross anywhere else.
std::optional<Region> merge_components(const Region& a, const Region& b);

}  // namespace hullcook
