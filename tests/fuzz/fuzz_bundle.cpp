// libFuzzer target: the runtime's Bundle::open on any bytes, then every accessor on what it
// accepts, checked against the promises of runtime.h. A mutated bundle almost never keeps its
// CRC-32, so each input is opened twice: as given, and with its checksum recomputed, which lets
// the fuzzer reach the validation behind the checksum.
#include "fuzz_check.h"

#include "hullcook/format/bundle_layout.h"
#include "hullcook/format/crc32.h"
#include "hullcook/runtime.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

namespace {

using namespace hullcook::runtime;

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

void walk_hull(const Hull& hull) {
  const std::size_t count = hull.vertex_count();
  FUZZ_CHECK(count >= 3, "a hull has at least 3 vertices");
  std::vector<Vec2> copied(count);
  FUZZ_CHECK(hull.copy_vertices(copied.data(), count) == count, "copy_vertices returns the count");
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2 v = hull.vertex(i);
    FUZZ_CHECK(finite(v), "vertices are finite");
    FUZZ_CHECK(copied[i].x == v.x && copied[i].y == v.y, "copy_vertices copies vertex(i)");
    const Vec2 mirrored = hull.placed_vertex(i, {2.0f, true});
    FUZZ_CHECK(!std::isnan(mirrored.x) && !std::isnan(mirrored.y), "placed vertices are numbers");
  }
  Vec2 small[2];
  FUZZ_CHECK(hull.copy_vertices(small, 2, {0.5f, true}) == count, "a short buffer gets the count");
  FUZZ_CHECK(hull.copy_vertices(nullptr, 0) == count, "an empty buffer gets the count");
  const double area = hull.area();
  FUZZ_CHECK(area > 0.0 && std::isfinite(area), "a hull's area is positive");
  (void)hull.centroid();
}

void walk_level(const Level& level) {
  FUZZ_CHECK(std::isfinite(level.tau()) && level.tau() >= 0.0f, "τ is finite and >= 0");
  std::size_t vertices = 0;
  for (std::size_t h = 0; h < level.hull_count(); ++h) {
    const Hull hull = level.hull(h);
    walk_hull(hull);
    vertices += hull.vertex_count();
  }
  FUZZ_CHECK(vertices == level.vertex_count(), "a level's vertex count sums its hulls'");
  FUZZ_CHECK(level.hull(level.hull_count()).vertex_count() == 0, "a hull out of range is empty");
}

void walk_asset(const Bundle& bundle, const Asset& asset, std::size_t index) {
  FUZZ_CHECK(asset.valid() && asset.index() == index, "asset(i) is asset i");
  const std::string_view name = asset.name();
  FUZZ_CHECK(!name.empty() && name.data()[name.size()] == '\0', "names are 0-terminated");
  FUZZ_CHECK(bundle.find(name).name() == name, "find(name) finds an asset of that name");
  FUZZ_CHECK(asset.image_width() >= 0 && asset.image_height() >= 0, "image sizes are >= 0");
  FUZZ_CHECK(asset.pixels_per_unit() > 0.0f && std::isfinite(asset.pixels_per_unit()),
             "pixels per unit are positive");
  FUZZ_CHECK(finite(asset.pivot()), "the pivot is finite");
  (void)asset.flip_y();
  FUZZ_CHECK(asset.measure() != nullptr, "measure() is never null");
  FUZZ_CHECK(std::isfinite(asset.quantization_error()), "the quantization error is finite");
  const Physics physics = asset.physics();
  if (asset.has_physics()) {
    FUZZ_CHECK(physics.density >= 0.0f && physics.friction >= 0.0f && physics.restitution >= 0.0f,
               "physics values are >= 0");
  }
  FUZZ_CHECK(asset.level_count() >= 1, "a valid asset has a level");
  float previous_tau = 0.0f;
  for (std::size_t l = 0; l < asset.level_count(); ++l) {
    const Level level = asset.level(l);
    FUZZ_CHECK(level.tau() >= previous_tau, "levels go from finest to coarsest");
    previous_tau = level.tau();
    walk_level(level);
  }
  FUZZ_CHECK(asset.level(asset.level_count()).hull_count() == 0, "a level out of range is empty");
  for (float tau : {-1.0f, 0.0f, 0.5f, previous_tau, 1e30f, NAN}) {
    FUZZ_CHECK(asset.select_level(tau).hull_count() <= bundle.hull_count(), "select_level");
  }
}

void open_and_walk(const unsigned char* bytes, std::size_t size) {
  Bundle bundle;
  const Status status = bundle.open(bytes, size);
  FUZZ_CHECK(status_string(status) != nullptr, "status_string is never null");
  if (status != Status::ok) {
    FUZZ_CHECK(bundle.empty() && bundle.asset_count() == 0, "a failed open leaves it empty");
    return;
  }
  FUZZ_CHECK(bundle.size() <= size, "the bundle lies inside the buffer");
  FUZZ_CHECK(bundle.version_major() == kFormatVersionMajor, "the major version is this one");
  for (std::size_t i = 0; i < bundle.asset_count(); ++i) walk_asset(bundle, bundle.asset(i), i);
  FUZZ_CHECK(!bundle.asset(bundle.asset_count()).valid(), "an asset out of range is empty");
  FUZZ_CHECK(!bundle.find("").valid(), "no asset has an empty name");
  (void)bundle.find(std::string_view(reinterpret_cast<const char*>(bytes), size < 40 ? size : 40));
  (void)bundle.level_count();
  (void)bundle.vertex_count();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The runtime requires a 4-byte aligned buffer; libFuzzer's is, but a copy makes sure and lets
  // the checksum be patched.
  std::vector<std::uint32_t> words((size + 3) / 4);
  auto* bytes = reinterpret_cast<unsigned char*>(words.data());
  if (size > 0) std::memcpy(bytes, data, size);
  open_and_walk(bytes, size);

  using hullcook::format::BundleHeader;
  if (size < sizeof(BundleHeader)) return 0;
  std::uint32_t total_size = 0;
  std::memcpy(&total_size, bytes + offsetof(BundleHeader, total_size), 4);
  if (total_size < sizeof(BundleHeader) || total_size > size) return 0;
  const std::uint32_t checksum =
      hullcook::format::crc32(0, bytes + sizeof(BundleHeader), total_size - sizeof(BundleHeader));
  std::memcpy(bytes + offsetof(BundleHeader, checksum), &checksum, 4);
  open_and_walk(bytes, size);
  return 0;
}
