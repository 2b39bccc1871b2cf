// Tilesets (--grid --tile): a cell's traced shape kept inside the cell, its outline points near
// the cell's border put exactly on it, so that solid neighbours meet along the whole border with
// no seam, notch or bump for a body to catch on (ghost collisions at tile seams).
#pragma once

#include "hullcook/core/polygon.h"

#include <string>
#include <vector>

namespace hullcook {

// regions [px, cell coordinates: 0..width x 0..height] with every point clamped into the cell
// and every coordinate within snap of a border line (x = 0 or width, y = 0 or height) set to it
// exactly, then cleaned (repeated and collinear points dropped) and validated. Where snapping
// would leave an invalid outline (a feature thinner than snap squeezed onto the border), the
// traced regions are kept, clamped only if that is valid, and a warning says so.
std::vector<Region> snap_to_cell(const std::vector<Region>& regions, int width, int height,
                                 double snap, const std::string& source,
                                 std::vector<std::string>& warnings);

}  // namespace hullcook
