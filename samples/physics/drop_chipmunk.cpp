// hullcook_drop_chipmunk BUNDLE.hcb: drops the bundle's sprites onto its terrain, between walls,
// in Chipmunk 7, prints where each body came to rest, and optionally draws it (--svg, --frames).
// Exit 0, 1 on usage, 2 on a bad bundle, 3 when a picture cannot be written.
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
  if (!samples::prepare_frames(options)) return 3;
  std::vector<samples::Placed> placed;
  const samples::Bounds scene = samples::lay_out(bundle, options, placed);

  cpSpace* space = cpSpaceNew();
  cpSpaceSetGravity(space, cpv(0, -10));
  // Piles of large multi-hull sprites sink into each other with Chipmunk's defaults; more
  // iterations, two substeps per frame and a stiffer correction (half the overlap per 1/60 s)
  // keep every overlap within the slop.
  cpSpaceSetIterations(space, 30);
  cpSpaceSetCollisionSlop(space, 0.005);
  cpSpaceSetCollisionBias(space, cpfpow(1.0 - 0.5, 60.0));
  cpSpaceSetSleepTimeThreshold(space, 0.5);
  for (const samples::Bounds& wall : samples::walls(scene)) {
    cpShape* box = cpSpaceAddShape(
        space, cpBoxShapeNew2(cpSpaceGetStaticBody(space),
                              cpBBNew(wall.min_x, wall.min_y, wall.max_x, wall.max_y), 0));
    cpShapeSetFriction(box, 0.6);
  }

  std::vector<cpBody*> bodies;
  std::size_t altered = 0;
  chipmunk::ShapeOptions shape_options;
  shape_options.placement = {options.scale, false};
  shape_options.friction = 0.6;
  for (const samples::Placed& p : placed) {
    cpBody* body = cpSpaceAddBody(space, p.terrain ? cpBodyNewStatic() : cpBodyNew(0, 0));
    cpBodySetPosition(body, cpv(p.x, p.y));
    // Bodies of 1 kg, as in the Box2D sample: a sheet of hundreds of hulls weighing thousands of
    // small sprites pressed one 0.015 units into its neighbour (3 times the slop).
    shape_options.density = samples::unit_mass_density(p, options.scale);
    altered += chipmunk::add_shapes(space, body, p.asset, p.level, shape_options).altered;
    bodies.push_back(body);
  }
  auto frame = [&] {
    return samples::frame_of(scene, placed, options.scale, [&](std::size_t b, runtime::Vec2 p) {
      const cpVect world_point = cpBodyLocalToWorld(bodies[b], cpv(p.x, p.y));
      return runtime::Vec2{static_cast<float>(world_point.x), static_cast<float>(world_point.y)};
    });
  };
  int status = 0;
  const int steps = static_cast<int>(options.seconds * 60.0f);
  samples::Frame checkpoint;
  for (int i = 0; i < steps && status == 0; ++i) {
    if (i == samples::rest_check_step(steps)) checkpoint = frame();
    if (!options.frames_dir.empty() && i % options.every == 0 &&
        !samples::write_frame(options, i / options.every, frame()))
      status = 3;
    for (int substep = 0; substep < 2; ++substep) cpSpaceStep(space, 1.0 / 120.0);
  }
  if (status == 0) {
    const samples::Frame final_frame = frame();
    const std::vector<float> moved = samples::displacements(checkpoint, final_frame);
    for (std::size_t i = 0; i < placed.size(); ++i) {
      if (placed[i].terrain) continue;
      const cpVect position = cpBodyGetPosition(bodies[i]);
      samples::print_rest(placed[i], static_cast<float>(position.x), static_cast<float>(position.y),
                          static_cast<float>(cpBodyGetAngle(bodies[i])),
                          cpBodyIsSleeping(bodies[i]) == cpTrue, moved[i]);
    }
    if (!samples::write_final_svg(options, final_frame)) status = 3;
  }
  if (status == 0) {
    std::printf("scene: x in [%g, %g], floor %g; slop %g\n", scene.min_x, scene.max_x, scene.min_y,
                cpSpaceGetCollisionSlop(space));
    std::printf("chipmunk: %zu bodies, %zu hulls altered by Chipmunk\n", placed.size(), altered);
  }
  hullcook::chipmunk::free_space_and_contents(space);
  return status;
}
