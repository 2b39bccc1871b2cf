// hullcook_drop_box2d BUNDLE.hcb: drops the bundle's sprites onto its terrain in Box2D 2.4 and
// prints where each body came to rest. Exit 0, 1 on usage, 2 on a bad bundle.
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
  std::vector<samples::Placed> placed;
  const float floor_y = samples::lay_out(bundle, options, placed);

  b2World world(b2Vec2(0.0f, -10.0f));
  b2BodyDef floor_definition;
  b2Body* floor = world.CreateBody(&floor_definition);
  b2EdgeShape edge;
  edge.SetTwoSided(b2Vec2(-1e4f, floor_y), b2Vec2(1e4f, floor_y));
  floor->CreateFixture(&edge, 0.0f);

  std::vector<b2Body*> bodies;
  std::size_t altered = 0;
  for (const samples::Placed& p : placed) {
    b2BodyDef definition;
    definition.type = p.terrain ? b2_staticBody : b2_dynamicBody;
    definition.position.Set(p.x, p.y);
    b2Body* body = world.CreateBody(&definition);
    b2FixtureDef fixture;
    fixture.density = 1.0f;
    fixture.friction = 0.6f;
    altered +=
        box2d::create_fixtures(body, p.asset, p.level, fixture, {options.scale, false}).altered;
    bodies.push_back(body);
  }
  const int steps = static_cast<int>(options.seconds * 60.0f);
  for (int i = 0; i < steps; ++i) world.Step(1.0f / 60.0f, 8, 3);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (placed[i].terrain) continue;
    const b2Vec2 position = bodies[i]->GetPosition();
    samples::print_rest(placed[i], position.x, position.y, bodies[i]->GetAngle(),
                        !bodies[i]->IsAwake());
  }
  std::printf("box2d: %zu bodies, %zu hulls altered by Box2D\n", placed.size(), altered);
  return 0;
}
