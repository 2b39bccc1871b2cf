// hullcook_drop_box2d BUNDLE.hcb: drops the bundle's sprites onto its terrain, between walls, in
// Box2D 2.4, prints where each body came to rest, and optionally draws it (--svg, --frames).
// Exit 0, 1 on usage, 2 on a bad bundle, 3 when a picture cannot be written.
#include "drop_scene.h"

#include "hullcook/box2d.h"

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

  b2World world(b2Vec2(0.0f, -10.0f));
  b2BodyDef wall_definition;
  b2Body* walls = world.CreateBody(&wall_definition);
  for (const samples::Bounds& wall : samples::walls(scene)) {
    b2PolygonShape box;
    const float half_width = 0.5f * (wall.max_x - wall.min_x);
    const float half_height = 0.5f * (wall.max_y - wall.min_y);
    box.SetAsBox(half_width, half_height, b2Vec2(wall.min_x + half_width, wall.min_y + half_height),
                 0.0f);
    walls->CreateFixture(&box, 0.0f)->SetFriction(0.6f);
  }

  std::vector<b2Body*> bodies;
  std::size_t altered = 0;
  for (const samples::Placed& p : placed) {
    b2BodyDef definition;
    definition.type = p.terrain ? b2_staticBody : b2_dynamicBody;
    definition.position.Set(p.x, p.y);
    b2Body* body = world.CreateBody(&definition);
    b2FixtureDef fixture;
    fixture.density = samples::unit_mass_density(p, options.scale);
    fixture.friction = 0.6f;
    altered +=
        box2d::create_fixtures(body, p.asset, p.level, fixture, {options.scale, false}).altered;
    bodies.push_back(body);
  }
  auto frame = [&] {
    return samples::frame_of(scene, placed, options.scale, [&](std::size_t b, runtime::Vec2 p) {
      const b2Vec2 world_point = bodies[b]->GetWorldPoint(b2Vec2(p.x, p.y));
      return runtime::Vec2{world_point.x, world_point.y};
    });
  };
  const int steps = static_cast<int>(options.seconds * 60.0f);
  samples::Frame checkpoint;
  for (int i = 0; i < steps; ++i) {
    if (i == samples::rest_check_step(steps)) checkpoint = frame();
    if (!options.frames_dir.empty() && i % options.every == 0 &&
        !samples::write_frame(options, i / options.every, frame()))
      return 3;
    // Two substeps per frame: piles of large multi-hull sprites otherwise keep jittering and
    // small hulls sink into their neighbours under the heavy sheets.
    for (int substep = 0; substep < 2; ++substep) world.Step(1.0f / 120.0f, 8, 3);
  }
  const samples::Frame final_frame = frame();
  const std::vector<float> moved = samples::displacements(checkpoint, final_frame);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (placed[i].terrain) continue;
    const b2Vec2 position = bodies[i]->GetPosition();
    samples::print_rest(placed[i], position.x, position.y, bodies[i]->GetAngle(),
                        !bodies[i]->IsAwake(), moved[i]);
  }
  if (!samples::write_final_svg(options, final_frame)) return 3;
  std::printf("scene: x in [%g, %g], floor %g; slop %g\n", scene.min_x, scene.max_x, scene.min_y,
              static_cast<double>(b2_linearSlop));
  std::printf("box2d: %zu bodies, %zu hulls altered by Box2D\n", placed.size(), altered);
  return 0;
}
