#include "hullcook/chipmunk.h"

#include <memory>
#include <new>

namespace hullcook::chipmunk {

ShapeReport add_shapes(cpSpace* space, cpBody* body, const runtime::Asset& asset,
                       const runtime::Level& level, const ShapeOptions& options) {
  ShapeReport report;
  if (space == nullptr || body == nullptr) return report;
  const float scale = options.placement.scale;
  cpFloat density = options.density, friction = options.friction;
  cpFloat elasticity = options.elasticity;
  bool sensor = false;
  cpShapeFilter filter = CP_SHAPE_FILTER_ALL;
  if (options.use_asset_physics && asset.has_physics()) {
    const runtime::Physics physics = asset.physics();
    // kg per output unit² -> kg per game unit².
    density = physics.density / (cpFloat{scale} * scale);
    friction = physics.friction;
    elasticity = physics.restitution;
    sensor = physics.sensor;
    filter = cpShapeFilterNew(CP_NO_GROUP, physics.category_bits, physics.mask_bits);
  }
  for (std::size_t h = 0; h < level.hull_count(); ++h) {
    const runtime::Hull hull = level.hull(h);
    const std::size_t count = hull.vertex_count();
    // Most hulls fit on the stack; a hull of --max-verts 0 may have hundreds of vertices (only
    // the first 64 were given, and Chipmunk made a smaller hull of them).
    cpVect on_stack[runtime::kMaxStackVertices];
    std::unique_ptr<cpVect[]> on_heap;
    cpVect* vertices = on_stack;
    if (count > runtime::kMaxStackVertices) {
      on_heap.reset(new (std::nothrow) cpVect[count]);
      if (!on_heap) {
        ++report.skipped;
        continue;
      }
      vertices = on_heap.get();
    }
    for (std::size_t i = 0; i < count; ++i) {
      const runtime::Vec2 p = hull.placed_vertex(i, options.placement);
      vertices[i] = cpv(p.x, p.y);
    }
    cpShape* shape = cpPolyShapeNew(body, static_cast<int>(count), vertices, cpTransformIdentity,
                                    options.radius);
    if (static_cast<std::size_t>(cpPolyShapeGetCount(shape)) != count) ++report.altered;
    cpShapeSetFriction(shape, friction);
    cpShapeSetElasticity(shape, elasticity);
    cpShapeSetSensor(shape, sensor ? cpTrue : cpFalse);
    cpShapeSetFilter(shape, filter);
    // After the filter: setting the density makes the body accumulate its mass from the shape.
    cpShapeSetDensity(shape, density);
    cpSpaceAddShape(space, shape);
    report.area += cpShapeGetArea(shape);
    ++report.created;
  }
  return report;
}

void free_space_and_contents(cpSpace* space) {
  if (!space) return;
  // Removal inside the iteration is only allowed from post-step callbacks.
  cpSpaceEachShape(
      space,
      [](cpShape* shape, void* s) {
        cpSpaceAddPostStepCallback(
            static_cast<cpSpace*>(s),
            [](cpSpace* sp, void* sh, void*) {
              cpSpaceRemoveShape(sp, static_cast<cpShape*>(sh));
              cpShapeFree(static_cast<cpShape*>(sh));
            },
            shape, nullptr);
      },
      space);
  cpSpaceEachBody(
      space,
      [](cpBody* body, void* s) {
        cpSpaceAddPostStepCallback(
            static_cast<cpSpace*>(s),
            [](cpSpace* sp, void* b, void*) {
              cpSpaceRemoveBody(sp, static_cast<cpBody*>(b));
              cpBodyFree(static_cast<cpBody*>(b));
            },
            body, nullptr);
      },
      space);
  cpSpaceStep(space, 0.0);  // runs the post-step removals
  cpSpaceFree(space);
}

}  // namespace hullcook::chipmunk
