// Internal: cutting a region along the diagonals Algorithm 4.2 chose, and what each piece
// inherits from its parent's measure (see ParentHint).
#pragma once

#include "decomposition_types.h"

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

// What a piece keeps of its parent's HoleEnds (see ParentHint::hole_ends): a hole keeps its
// antipodal pair, and the vertex nearest to an end where the piece keeps that vertex and no other
// vertex was as near. The piece's vertices are some of the parent's, so none is nearer.
void inherit_hole_ends(const Region& parent, const std::vector<HoleEnds>& parent_ends,
                       const Region& piece, ParentHint& hint);

}  // namespace hullcook::detail
