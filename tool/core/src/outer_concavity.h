// Internal: the concavity of the outer boundary ∂P0 (the paper's §5.1): straight-line (SL),
// shortest-path (SP) and hybrid (H1, H2) concavity of every vertex, pocket by pocket.
#pragma once

#include "decomposition_types.h"

#include <bit>
#include <cstdint>
#include <unordered_map>

namespace hullcook::detail {

// Shortest paths of pockets already measured in an ancestor, reused instead of re-triangulating
// (only H2 measures a pocket again; see decompose()). A pocket is its chain from β- to β+. A
// child's pocket with the same end points and length is often the same chain, but not always: a
// hole joined to the boundary can bring other vertices between the same ends (issue 3, a traced
// sprite's grid). An entry keeps its chain, and a lookup takes it only for an equal chain.
struct PocketKey {
  double sx, sy, tx, ty;
  std::size_t length;
  bool operator==(const PocketKey&) const = default;
};
struct PocketKeyHash {
  // The coordinates' bits (both zeros as one, since they compare equal), multiplied in: a
  // lookup per pocket, where std::hash<double> called a byte-wise hash four times.
  std::size_t operator()(const PocketKey& k) const {
    auto bits = [](double v) { return v == 0.0 ? 0 : std::bit_cast<std::uint64_t>(v); };
    std::uint64_t h = k.length;
    for (double v : {k.sx, k.sy, k.tx, k.ty}) h = (h ^ bits(v)) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
struct PocketPaths {
  std::vector<Vec2> chain;
  std::vector<double> paths;
};
using PocketCache = std::unordered_map<PocketKey, PocketPaths, PocketKeyHash>;

// Measures into result, whose storage is reused: a decomposition measures every component. A
// hint (see ParentHint) spares what the parent measured; a cache (H2 only) reuses shortest paths.
void measure_outer(const Ring& ring, Measure measure, double tau, OuterConcavity& result,
                   PocketCache* cache = nullptr, const ParentHint* hint = nullptr);

}  // namespace hullcook::detail
