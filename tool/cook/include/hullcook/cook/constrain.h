// Engine constraints, applied after the decomposition: Box2D and Chipmunk accept every hull we
// write unchanged, and the error bound τ still holds.
#pragma once

#include "hullcook/cook/asset.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace hullcook {

struct EngineLimits {
  std::size_t max_verts = 8;  // per hull; 0 = unlimited
  double weld = 0.005;        // [output units] minimum distance between two hull vertices
};

// A vertex is collinear with its neighbours (and removed) when it is closer than this fraction
// of the weld distance to the line through them: engines computing hulls in float must see a
// strict turn.
inline constexpr double kCollinearFractionOfWeld = 0.1;

// Splits a component that no hull within the limits can cover into smaller pieces, each with
// its component, convex hull and concavity; tau is the tolerance to split at. Returns the
// component unchanged (one piece) when it cannot split it further.
using SplitComponent = std::function<std::vector<CookedPiece>(const Region& component, double tau)>;

// Makes every hull satisfy the limits while keeping, for tolerance tau [output units]:
//  - each hull convex, counter-clockwise, with at most max_verts vertices, no two vertices closer
//    than weld and no vertex within kCollinearFractionOfWeld * weld of its neighbours' line;
//  - each component inside its hull, and each component vertex within max(tau, its distance
//    before) of its hull's boundary;
//  - every hull point within tau of its component.
// Hulls only grow (edges are removed by extending their neighbours) or components are split
// further with split. A piece that cannot meet the limits (smaller than the weld distance) is
// left out and reported in warnings, never dropped silently.
std::vector<CookedPiece> apply_engine_limits(std::vector<CookedPiece> pieces, double tau,
                                             const EngineLimits& limits,
                                             const SplitComponent& split,
                                             std::vector<std::string>& warnings);

// True when hull meets the limits' vertex count, weld and collinearity rules and is a convex,
// counter-clockwise polygon with at least 3 vertices.
bool hull_meets_limits(const Ring& hull, const EngineLimits& limits);

}  // namespace hullcook
