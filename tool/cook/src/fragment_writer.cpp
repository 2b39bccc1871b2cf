#include "hullcook/cook/fragment.h"

#include "hullcook/format/crc32.h"
#include "hullcook/format/fragment_layout.h"

#include <cstdio>
#include <cstring>
#include <filesystem>

#ifndef HULLCOOK_VERSION
#error "HULLCOOK_VERSION must be defined (tool/cook/CMakeLists.txt)"
#endif

namespace hullcook {
namespace {

using format::FragmentHeader;

// Hexadecimal floating point: exact, and the same text on every host.
std::string exact(double value) {
  char text[64];
  std::snprintf(text, sizeof(text), "%a", value);
  return text;
}

std::string tolerance_text(const Tolerance& tolerance) {
  return exact(tolerance.value) + (tolerance.relative ? " of R" : " units");
}

// Appends the payload's little-endian encoding (FRAGMENT.md §3).
class Encoder {
 public:
  explicit Encoder(std::string& out) : out_(out) {}

  template <typename T>
  void raw(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out_.append(bytes, sizeof(T));
  }
  void u32(std::size_t value) { raw(static_cast<std::uint32_t>(value)); }
  void u64(std::size_t value) { raw(static_cast<std::uint64_t>(value)); }
  void f64(double value) { raw(value); }
  void point(Vec2 point) {
    f64(point.x);
    f64(point.y);
  }
  void string(std::string_view text) {
    u32(text.size());
    out_.append(text);
  }
  void ring(const Ring& ring) {
    u32(ring.size());
    for (Vec2 v : ring) point(v);
  }
  void region(const Region& region) {
    ring(region.outer);
    u32(region.holes.size());
    for (const Ring& hole : region.holes) ring(hole);
  }

 private:
  std::string& out_;
};

void encode_asset(Encoder& out, const CookedAsset& asset) {
  out.string(asset.name);
  // The file name alone: a fragment must not depend on where its input was.
  out.string(std::filesystem::path(asset.source).filename().generic_string());
  out.raw(static_cast<std::int32_t>(asset.image_width));
  out.raw(static_cast<std::int32_t>(asset.image_height));
  out.f64(asset.pixels_per_unit);
  out.point(asset.pivot);
  out.f64(asset.transform.scale);
  out.point(asset.transform.origin);
  std::uint32_t flags = 0;
  if (asset.transform.flip_y) flags |= format::kFragmentFlipY;
  if (asset.physics) flags |= format::kFragmentHasPhysics;
  if (asset.quantization_error) flags |= format::kFragmentHasQuantizationError;
  if (asset.tile) flags |= format::kFragmentTile;
  out.raw(flags);
  out.f64(asset.tau);
  out.string(asset.measure);
  out.u32(asset.regions.size());
  for (const Region& region : asset.regions) out.region(region);
  out.u32(asset.pieces.size());
  for (const CookedPiece& piece : asset.pieces) {
    out.region(piece.component);
    out.ring(piece.hull);
    out.f64(piece.concavity);
  }
  out.u32(asset.levels.size());
  for (const CookedLevel& level : asset.levels) {
    out.f64(level.tau);
    out.u32(level.hulls.size());
    for (const Ring& hull : level.hulls) out.ring(hull);
  }
  if (asset.physics) {
    const PhysicsProperties& physics = *asset.physics;
    out.raw(physics.density);
    out.raw(physics.friction);
    out.raw(physics.restitution);
    out.raw(physics.category_bits);
    out.raw(physics.mask_bits);
    out.raw(static_cast<std::uint32_t>(physics.sensor ? format::kFragmentSensor : 0));
  }
  if (asset.quantization_error) out.f64(*asset.quantization_error);
  out.u32(asset.warnings.size());
  for (const std::string& warning : asset.warnings) out.string(warning);
  out.u64(asset.stats.traced_vertices);
  out.u64(asset.stats.pieces);
  out.f64(asset.stats.max_concavity);
  out.f64(asset.stats.convexity);
}

}  // namespace

const char* tool_version() { return HULLCOOK_VERSION; }

std::string settings_text(const Settings& settings) {
  std::string text;
  auto line = [&text](const char* key, const std::string& value) {
    text += key;
    text += '=';
    text += value;
    text += '\n';
  };
  line("tau", tolerance_text(settings.tau));
  line("measure", settings.measure);
  line("sc", exact(settings.sc));
  line("sd", exact(settings.sd));
  line("max_pieces", std::to_string(settings.max_pieces));
  std::string lods;
  for (const Tolerance& lod : settings.lods)
    lods += (lods.empty() ? "" : ",") + tolerance_text(lod);
  line("lods", lods);
  line("alpha", std::to_string(settings.alpha));
  line("color_key", settings.color_key ? color_text(*settings.color_key) : "none");
  line("min_blob_area", exact(settings.min_blob_area));
  line("min_hole_area", exact(settings.min_hole_area));
  line("simplify", settings.simplify ? exact(*settings.simplify) : "default");
  line("max_pixels", std::to_string(settings.max_pixels));
  if (settings.grid) {
    const Grid& grid = *settings.grid;
    line("grid", std::to_string(grid.cell_width) + "x" + std::to_string(grid.cell_height) +
                     " margin " + std::to_string(grid.margin) + " spacing " +
                     std::to_string(grid.spacing) +
                     (grid.tile_snap ? " tile snap " + exact(*grid.tile_snap) : ""));
  } else {
    line("grid", "none");
  }
  line("pixels_per_unit", exact(settings.pixels_per_unit));
  line("pivot", exact(settings.pivot_u) + "," + exact(settings.pivot_v));
  line("y_down", settings.y_down ? "true" : "false");
  line("max_verts", std::to_string(settings.max_verts));
  line("weld", settings.weld ? exact(*settings.weld) : "default");
  // Only when set: fragments cooked without it keep their bytes.
  if (settings.merge_pieces) line("merge_pieces", "true");
  if (settings.physics) {
    const PhysicsProperties& physics = *settings.physics;
    line("physics", exact(physics.density) + "," + exact(physics.friction) + "," +
                        exact(physics.restitution) + "," + (physics.sensor ? "sensor" : "solid") +
                        "," + std::to_string(physics.category_bits) + "," +
                        std::to_string(physics.mask_bits));
  } else {
    line("physics", "none");
  }
  return text;
}

std::string write_fragment(const std::vector<CookedAsset>& assets, const Settings& settings) {
  const std::string settings_string = settings_text(settings);
  std::string bytes(sizeof(FragmentHeader), '\0');
  Encoder out(bytes);
  out.string(settings_string);
  for (const CookedAsset& asset : assets) encode_asset(out, asset);

  FragmentHeader header{};
  std::memcpy(header.magic, format::kFragmentMagic, sizeof(header.magic));
  header.format_version = format::kFragmentVersion;
  header.asset_count = static_cast<std::uint32_t>(assets.size());
  header.total_size = bytes.size();
  header.settings_hash = format::fnv1a_64(settings_string.data(), settings_string.size());
  static_assert(sizeof(HULLCOOK_VERSION) <= format::kToolVersionSize);
  std::memcpy(header.tool_version, HULLCOOK_VERSION, sizeof(HULLCOOK_VERSION));
  std::memcpy(bytes.data(), &header, sizeof(header));
  header.checksum = format::crc32(0, bytes.data(), bytes.size());
  std::memcpy(bytes.data(), &header, sizeof(header));
  return bytes;
}

}  // namespace hullcook
