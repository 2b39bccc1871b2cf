// A deterministic set of cooked assets for bundle tests and golden files: every feature of the
// format (levels, physics, empty levels, a UTF-8 name, thin and near-degenerate hulls).
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/runtime.h"

#include <cmath>
#include <string>
#include <vector>

namespace hullcook::test {

// A regular polygon, counter-clockwise [output units].
inline Ring regular_polygon(Vec2 centre, double radius, int sides, double phase = 0.0) {
  Ring ring;
  for (int i = 0; i < sides; ++i) {
    const double angle = phase + 2.0 * M_PI * i / sides;
    ring.push_back(centre + Vec2{radius * std::cos(angle), radius * std::sin(angle)});
  }
  return ring;
}

inline Ring rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

inline CookedAsset make_asset(std::string name, std::vector<CookedLevel> levels,
                              double pixels_per_unit = 1.0, int width = 0, int height = 0) {
  CookedAsset asset;
  asset.name = std::move(name);
  asset.source = asset.name;
  asset.image_width = width;
  asset.image_height = height;
  asset.pixels_per_unit = pixels_per_unit;
  asset.levels = std::move(levels);
  asset.tau = asset.levels.empty() ? 0.0 : asset.levels[0].tau;
  asset.transform.scale = 1.0 / pixels_per_unit;
  asset.transform.flip_y = true;
  return asset;
}

inline std::vector<CookedAsset> synthetic_assets() {
  std::vector<CookedAsset> assets;
  assets.push_back(make_asset("box", {{0.0, {rectangle(-1, -1, 1, 1)}}}));

  CookedAsset crate = make_asset(
      "props/crate.png",
      {{2.0 / 32, {rectangle(-1, -0.75, 1, 0.75)}}, {8.0 / 32, {rectangle(-1, -0.75, 1, 0.75)}}},
      32.0, 64, 48);
  crate.pivot = {0.5, 1.0};
  crate.measure = "sp";
  crate.transform.flip_y = false;
  crate.physics = PhysicsProperties{2.5f, 0.6f, 0.1f, false, 0x0002, 0xFFFD};
  assets.push_back(crate);

  // A hill: a fine level of several convex pieces, a coarser one, and the coarsest as one hull.
  std::vector<Ring> fine, medium;
  for (int i = 0; i < 6; ++i) {
    const double x0 = 20.0 * i - 60.0, x1 = x0 + 20.0;
    const double h0 = 30.0 - std::fabs(x0) * 0.4, h1 = 30.0 - std::fabs(x1) * 0.4;
    fine.push_back({{x0, 0.0}, {x1, 0.0}, {x1, h1}, {x0, h0}});
  }
  medium.push_back({{-60, 0}, {0, 0}, {0, 30}, {-60, 6}});
  medium.push_back({{0, 0}, {60, 0}, {60, 6}, {0, 30}});
  CookedAsset hill = make_asset(
      "terrain/hill.png",
      {{2.0, fine}, {8.0, medium}, {24.0, {{{-60, 0}, {60, 0}, {60, 6}, {0, 30}, {-60, 6}}}}}, 1.0,
      128, 32);
  assets.push_back(hill);

  // Nasty hulls: a thin sliver and a near-collinear octagon arc.
  assets.push_back(make_asset("nasty/sliver",
                              {{0.5,
                                {{{0.0, 0.0}, {100.0, 0.01}, {100.0, 0.05}},
                                 {{0, 0}, {10, 1e-4}, {20, 3e-4}, {30, 7e-4}, {30, 2}, {0, 2}},
                                 regular_polygon({5, 5}, 3.0, 8, 0.1)}}},
                              4.0, 400, 8));
  assets.push_back(make_asset("empty.png", {}, 1.0, 16, 16));
  assets.push_back(make_asset("unicode/\xE5\x90\x8D\xE5\x89\x8D.png",  // 名前.png
                              {{1.0, {regular_polygon({0, 0}, 10.0, 5)}}}, 2.0, 40, 40));
  return assets;
}

// Every vertex of an opened asset's levels, to walk all data (used after fuzzed opens).
inline double touch_everything(const runtime::Bundle& bundle) {
  double sum = 0.0;
  for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
    const runtime::Asset asset = bundle.asset(a);
    sum += static_cast<double>(asset.name().size()) + asset.pixels_per_unit();
    sum += asset.physics().density;
    for (std::size_t l = 0; l < asset.level_count(); ++l) {
      const runtime::Level level = asset.level(l);
      for (std::size_t h = 0; h < level.hull_count(); ++h) {
        const runtime::Hull hull = level.hull(h);
        for (std::size_t v = 0; v < hull.vertex_count(); ++v) sum += hull.vertex(v).x;
        sum += hull.area();
      }
    }
    sum += bundle.find(asset.name()).index();
  }
  return sum;
}

}  // namespace hullcook::test
