// hullcook_drop_chipmunk BUNDLE.hcb: drops the bundle's sprites onto its terrain in Chipmunk 7
// and prints where each body came to rest. Exit 0, 1 on usage, 2 on a bad bundle.
#include "drop_scene.h"

#include "hullcook/chipmunk.h"

#include <cstdio>

int main(int argc, char** argv) {
  using namespace hullcook;
  samples::Options options;
  if (!samples::parse(argc, argv, options)) return 1;
  runtime::MappedFile file;
  runtime::Bundle bundle;
  if (!samples::open_bundle(options, file, bundle)) return 2;
  std::vector<samples::Placed> placed;
  const float floor_y = samples::lay_out(bundle, options, placed);

  cpSpace* space = cpSpaceNew();
  cpSpaceSetGravity(space, cpv(0, -10));
  cpSpaceSetIterations(space, 20);
  cpSpaceSetCollisionSlop(space, 0.005);
  cpSpaceSetSleepTimeThreshold(space, 0.5);
  cpShape* floor = cpSpaceAddShape(
      space,
      cpSegmentShapeNew(cpSpaceGetStaticBody(space), cpv(-1e4, floor_y), cpv(1e4, floor_y), 0));
  cpShapeSetFriction(floor, 0.6);

  std::vector<cpBody*> bodies;
  std::size_t altered = 0;
  chipmunk::ShapeOptions shape_options;
  shape_options.placement = {options.scale, false};
  shape_options.friction = 0.6;
  for (const samples::Placed& p : placed) {
    cpBody* body = cpSpaceAddBody(space, p.terrain ? cpBodyNewStatic() : cpBodyNew(0, 0));
    cpBodySetPosition(body, cpv(p.x, p.y));
    altered += chipmunk::add_shapes(space, body, p.asset, p.level, shape_options).altered;
    bodies.push_back(body);
  }
  const int steps = static_cast<int>(options.seconds * 60.0f);
  for (int i = 0; i < steps; ++i) cpSpaceStep(space, 1.0 / 60.0);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (placed[i].terrain) continue;
    const cpVect position = cpBodyGetPosition(bodies[i]);
    samples::print_rest(placed[i], static_cast<float>(position.x), static_cast<float>(position.y),
                        static_cast<float>(cpBodyGetAngle(bodies[i])),
                        cpBodyIsSleeping(bodies[i]) == cpTrue);
  }
  std::printf("chipmunk: %zu bodies, %zu hulls altered by Chipmunk\n", placed.size(), altered);
  hullcook::chipmunk::free_space_and_contents(space);
  return 0;
}
