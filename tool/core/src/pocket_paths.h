// Internal: shortest paths inside a pocket polygon (Algorithm 5.1 of the paper).
#pragma once

#include "hullcook/core/polygon.h"

#include <array>
#include <vector>

namespace hullcook::detail {

// The pocket chain q[0] = β-, ..., q[m] = β+ of a counter-clockwise outer boundary, whose bridge
// β = (q[0], q[m]) is a convex hull edge. Sets distance[i], for every q[i], to the length of the
// shortest path inside the pocket polygon from q[i] to the bridge segment [units].
// The pocket is first cut at chords perpendicular to the bridge, which no shortest path crosses;
// the parts whose chain runs forward along the bridge take their perpendicular drops, and the
// others a funnel algorithm over a triangulation of the part, with the bridge as a source at
// infinity (perpendicular drops) bounded by the part's two ends on it.
void shortest_paths_to_bridge(const std::vector<Vec2>& q, std::vector<double>& distance);

}  // namespace hullcook::detail
