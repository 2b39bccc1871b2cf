// Internal: cutting a region along the diagonals Algorithm 4.2 chose, and what each piece
// inherits from its parent's measure (see ParentHint).
#pragma once

#include "decomposition_types.h"

#include <optional>
#include <utility>

namespace hullcook::detail {

// Cuts the outer ring along the diagonal i-j; holes go to the piece containing them. Fills the
// children's hull hints from the parent's hull points.
std::pair<Region, Region> split_outer(const Region& region, std::size_t i, std::size_t j,
                                      const OuterConcavity& parent, bool with_values,
                                      std::pair<ParentHint, ParentHint>& hints);

// Cuts along hole[p]-outer[x] and hole[q]-outer[y] (x != y): two pieces without that hole. Fills
// the pieces' hull hints from the parent's hull points.
std::pair<Region, Region> split_hole(const Region& region, std::size_t h, std::size_t p,
                                     std::size_t x, std::size_t q, std::size_t y,
                                     const OuterConcavity& parent, bool with_values,
                                     std::pair<ParentHint, ParentHint>& hints);

// Cuts along hole[p]-other[u] and hole[q]-other[v] between holes h and other (p != q, u != v, the
// two cuts diagonals that do not meet): the piece between the two holes, and the region with the
// holes and that piece merged into one hole (the last of its holes). Nullopt when the cuts do not
// close one counter-clockwise piece and one clockwise hole.
std::optional<std::pair<Region, Region>> split_between_holes(
    const Region& region, std::size_t h, std::size_t p, std::size_t q, std::size_t other,
    std::size_t u, std::size_t v, const OuterConcavity& parent, bool with_values,
    std::pair<ParentHint, ParentHint>& hints);

// The cut that always exists, for a hole no vertex-to-vertex cut opens: the trapezoid of a slab
// between two consecutive vertex heights (horizontal or vertical) that lies beside the hole, cut
// out along its top and bottom (ending on edges at new vertices where they must). The trapezoid
// comes first; the rest has the hole joined to ∂P0 or merged with another hole. Chooses the
// trapezoid whose smaller extent (height or width) is largest. Nullopt only where every
// candidate's crossings lie within rounding of each other.
std::optional<std::pair<Region, Region>> cut_across_slab(const Region& region, std::size_t h);

// A piece whose area is below sliver_width(its bounding box's diagonal) times that diagonal is a
// sliver: the trace of a cut through near-collinear vertices, not a shape (issue 16).
bool is_sliver(const Ring& ring);
// The same for the piece that the chain of ring from first to last (cyclic) closes, without
// building it.
bool is_sliver(const Ring& ring, std::size_t first, std::size_t last);

// What a piece keeps of its parent's HoleEnds (see ParentHint::hole_ends): a hole keeps its
// antipodal pair, and the vertex nearest to an end where the piece keeps that vertex and no other
// vertex was as near. The piece's vertices are some of the parent's, so none is nearer.
void inherit_hole_ends(const Region& parent, const std::vector<HoleEnds>& parent_ends,
                       const Region& piece, ParentHint& hint);

}  // namespace hullcook::detail
