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

// Whether two distinct points, each a vertex of one ring, lie on both rings' boundaries. Two
// rings that share a stretch of boundary have them: its ends. Most pairs that a merge asks about
// do not (the thin triangles of a fan, whose boxes span the others, meet only at its apex), and
// this asks it without allocating: a sawtooth of 5,000 vertices made 2 million calls.
// merge_components asks it first.
bool meet_at_two_points(const Ring& a, const Ring& b);

// How many distinct points the two rings' vertices give on the other's boundary, as
// meet_at_two_points counts them: 0, 1, or 2 for two or more.
int boundary_points_shared(const Ring& a, const Ring& b);

// boundary_points_shared's count, with the first point found: the only one when count is 1.
struct SharedBoundaryPoints {
  int count = 0;
  Vec2 first{0, 0};
};
SharedBoundaryPoints shared_boundary_points(const Ring& a, const Ring& b);

}  // namespace hullcook
