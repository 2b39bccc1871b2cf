// Internal: shortest paths inside a pocket polygon (Algorithm 5.1 of the paper).
#pragma once

#include "hullcook/core/polygon.h"

#include <array>
#include <vector>

namespace hullcook::detail {

// Triangulates a simple counter-clockwise polygon by ear clipping (exact predicates).
// Returns n - 2 triangles as index triples, each counter-clockwise. When neighbours is given, it
// receives per triangle the triangle across each edge (tri[e], tri[(e + 1) % 3]), or -1 across a
// polygon edge.
std::vector<std::array<int, 3>> triangulate(const std::vector<Vec2>& polygon,
                                            std::vector<std::array<int, 3>>* neighbours = nullptr);

// The pocket chain q[0] = β-, ..., q[m] = β+ of a counter-clockwise outer boundary, whose bridge
// β = (q[0], q[m]) is a convex hull edge. Returns, for every q[i], the length of the shortest path
// inside the pocket polygon from q[i] to the bridge segment [units].
// A funnel algorithm over a triangulation of the pocket, with the bridge as a source at infinity
// (perpendicular drops) bounded by its two end points.
std::vector<double> shortest_paths_to_bridge(const std::vector<Vec2>& q);

}  // namespace hullcook::detail
