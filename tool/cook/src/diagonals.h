// Cutting a simple ring along its diagonals: the engine limits' halves and slices of a piece that
// no hull of --max-verts vertices holds (constrain.cpp).
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace hullcook {

// Splits a convex component along a diagonal from a vertex to the one halfway round, into halves
// with an area that the contract does not call slivers (at its slack for rounding). The
// diagonal starts at a vertex whose turn is too small to measure, if there is one: that vertex is
// what no hull of the component could keep (hull_meets_limits wants every turn positive), and a
// half whose ends it is no longer turns there. Otherwise, or when those halves do not do, from
// vertex 0, then from the others in order: a random polygon's three nearly collinear vertices at
// 0..2 left the first half without area, and a 1000-vertex star 1e-6 wide at --max-verts 3 was
// halved into slivers, both internal errors on valid input. Sets *only_slivers when some halves
// had an area but every such pair held a sliver.
std::optional<std::pair<Ring, Ring>> halve_convex(const Ring& polygon, double slack,
                                                  bool* only_slivers);

// Whether the segment from ring[i] to ring[j] lies inside the simple counter-clockwise ring but
// for its ends (exact): it leaves each end into the interior angle there, and it meets no edge
// that does not end at i or j.
bool is_inner_diagonal(const Ring& ring, std::size_t i, std::size_t j);

// The rings that slicing cuts: runs base[first .. first + n - 1] of one ring, each closed by the
// edge from its last vertex back to its first. Boxes of every kEdges edges of base let
// is_inner_diagonal skip the edges far from a diagonal: every length a slice tries asks it, and
// a scan of every edge was half the time of slicing a disc of 6,000 vertices into triangles.
class RunsOfRing {
 public:
  // base must outlive this.
  explicit RunsOfRing(const Ring& base);

  // is_inner_diagonal(ring, i, j) for ring = base[first .. first + ring.size() - 1] (ring.size()
  // at least 4, i and j distinct indices of ring): the same answer, from the edges near the
  // diagonal.
  bool is_inner_diagonal(const Ring& ring, std::size_t first, std::size_t i, std::size_t j) const;

 private:
  static constexpr std::size_t kEdges = 32;
  struct Bounds {
    Vec2 low, high;
  };
  static bool box_misses(const Bounds& box, Vec2 p, Vec2 q);

  const Ring& base_;
  std::vector<Bounds> boxes_;
};

// Splits a ring that is not convex along its shortest inner diagonal between vertices halfway
// round from each other (of up to 32 evenly spaced starts), into halves that the contract does
// not call slivers. A nearly convex component, such as a traced disc, then needs about half the
// hull vertices on each side; decomposing it finer instead cut its rim's notches of a fraction
// of τ into slivers of their own: 154 hulls for a 512 px disc at --max-verts 8.
std::optional<std::pair<Ring, Ring>> halve_along_diagonal(const Ring& ring, double slack);

}  // namespace hullcook
