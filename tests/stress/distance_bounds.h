// Proven distance bounds for the referee (independent_check.h): how far a component's boundary
// strays from its convex hull, and how far a polygon's points are from a filled target. Each
// answer is a proof (a bound that holds everywhere) or a witness (a point beyond the limit).
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <vector>

namespace hullcook::stress {

// The edge lines of a convex, counter-clockwise polygon, as signed distances (positive inside).
class ConvexLines {
 public:
  explicit ConvexLines(const Ring& hull);
  // min over the edge lines: for a point inside the polygon, its distance to the boundary;
  // negative outside.
  double depth(Vec2 p) const;
  // The largest depth() along the segment pq (both inside the polygon): depth is the minimum of
  // affine functions, hence concave along pq, and its maximum is found where the active line's
  // slope changes sign. point is where it is reached.
  double max_depth(Vec2 p, Vec2 q, double limit, Vec2& point) const;

 private:
  Vec2 origin_;
  std::vector<Vec2> normals_;  // unit, pointing inside
  std::vector<double> offsets_;
};

struct FarthestPoint {
  bool proven = true;   // every point of the domain is within limit of the target
  double distance = 0;  // the witness's distance to the target (0 when proven; the farthest
                        // seen when the budget ran out without a witness)
  Vec2 point{0, 0};     // the witness
};

// Decides whether every point of the convex polygon domain (counter-clockwise) is within limit of
// the filled target (regions, holes excluded), by halving the domain's fan triangles across their
// longest edge: a triangle is proven by the 1-Lipschitz bound from its centroid, by the convexity
// of the distance to one target segment (its maximum over the triangle is at a corner), by lying
// inside the target, or, with its centroid inside, by bounding the parts of it right of each target
// segment that meets it (where alone it can leave the target); a centroid farther than limit is a
// witness, and the search goes on a little for the farthest (to a thousandth of its distance).
// Triangles smaller than resolution are taken as proven (their points are within limit +
// resolution). Gives up after budget triangles (proven = false, with the farthest witness found if
// any).
FarthestPoint farthest_from_target(const Ring& domain, const std::vector<Region>& target,
                                   double limit, double resolution, std::size_t budget);

}  // namespace hullcook::stress
