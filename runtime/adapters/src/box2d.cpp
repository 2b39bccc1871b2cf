#include "hullcook/box2d.h"

namespace hullcook::box2d {

bool set_polygon(const runtime::Hull& hull, b2PolygonShape& shape, runtime::Placement placement) {
  const std::size_t count = hull.vertex_count();
  const std::size_t used = count < b2_maxPolygonVertices ? count : b2_maxPolygonVertices;
  b2Vec2 vertices[b2_maxPolygonVertices];
  for (std::size_t i = 0; i < used; ++i) {
    const runtime::Vec2 p = hull.placed_vertex(i, placement);
    vertices[i].Set(p.x, p.y);
  }
  shape.Set(vertices, static_cast<int32>(used));
  return static_cast<std::size_t>(shape.m_count) == count;
}

FixtureReport create_fixtures(b2Body* body, const runtime::Asset& asset,
                              const runtime::Level& level, const b2FixtureDef& fixture_template,
                              runtime::Placement placement, bool use_asset_physics) {
  FixtureReport report;
  if (body == nullptr) return report;
  b2FixtureDef definition = fixture_template;
  if (use_asset_physics && asset.has_physics()) {
    const runtime::Physics physics = asset.physics();
    definition.density = physics.density;
    definition.friction = physics.friction;
    definition.restitution = physics.restitution;
    definition.isSensor = physics.sensor;
    definition.filter.categoryBits = physics.category_bits;
    definition.filter.maskBits = physics.mask_bits;
  }
  b2PolygonShape shape;
  definition.shape = &shape;
  for (std::size_t h = 0; h < level.hull_count(); ++h) {
    if (!set_polygon(level.hull(h), shape, placement)) ++report.altered;
    body->CreateFixture(&definition);
    ++report.created;
  }
  return report;
}

}  // namespace hullcook::box2d
