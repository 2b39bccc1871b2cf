#include "hullcook/box2d.h"

namespace hullcook::box2d {
namespace {

// The hull's vertices, placed, as Box2D takes them: at most b2_maxPolygonVertices. Returns how
// many were written.
int32 placed_vertices(const runtime::Hull& hull, runtime::Placement placement,
                      b2Vec2 (&vertices)[b2_maxPolygonVertices]) {
  const std::size_t count = hull.vertex_count();
  const std::size_t used = count < b2_maxPolygonVertices ? count : b2_maxPolygonVertices;
  for (std::size_t i = 0; i < used; ++i) {
    const runtime::Vec2 p = hull.placed_vertex(i, placement);
    vertices[i].Set(p.x, p.y);
  }
  return static_cast<int32>(used);
}

// Whether b2PolygonShape::Set takes the vertices without its assertion on a degenerate polygon
// (which aborts the process where Box2D is built with assertions, as Debian's is): at least 3
// left after its weld (points closer than 0.5 b2_linearSlop, taken as Set takes them), spanning
// more than the area its centroid asserts (b2_epsilon), here with a margin for the rounding of
// the two sums.
bool box2d_accepts(const b2Vec2* vertices, int32 count) {
  b2Vec2 kept[b2_maxPolygonVertices];
  int32 n = 0;
  const float weld = 0.5f * b2_linearSlop;
  for (int32 i = 0; i < count; ++i) {
    bool unique = true;
    for (int32 j = 0; j < n && unique; ++j) {
      unique = b2DistanceSquared(vertices[i], kept[j]) >= weld * weld;
    }
    if (unique) kept[n++] = vertices[i];
  }
  if (n < 3) return false;
  float twice_area = 0.0f;  // the hull's vertices are counter-clockwise: a fan from the first
  for (int32 i = 1; i + 1 < n; ++i) twice_area += b2Cross(kept[i] - kept[0], kept[i + 1] - kept[0]);
  return 0.5f * twice_area > 4.0f * b2_epsilon;
}

}  // namespace

bool takes_polygon(const runtime::Hull& hull, runtime::Placement placement) {
  b2Vec2 vertices[b2_maxPolygonVertices];
  return box2d_accepts(vertices, placed_vertices(hull, placement, vertices));
}

bool set_polygon(const runtime::Hull& hull, b2PolygonShape& shape, runtime::Placement placement) {
  b2Vec2 vertices[b2_maxPolygonVertices];
  const int32 used = placed_vertices(hull, placement, vertices);
  if (!box2d_accepts(vertices, used)) return false;
  shape.Set(vertices, used);
  return static_cast<std::size_t>(shape.m_count) == hull.vertex_count();
}

FixtureReport create_fixtures(b2Body* body, const runtime::Asset& asset,
                              const runtime::Level& level, const b2FixtureDef& fixture_template,
                              runtime::Placement placement, bool use_asset_physics) {
  FixtureReport report;
  if (body == nullptr) return report;
  b2FixtureDef definition = fixture_template;
  if (use_asset_physics && asset.has_physics()) {
    const runtime::Physics physics = asset.physics();
    // kg per output unit² -> kg per game unit².
    definition.density = physics.density / (placement.scale * placement.scale);
    definition.friction = physics.friction;
    definition.restitution = physics.restitution;
    definition.isSensor = physics.sensor;
    definition.filter.categoryBits = physics.category_bits;
    definition.filter.maskBits = physics.mask_bits;
  }
  b2PolygonShape shape;
  definition.shape = &shape;
  for (std::size_t h = 0; h < level.hull_count(); ++h) {
    const runtime::Hull hull = level.hull(h);
    if (!takes_polygon(hull, placement)) {
      ++report.skipped;
      continue;
    }
    if (!set_polygon(hull, shape, placement)) ++report.altered;
    body->CreateFixture(&definition);
    ++report.created;
  }
  return report;
}

}  // namespace hullcook::box2d
