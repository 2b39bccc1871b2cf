// Internal: triangulation of simple polygons, with the adjacency the shortest-path funnel walks.
#pragma once

#include "hullcook/core/polygon.h"

#include <array>
#include <vector>

namespace hullcook::detail {

// Triangulates a simple counter-clockwise polygon (exact predicates): monotone pieces by a plane
// sweep, each triangulated in linear time, O(n log n) in all; ear clipping triangulates small
// polygons, and takes over should the sweep meet input it does not handle (repeated points). Fills
// triangles with n - 2 index triples, each counter-clockwise. When neighbours is given, it receives
// per triangle the triangle across each edge (tri[e], tri[(e + 1) % 3]), or -1 across a polygon
// edge. The vectors are the caller's, so that their storage can be reused.
void triangulate(const std::vector<Vec2>& polygon, std::vector<std::array<int, 3>>& triangles,
                 std::vector<std::array<int, 3>>* neighbours = nullptr);

// The sweep alone: false (output unspecified) where triangulate() falls back to ear clipping.
bool triangulate_by_sweep(const std::vector<Vec2>& polygon,
                          std::vector<std::array<int, 3>>& triangles,
                          std::vector<std::array<int, 3>>* neighbours = nullptr);

// The same by ear clipping, O(n r) for r reflex vertices: the fallback of triangulate().
void triangulate_by_ear_clipping(const std::vector<Vec2>& polygon,
                                 std::vector<std::array<int, 3>>& triangles,
                                 std::vector<std::array<int, 3>>* neighbours = nullptr);

}  // namespace hullcook::detail
