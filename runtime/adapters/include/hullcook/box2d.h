// hullcook::box2d: cooked hulls as Box2D 2.4 fixtures. Links hullcook::runtime and box2d::box2d.
// No exceptions, no heap allocation of its own (Box2D allocates fixtures in its block allocator).
#pragma once

#include "hullcook/runtime.h"

#include <box2d/box2d.h>

#include <cstddef>

namespace hullcook::box2d {

// What create_fixtures() did.
struct FixtureReport {
  std::size_t created = 0;  // fixtures added to the body, one per hull not skipped
  // Hulls Box2D could not take unchanged: more than b2_maxPolygonVertices vertices, or vertices
  // closer than its weld distance (0.5 b2_linearSlop) after placement. Box2D still got them,
  // reduced to its own hull; cook with --max-verts 8 and the default weld so that this stays 0.
  std::size_t altered = 0;
  // Hulls Box2D would refuse (see takes_polygon), given no fixture: a placement scale so small,
  // or a bundle cooked with so small a weld, that a hull shrinks to a point or a line at Box2D's
  // weld distance. Expect 0 at the scale the bundle was cooked for (--ppu).
  std::size_t skipped = 0;
};

// Whether b2PolygonShape::Set can take hull, placed (scale, mirror): at least 3 of its first
// b2_maxPolygonVertices vertices stay apart at Box2D's weld distance (0.5 b2_linearSlop) and
// span an area. Set asserts on any other polygon (SIGABRT where, as in Debian's package,
// Box2D is built with assertions).
bool takes_polygon(const runtime::Hull& hull, runtime::Placement placement = {});

// Sets shape to hull, placed (scale, mirror). Returns true when Box2D kept every vertex (the
// shape's m_count equals the hull's vertex count), false when it welded or dropped some, or
// when the hull has more than b2_maxPolygonVertices vertices (then the first 8 are used), or
// when Box2D cannot take it at all (takes_polygon; then shape is left as it was).
bool set_polygon(const runtime::Hull& hull, b2PolygonShape& shape,
                 runtime::Placement placement = {});

// Creates one b2PolygonShape fixture per hull of level on body. Each fixture is a copy of
// fixture_template (its shape is replaced) with, when use_asset_physics is set and the asset
// has physics properties, its density (converted from kg per output unit² to kg per game unit²
// with the placement's scale), friction, restitution, isSensor and filter category and mask bits
// taken from the asset. A hull Box2D cannot take (takes_polygon) gets no fixture (skipped). The
// fixtures' own densities then give the body its mass, centre and rotational inertia (Box2D's
// b2Body::ResetMassData, called by CreateFixture). Must not be called during a world step (Box2D's
// rule). level must belong to asset.
FixtureReport create_fixtures(b2Body* body, const runtime::Asset& asset,
                              const runtime::Level& level, const b2FixtureDef& fixture_template,
                              runtime::Placement placement = {}, bool use_asset_physics = true);

}  // namespace hullcook::box2d
