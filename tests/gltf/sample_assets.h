// Hand-made cooked assets for the glTF writer's tests and its validator run.
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/cook/cook.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace hullcook::test {

// A regular polygon, counter-clockwise [output units]. The phase keeps the coordinates away from
// round numbers, so that an exact round trip of doubles means something.
inline Ring regular_polygon(Vec2 center, double radius, int sides, double phase = 0.1234567) {
  Ring ring;
  for (int i = 0; i < sides; ++i) {
    double angle = phase + 2.0 * std::numbers::pi * i / sides;
    ring.push_back(center + radius * Vec2{std::cos(angle), std::sin(angle)});
  }
  return ring;
}

inline CookedAsset base_asset(const std::string& name) {
  CookedAsset asset;
  asset.name = name;
  asset.source = "sprites/" + name + ".png";
  asset.image_width = 64;
  asset.image_height = 48;
  asset.pixels_per_unit = 32.0;
  asset.pivot = {0.5, 0.25};
  asset.transform = {1.0 / 32.0, {32.0, 36.0}, true};
  asset.tau = 0.0625;
  asset.measure = "h1";
  return asset;
}

// One square hull and a coarser level with a triangle.
inline CookedAsset box_asset() {
  CookedAsset asset = base_asset("box");
  asset.levels.push_back(
      {asset.tau, {{{-1.0, -0.5}, {1.0 / 3.0, -0.5}, {1.0 / 3.0, 0.1}, {-1.0, 0.1}}}});
  asset.levels.push_back({0.5, {{{-1.0, -0.5}, {1.0 / 3.0, -0.5}, {-1.0, 0.1}}}});
  return asset;
}

// Many hulls (a grid of hexagons and octagons), two levels.
inline CookedAsset many_hulls_asset(int count = 150) {
  CookedAsset asset = base_asset("dir/many");
  CookedLevel fine{asset.tau, {}};
  for (int i = 0; i < count; ++i) {
    Vec2 center{0.37 * (i % 15) - 2.5, 0.41 * (i / 15) - 1.75};
    fine.hulls.push_back(regular_polygon(center, 0.15 + 0.001 * i, i % 2 ? 6 : 8, 0.01 * i + 0.3));
  }
  asset.levels.push_back(std::move(fine));
  asset.levels.push_back({0.25, {regular_polygon({0.0, 0.0}, 3.0, 8)}});
  return asset;
}

// Physics properties with a non-default collision filter.
inline CookedAsset physics_asset() {
  CookedAsset asset = base_asset("crate");
  asset.levels.push_back(
      {asset.tau, {regular_polygon({0.25, 0.5}, 0.75, 5), regular_polygon({1.5, 0.5}, 0.5, 7)}});
  asset.physics = PhysicsProperties{};
  asset.physics->density = 2.5f;
  asset.physics->friction = 0.6f;
  asset.physics->restitution = 0.3f;
  asset.physics->category_bits = 0x0006;
  asset.physics->mask_bits = 0x00F1;
  return asset;
}

// A sensor: its hulls become triggers.
inline CookedAsset sensor_asset() {
  CookedAsset asset = base_asset("zone");
  asset.levels.push_back({asset.tau, {regular_polygon({0.0, 0.0}, 2.0, 4)}});
  asset.physics = PhysicsProperties{};
  asset.physics->sensor = true;
  asset.physics->mask_bits = 0;
  return asset;
}

// An asset that traced to nothing: one level without hulls.
inline CookedAsset empty_asset() {
  CookedAsset asset = base_asset("blank");
  asset.levels.push_back({asset.tau, {}});
  return asset;
}

inline std::vector<CookedAsset> all_sample_assets() {
  return {box_asset(), many_hulls_asset(), physics_asset(), sensor_asset(), empty_asset()};
}

// samples/sprites cooked at --tau 2 --ppu 32 with the given extra levels (the figures of issue 20
// are without; scripts/cook-samples adds 8 and 0.5).
inline std::vector<CookedAsset> sample_sprites(std::vector<Tolerance> lods = {}) {
  Settings settings;
  settings.tau = Tolerance{2.0, false};
  settings.lods = std::move(lods);
  settings.pixels_per_unit = 32;
  return cook({std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/sprites"}, settings).assets;
}

inline std::size_t vertex_count(const std::vector<CookedAsset>& assets) {
  std::size_t vertices = 0;
  for (const CookedAsset& asset : assets) {
    for (const CookedLevel& level : asset.levels) {
      for (const Ring& hull : level.hulls) vertices += hull.size();
    }
  }
  return vertices;
}

// The grid step --meshopt may use at most: the bundle's (formats/SPEC.md §9), with the asset's
// whole extent in place of the largest hull's.
inline double largest_meshopt_step(const CookedAsset& asset) {
  double min_x = 1e300, min_y = 1e300, max_x = -1e300, max_y = -1e300;
  for (const CookedLevel& level : asset.levels) {
    for (const Ring& hull : level.hulls) {
      for (const Vec2& v : hull) {
        min_x = std::min(min_x, v.x), max_x = std::max(max_x, v.x);
        min_y = std::min(min_y, v.y), max_y = std::max(max_y, v.y);
      }
    }
  }
  return std::max({std::sqrt(2.0) * 0.01 * asset.levels.front().tau,
                   std::sqrt(2.0) / (64.0 * asset.pixels_per_unit),
                   std::max(max_x - min_x, max_y - min_y) / 65000.0});
}

}  // namespace hullcook::test
