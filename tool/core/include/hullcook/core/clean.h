// Clean-up and validation of input polygons, before decomposition.
#pragma once

#include "hullcook/core/polygon.h"

#include <string_view>
#include <vector>

namespace hullcook {

// Removes repeated and collinear vertices, orients outer rings counter-clockwise and holes
// clockwise, then validates every region. Throws InputError "source: region R hole H: problem"
// for: NaN or infinite coordinates, fewer than 3 distinct points, zero area, self-intersection
// (or self-touching), a hole crossing, touching or outside its outer boundary, holes crossing,
// touching or nested in each other. Regions are not checked against each other.
// Self-intersection is found with a uniform grid: near-linear on ordinary rings.
std::vector<Region> clean_and_validate(std::vector<Region> regions, std::string_view source);

// Removes repeated and exactly collinear vertices of a ring (including across the closing edge).
// The result may have fewer than 3 vertices.
Ring remove_degenerate_vertices(const Ring& ring);

// The same, in place (no allocation).
void remove_degenerate_vertices_in_place(Ring& ring);

}  // namespace hullcook
