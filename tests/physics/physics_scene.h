// A small hand-made scene for the engine tests: flat cooked terrain and two sprites whose
// silhouettes are known exactly, written with write_bundle() and opened with the runtime.
#pragma once

#include "../formats/synthetic_assets.h"
#include "hullcook/cook/bundle_writer.h"
#include "hullcook/runtime.h"

#include <cmath>

#include <string>
#include <vector>

namespace hullcook::test {

// 32 px per metre; τ = 1 px.
inline constexpr double kPixelsPerUnit = 32.0;
inline constexpr double kTau = 1.0 / kPixelsPerUnit;

// Top surface of the terrain: y = 0 for x in [-20, 20] [m].
inline Ring ground_hull() { return {{-20, -1}, {20, -1}, {20, 0}, {-20, 0}}; }

// "props/house": a 1 m box with a roof; the silhouette is a pentagon of area 1 m².
inline Ring house_silhouette() {
  return {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.25}, {0, 0.75}, {-0.5, 0.25}};
}
inline std::vector<Ring> house_hulls() {
  return {{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.25}, {-0.5, 0.25}},
          {{-0.5, 0.25}, {0.5, 0.25}, {0, 0.75}}};
}
// The top of the house at x in [-0.5, 0.5] [m], in its own frame.
inline double house_top(double x) { return x < 0 ? 0.75 + x : 0.75 - x; }

// "props/ell": an L of two boxes; area 1 + 0.5 = 1.5 m²; bottom at y = -0.5.
inline Ring ell_silhouette() {
  return {{-1, -0.5}, {1, -0.5}, {1, 0}, {-0.5, 0}, {-0.5, 1}, {-1, 1}};
}
inline std::vector<Ring> ell_hulls() {
  return {{{-1, -0.5}, {1, -0.5}, {1, 0}, {-1, 0}}, {{-1, 0}, {-0.5, 0}, {-0.5, 1}, {-1, 1}}};
}

inline CookedAsset scene_asset(const std::string& name, std::vector<Ring> hulls,
                               double coarse_tau) {
  CookedAsset asset;
  asset.name = name;
  asset.image_width = 64;
  asset.image_height = 64;
  asset.pixels_per_unit = kPixelsPerUnit;
  asset.tau = kTau;
  asset.transform.scale = 1.0 / kPixelsPerUnit;
  asset.transform.flip_y = true;
  asset.levels.push_back({kTau, hulls});
  if (coarse_tau > 0) asset.levels.push_back({coarse_tau, {hulls.front()}});
  return asset;
}

inline std::string scene_bundle() {
  std::vector<CookedAsset> assets;
  assets.push_back(scene_asset("props/ell.png", ell_hulls(), 0.0));
  CookedAsset house = scene_asset("props/house.png", house_hulls(), 0.25);
  house.physics = PhysicsProperties{2.0f, 0.5f, 0.0f, false, 0x0002, 0xFFFF};
  assets.push_back(house);
  assets.push_back(scene_asset("terrain/ground.png", {ground_hull()}, 0.0));
  return write_bundle(assets);
}

// A bundle of one asset, name, whose one level holds hulls; opened (check opened) and kept with
// its bytes, which the bundle reads in place.
struct HullsBundle {
  HullsBundle(const std::string& name, std::vector<Ring> hulls)
      : bytes(write_bundle({scene_asset(name, std::move(hulls), 0.0)})),
        opened(bundle.open(bytes.data(), bytes.size()) == runtime::Status::ok),
        asset(bundle.find(name)) {}
  std::string bytes;
  runtime::Bundle bundle;
  bool opened;
  runtime::Asset asset;
};

inline double ring_area(const Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

inline Vec2 ring_centroid(const Ring& ring) {
  double twice = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    const double c = a.x * b.y - a.y * b.x;
    twice += c;
    cx += (a.x + b.x) * c;
    cy += (a.y + b.y) * c;
  }
  return {cx / (3 * twice), cy / (3 * twice)};
}

inline double ring_perimeter(const Ring& ring) {
  double length = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 d = ring[(i + 1) % ring.size()] - ring[i];
    length += std::hypot(d.x, d.y);
  }
  return length;
}

}  // namespace hullcook::test
