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
// Self-intersection is found with a uniform grid: near-linear on ordinary rings. threads: how many
// may validate regions at once; the result, and the error thrown (the first region's), are the
// same for any count.
std::vector<Region> clean_and_validate(std::vector<Region> regions, std::string_view source,
                                       unsigned threads = 1);

// Throws InputError "source: region R hole H: too small: ..." for a ring whose bounding box's
// larger side is above 0 and below 1e-140: there the orientation tests' products of coordinate
// differences reach the subnormal range and stop being exact. For input, before
// clean_and_validate (which would otherwise remove such a ring's vertices as collinear); not for
// the pieces of a valid input, which may be smaller.
void refuse_tiny_rings(const std::vector<Region>& regions, std::string_view source);

// Removes repeated and exactly collinear vertices of a ring (including across the closing edge).
// The result may have fewer than 3 vertices.
Ring remove_degenerate_vertices(const Ring& ring);

// The same, in place (no allocation).
void remove_degenerate_vertices_in_place(Ring& ring);

}  // namespace hullcook
