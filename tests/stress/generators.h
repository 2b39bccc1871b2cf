// Seeded generators of polygons with holes for the stress tests (issue 16): the shapes of
// tilesets, frames and UI art on which hole resolution gave up, each family drawn from one 64-bit
// seed, then placed (scaled, rotated, offset, rounded to a grid) and validated as input. One
// family (random_simple) draws hole-free random polygons instead, whose decimal coordinates put
// vertices almost on the lines of their neighbours.
#pragma once

#include "hullcook/core/polygon.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook::stress {

enum class Family {
  thin_wall,  // holes d in {0.01, 0.1, 0.3, 1, 3} from the outer boundary or from each other
  grid,       // up to 20x20 rectangular, rounded or octagonal holes, walls 0.5-4, 4-vertex outer
  row,        // rows of diamonds, hexagons or circles (honeycomb or not), 4-vertex outer
  ring,       // a ring (outer and hole: circles or squares, eccentric or not), maybe a disc inside
  star,       // a random star with random holes (polygons and small stars)
  button,     // a UI button whose few holes nearly fill it (walls 0.2-1.5, notched holes)
  random_simple,  // random points untangled into a simple polygon, on a decimal grid, with
                  // vertices inserted along edges: nearly collinear in binary; no holes
  dense,   // 300-1500 nearly collinear vertices: a jittered circle or a rectangle bulging out by
           // 1e-9 to 1e-3 of its size, mostly with 1-3 round holes of 60-600 sides
  teeth,   // a comb of up to 120 teeth up to 300 long, or a star of up to 300 spikes up to 500
           // long, with 1-5 holes in its spine or core
  spiral,  // an arm wound 1-10 turns (one pocket winding to the centre), 12-200 vertices a turn,
           // its outer side maybe jittered (nearly collinear), with 1-4 round holes along it
};

const std::vector<Family>& all_families();
const char* family_name(Family family);
std::optional<Family> parse_family(std::string_view name);

// How a generated shape is placed: rotated about the origin, scaled, offset, then every
// coordinate rounded to a multiple of rounding (as if written to a file with fewer digits), which
// makes regular shapes' vertices nearly collinear.
struct Placement {
  double rotation = 0.0;  // [radians]
  double scale = 1.0;
  Vec2 offset{0.0, 0.0};
  double rounding = 0.0;  // a power of ten, or 0 for none
};

struct GeneratedCase {
  Family family = Family::grid;
  std::uint64_t seed = 0;
  std::string description;      // the parameters drawn, to read in a failure message
  std::vector<Region> regions;  // valid input (clean_and_validate passed); empty when rejected
  std::string rejection;        // clean_and_validate's message when the case is not valid input
  double thinnest_feature = 0;  // [units] after placement: the narrowest wall or gap drawn
};

// The case (family, seed): the same on every run. A case that clean_and_validate refuses (the
// placement's rounding can make a thin wall touch) comes back with its rejection and no regions.
GeneratedCase generate_case(Family family, std::uint64_t seed);

// The regions moved by the placement (see Placement), without validation.
std::vector<Region> place(const std::vector<Region>& regions, const Placement& placement);

}  // namespace hullcook::stress
