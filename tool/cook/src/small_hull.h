// Hulls for a piece too small for the weld: the smallest shapes the engine accepts around it.
#pragma once

#include "hullcook/cook/constrain.h"

#include <vector>

namespace hullcook {

// Convex counter-clockwise candidates holding every point of ring: rectangles and triangles
// aligned with each edge of its hull and with the axes, each at least the weld distance across
// (or, with no weld, a hair wider than the ring), smallest area first; then, with reach above 0
// [output units, τ], flat triangles whose bases reach only part of it past the ring's ends. They
// are candidates: the caller checks them against the limits and τ.
std::vector<Ring> small_hulls(const Ring& ring, const EngineLimits& limits, double reach = 0.0);

}  // namespace hullcook
