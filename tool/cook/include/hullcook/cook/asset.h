// What the cooker produces for one asset, before any writer turns it into bytes.
// Every writer (debug JSON, .hcb bundle, glTF) reads this and nothing else.
#pragma once

#include "hullcook/core/polygon.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace hullcook {

// Maps input units (pixels, or .poly units) to output units:
//   out = (in - origin) * scale, then y negated if flip_y.
struct Transform {
  double scale = 1.0;
  Vec2 origin{0.0, 0.0};
  bool flip_y = false;

  Vec2 apply(Vec2 in) const {
    Vec2 out = (in - origin) * scale;
    if (flip_y) out.y = -out.y;
    return out;
  }
};

// The largest density, friction or restitution: they are stored as f32 (they must also be
// finite and non-negative).
inline constexpr double kMaxPhysicsValue = 3.4028234663852886e38;  // FLT_MAX

// Optional per-asset physics properties, passed through to the engines.
struct PhysicsProperties {
  float density = 1.0f;      // [kg/unit²]
  float friction = 0.2f;     // unitless, Box2D's default
  float restitution = 0.0f;  // unitless
  bool sensor = false;
  std::uint16_t category_bits = 0x0001;
  std::uint16_t mask_bits = 0xFFFF;
};

// One approximately convex piece of the decomposition.
struct CookedPiece {
  Region component;          // [output units] the piece of the input polygon
  Ring hull;                 // [output units] its convex hull (after engine constraints), CCW
  double concavity;          // [output units] under the asset's measure
  std::uint32_t region = 0;  // the index of the outline's region the piece was cut from
};

// One level of detail: the hulls of the decomposition at tolerance tau.
struct CookedLevel {
  double tau = 0.0;         // [output units]
  std::vector<Ring> hulls;  // [output units] convex, CCW, no repeated or collinear vertex
};

struct CookedStats {
  std::size_t traced_vertices = 0;
  std::size_t pieces = 0;
  std::size_t hulls = 0;       // of the finest level, counted before any writer takes them
  double max_concavity = 0.0;  // [output units]
  double convexity = 1.0;      // Eq. 9 of the paper: Σ area(C) / Σ area(hull(C))
  double decompose_ms = 0.0;
  double decode_ms = 0.0;  // reading and decoding the image file
  double trace_ms = 0.0;   // tracing and simplifying the outline, decoding excluded
  double limits_ms = 0.0;  // fitting hulls to the engine limits (--max-verts, --weld), every level
  double contract_ms = 0.0;  // checking the output's contract, every level
  double total_ms = 0.0;
};

// Where an asset's pixels lie in an image file, for drawing them (the HTML report): the whole
// image, a --grid cell, or a sheet's frame (trimmed, maybe stored turned 90° clockwise, placed in
// its untrimmed frame of image_width x image_height).
struct SpriteCutout {
  std::string image;               // the image file; empty for an asset read from a .poly file
  int x = 0, y = 0;                // [px] the top left of the stored pixels in the image
  int width = 0, height = 0;       // [px] the sprite upright (stored height wide when rotated)
  bool rotated = false;            // stored turned 90° clockwise
  int offset_x = 0, offset_y = 0;  // [px] the sprite's top left in the asset's frame
  std::optional<std::array<std::uint8_t, 3>> color_key;  // RGB traced as transparent (--color-key)
};

// Whether pixels per unit stores as a positive, finite 32-bit float, as bundles and glTF keep it:
// below the smallest float it would be stored as 0 (issue 19's fuzzing of link found such a
// bundle, which the runtime refuses). The cook, the writers and the readers of fragments and
// glTF ask it alike.
inline bool stores_as_positive_float(double pixels_per_unit) {
  const float stored = static_cast<float>(pixels_per_unit);
  return stored > 0.0f && stored <= std::numeric_limits<float>::max();
}

struct CookedAsset {
  std::string name;      // path relative to the input root, '/'-separated
  std::string source;    // the file it came from, as given
  int image_width = 0;   // [px] 0 when the input is a polygon file
  int image_height = 0;  // [px]
  SpriteCutout cutout;
  double pixels_per_unit = 1.0;
  Vec2 pivot{0.5, 0.5};  // normalised image coordinates of the output origin
  Transform transform;
  double tau = 0.0;                 // [output units] of the finest level
  std::string measure = "h1";       // sl | sp | h1 | h2
  std::vector<Region> regions;      // [output units] the input after clean-up
  std::vector<CookedPiece> pieces;  // the finest level, with components
  std::vector<CookedLevel> levels;  // finest first; levels[0] holds the pieces' hulls
  std::optional<PhysicsProperties> physics;
  std::optional<double> quantization_error;  // [output units] when read back from a bundle
  // A --tile cell: the bundle quantizes it on a grid of half pixels divided by a power of two,
  // so that its cell's borders (hulls snapped onto them) are stored exactly.
  bool tile = false;
  // A --grid cell or a sheet's frame: one of the assets of source, which messages name too.
  bool part_of_source = false;
  // --lod levels finer than --max-pieces' level, which the asset does not have.
  std::size_t lods_left_out = 0;
  std::vector<std::string> warnings;
  CookedStats stats;
};

// The asset as errors and warnings name it: its source, and for a --grid cell or a sheet's frame
// also its name ("tiles.png (asset tiles.png/12)"), since points in a message are the cell's.
inline std::string described(const CookedAsset& asset) {
  return asset.part_of_source ? asset.source + " (asset " + asset.name + ")" : asset.source;
}

}  // namespace hullcook
