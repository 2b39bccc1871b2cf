// Polygon types shared by every stage of the cooker.
#pragma once

#include <glm/vec2.hpp>

#include <vector>

namespace hullcook {

using Vec2 = glm::dvec2;

// A closed ring of vertices; the closing edge from back() to front() is implicit.
using Ring = std::vector<Vec2>;

// One outer boundary with the holes inside it (the paper's ∂P0 ... ∂Pk).
// After clean_and_validate(): outer counter-clockwise, holes clockwise, no repeated or collinear
// vertices, no self-intersection, holes strictly inside the outer boundary and disjoint.
struct Region {
  Ring outer;
  std::vector<Ring> holes;
};

}  // namespace hullcook
