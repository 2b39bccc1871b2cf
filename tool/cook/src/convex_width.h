// The width of a convex hull: how thin a piece or a hull is, for the engine limits.
#pragma once

#include "hullcook/core/polygon.h"

namespace hullcook {

// The least distance between two parallel lines holding the convex ring (counter-clockwise), one
// of them through an edge: over its edges, the farthest vertex left of the edge's line [units];
// infinity when no edge has a length. Linear in the vertex count (rotating calipers) from
// kCalipersFrom vertices on a strictly convex ring not thinner than 1e-9 of its size, where it
// gives what the scan of every vertex per edge gives; quadratic (the scan) otherwise.
double width_of(const Ring& hull);

// For tests: width_of by scanning every vertex for every edge (quadratic).
double width_of_by_scan(const Ring& hull);

inline constexpr std::size_t kCalipersFrom = 64;

}  // namespace hullcook
