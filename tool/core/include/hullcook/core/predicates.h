// Geometric predicates whose sign is exact for every finite double input.
#pragma once

#include "hullcook/core/polygon.h"

namespace hullcook {

// Twice the signed area of triangle abc [units²]: positive when a, b, c turn counter-clockwise,
// negative clockwise, zero exactly when they are collinear. The sign is exact (Shewchuk-style
// filter with an exact expansion fallback); the magnitude is approximate when tiny.
// Exactness assumes the products do not underflow (|coordinates| well above 1e-150).
double orient2d(Vec2 a, Vec2 b, Vec2 c);

// -1, 0 or +1: the exact sign of orient2d(a, b, c).
int orientation(Vec2 a, Vec2 b, Vec2 c);

// Whether some vertex of ring turns left (exact): false for a ring of fewer than 3 vertices, one
// flattened to a line or a point, and one that turns only clockwise.
bool turns_left_somewhere(const Ring& ring);

// Whether ring, its consecutive repeated points taken as one, bounds a convex polygon counter-
// clockwise where vertices may be collinear (exact turns): it never turns right, never doubles
// back, turns left somewhere and winds once. What a reader may hold a convex hull as.
bool is_weakly_convex(const Ring& ring);

// Twice the signed area of ring [units²], summed exactly but for a final rounding: each product
// of the shoelace split into its rounded value and its error, the terms added with their errors
// carried (a compensated sum). A long thin ring's area is a small difference of large products,
// which signed_area's plain sum rounds by far more than a billionth of it.
double accurate_twice_area(const Ring& ring);

// Twice the region's area [units²] (its outer ring's, less its holes', whichever their
// orientations), summed the same way in one sum.
double accurate_twice_area(const Region& region);

// True when p lies on the closed segment ab (exact, for finite points).
bool on_segment(Vec2 a, Vec2 b, Vec2 p);

// True when the closed segments ab and cd share at least one point (exact).
bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// True when ab and cd cross at a single point interior to both (exact).
bool segments_cross_properly(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

}  // namespace hullcook
