// Geometry utilities on rings and regions, built on the exact predicates.
#pragma once

#include "hullcook/core/buckets.h"
#include "hullcook/core/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hullcook {

// Signed area of a ring [units²]: positive when counter-clockwise.
double signed_area(const Ring& ring);

// Area of a region: outer minus holes [units²]. Assumes a cleaned region.
double region_area(const Region& region);

// The least distance between two parallel lines that hold a convex ring between them [units]:
// over its edges, the spread of its vertices across the edge's line (signed, so that a ring
// against the rules is not measured thinner than it is; each direction normalised first, so that
// tiny coordinates do not underflow). 0 for fewer than 3 vertices or no edge of any length.
double convex_thickness(const Ring& ring);

// Convex hull of a point set, counter-clockwise, without repeated or collinear vertices,
// starting at the lowest-x (then lowest-y) point. Fewer than 3 points come back when the input
// is degenerate (all equal: 1 point; all collinear: the 2 extreme points).
Ring convex_hull(const Ring& points);

// The same, as indices into points (an index is returned once even if its point repeats).
std::vector<std::size_t> convex_hull_indices(const Ring& points);

// The same indices as convex_hull_indices(ring) when ring is a simple polygon without repeated
// vertices (either orientation), in linear time (Melkman's algorithm). Falls back to
// convex_hull_indices when its first vertices are degenerate.
std::vector<std::size_t> simple_polygon_hull_indices(const Ring& ring);
// The same, for a caller that knows a vertex of the hull (an extreme point): the scan starts there
// instead of searching for one. A hull_vertex out of range (>= ring.size()) is searched for.
std::vector<std::size_t> simple_polygon_hull_indices(const Ring& ring, std::size_t hull_vertex);
// The same, into hull, whose storage is reused: for a caller that takes many hulls.
void simple_polygon_hull_indices(const Ring& ring, std::size_t hull_vertex,
                                 std::vector<std::size_t>& hull);

// The orientation of a simple ring, exactly: +1 counter-clockwise, -1 clockwise, 0 for none (no
// turn at its lowest vertex, or fewer than 3 vertices).
int ring_orientation(const Ring& ring);

// Whether ring is a strictly convex counter-clockwise polygon: every turn strictly left (exact
// predicate) and the edges' directions turning once round, so that x and y each change their
// direction at most twice (a ring turning left everywhere but winding twice, as a pentagram's
// vertices in star order, changes each four times). Such a ring is simple.
bool is_strictly_convex_ccw(const Ring& ring);

enum class Location { outside, boundary, inside };

// Where p lies with respect to the closed ring (either orientation), exactly.
Location locate_point(const Ring& ring, Vec2 p);

// locate_point for many points in one ring: the same answers, looking only at the edges whose
// y range holds the point's y (filed by horizontal bands). For a ring of n edges it files edges
// at most 8n times, in n bands or, where edges span more, in a quarter as many, and so on (the
// filings counted again each time: O(n log n) at most), else keeps a plain scan. It refers to
// the ring, which must outlive it unchanged.
class RingLocator {
 public:
  explicit RingLocator(const Ring& ring);
  Location locate(Vec2 p) const;

 private:
  std::size_t band_of(double y) const;
  const Ring& ring_;
  double low_y_ = 0.0, band_height_ = 0.0;
  std::size_t bands_ = 0;         // 0: a plain scan of the ring
  Buckets<std::uint32_t> edges_;  // per band; edge i runs from vertex i - 1 (cyclic) to vertex i
};

// Where p lies with respect to the region: inside the outer ring and outside every hole.
Location locate_point(const Region& region, Vec2 p);

// The cross product's z of a and b [units²]: twice the signed area of the triangle (0, a, b),
// positive when b turns left of a. Rounded: a magnitude (a depth, an area); signs that decide
// topology come from orient2d.
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// The largest absolute coordinate of the points [units], 0 for none: the scale that their
// rounding errors are relative to.
inline double largest_coordinate(const std::vector<Vec2>& points) {
  double largest = 0.0;
  for (Vec2 p : points) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  return largest;
}

// Euclidean distance from p to the closed segment ab [units].
double point_segment_distance(Vec2 p, Vec2 a, Vec2 b);

// Its square [units²], as it is before the square root: the least of several distances is the
// square root of the least square, exactly (a correctly rounded square root is monotone), so a
// search takes one square root instead of one per segment.
inline double point_segment_distance_squared(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = ab.x * ab.x + ab.y * ab.y;
  double t = length2 > 0.0 ? ((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / length2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  const Vec2 d = p - (a + ab * t);
  return d.x * d.x + d.y * d.y;
}

// The point of the closed segment ab nearest to p: its parameter (0 at a, 1 at b; exactly 0 or 1
// when it is an end) and its distance from p [units].
struct SegmentProjection {
  double along;
  double distance;
};
SegmentProjection project_on_segment(Vec2 p, Vec2 a, Vec2 b);

struct Circle {
  Vec2 center{0.0, 0.0};
  double radius = 0.0;  // [units]
};

// Minimum enclosing circle of the points (Welzl's algorithm, iterative, fixed shuffle seed so the
// result is deterministic). An empty input gives radius 0.
Circle minimum_enclosing_circle(const Ring& points);

// Radius R of the minimum enclosing circle of every outer boundary [units].
double enclosing_radius(const std::vector<Region>& regions);

}  // namespace hullcook
