// Internal to hullcook_trace: ring geometry shared by the tracer and the simplifier.
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace hullcook::trace_detail {

// Shoelace area [px²]: positive for outer rings, negative for holes (see trace.h).
double signed_area(const Ring& ring);

// For rings that neither cross nor touch each other: the index of the ring immediately
// enclosing each ring, or -1. Uses each ring's orientation sign (outer > 0, hole < 0).
// threads: how many may work at once; the result is the same for any count.
// misplaced, when given, gets 1 for each ring whose parent that rule cannot be trusted for: the
// ring first met leftwards encloses it but has its orientation, or does not and has the other
// (rings that are not nested as outer boundaries and holes, e.g. after simplification).
// met_first, when given, gets that ring first met leftwards for each ring, or -1.
std::vector<int> nesting_parents(const std::vector<Ring>& rings, unsigned threads = 1,
                                 std::vector<char>* misplaced = nullptr,
                                 std::vector<int>* met_first = nullptr);

// Simplifies every ring with error bound eps [px] (every vertex of the original ring lies within
// eps of the simplified ring), keeping the rings simple, disjoint and nested as before, each with
// at least 3 vertices and its orientation. parents is nesting_parents(rings).
// Also removes collinear vertices (which does not move the outline). eps = 0 only does that.
// threads: how many may simplify rings at once; the result is the same for any count.
// pinned, when given, names vertices kept whatever eps (a tile's outline on its cell's border);
// without_collinear still drops one that lies straight between its neighbours.
std::vector<Ring> simplify_rings(const std::vector<Ring>& rings, const std::vector<int>& parents,
                                 double eps, unsigned threads = 1,
                                 const std::function<bool(Vec2)>& pinned = {});

}  // namespace hullcook::trace_detail
