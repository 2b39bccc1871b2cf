// hullcook::chipmunk: cooked hulls as Chipmunk 7 polygon shapes. Links hullcook::runtime and
// Chipmunk::Chipmunk. No exceptions; Chipmunk allocates the shapes, and add_shapes the copy of a
// hull of more than runtime::kMaxStackVertices vertices (--max-verts 0) that it gives Chipmunk.
#pragma once

#include "hullcook/runtime.h"

#include <chipmunk/chipmunk.h>

#include <cstddef>

namespace hullcook::chipmunk {

// What add_shapes() did.
struct ShapeReport {
  std::size_t created = 0;  // cpPolyShapes attached to the body, one per hull
  std::size_t altered = 0;  // hulls whose vertex count Chipmunk's own hull changed (expect 0)
  std::size_t skipped = 0;  // hulls of over 64 vertices whose copy could not be allocated
  double area = 0.0;        // [game units²] total area of the placed hulls
};

// Options for add_shapes().
struct ShapeOptions {
  runtime::Placement placement{};
  cpFloat radius = 0.0;           // [game units] Chipmunk's rounding radius of each polygon
  cpFloat density = 1.0;          // [kg / game unit²] used unless the asset's physics apply
  bool use_asset_physics = true;  // take density, friction, restitution, sensor, filter from
                                  // the asset when it has physics properties
  cpFloat friction = 0.7;         // used unless the asset's physics apply
  cpFloat elasticity = 0.0;       // used unless the asset's physics apply
};

// Creates one cpPolyShape per hull of level on body and adds it to space (both must not be null;
// nothing is created otherwise: Chipmunk attaches a shape to its body only when the shape is
// added to a space, and the space frees nothing, so remove and free the shapes as usual, e.g.
// with cpBodyEachShape). Each shape gets a density, so that Chipmunk accumulates the body's
// mass, centre of gravity and moment of inertia from the hulls themselves (set cpBodySetMass/
// Moment afterwards to override). The asset's density is in kg per output unit²; it is converted
// to game units with the placement scale. Must not be called while the space is locked (during
// cpSpaceStep).
// Chipmunk's cpPolyShapeNew copies each hull onto the calling thread's stack (alloca, 16 bytes a
// vertex) to take its hull: a bundle cooked with --max-verts 0 may hold hulls of thousands of
// vertices, which need that much stack (160 KB for 10,000).
ShapeReport add_shapes(cpSpace* space, cpBody* body, const runtime::Asset& asset,
                       const runtime::Level& level, const ShapeOptions& options = {});

// Removes and frees every shape and body in space, then space itself: Chipmunk's cpSpaceFree
// frees neither. space may be null. Must not be called during cpSpaceStep.
void free_space_and_contents(cpSpace* space);

}  // namespace hullcook::chipmunk
