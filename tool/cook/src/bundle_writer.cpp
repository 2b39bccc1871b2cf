#include "hullcook/cook/bundle_writer.h"

#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/format/bundle_layout.h"
#include "hullcook/format/crc32.h"

#include <sys/uio.h>
#include <unistd.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string_view>

namespace hullcook {
namespace {

using format::AssetRecord;
using format::BundleHeader;
using format::HullRecord;
using format::LevelRecord;
using format::PhysicsRecord;
using format::VertexRecord;

struct GridPoint {
  std::int64_t x = 0, y = 0;
  bool operator<(const GridPoint& o) const { return x < o.x || (x == o.x && y < o.y); }
  bool operator==(const GridPoint& o) const { return x == o.x && y == o.y; }
};

std::int64_t cross(const GridPoint& o, const GridPoint& a, const GridPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain on the integer grid, exact: counter-clockwise, strictly convex (no
// repeated or collinear vertex), into hull. Fewer than 3 points when the rounded hull is
// degenerate. Sorts points.
void strict_convex_hull(std::vector<GridPoint>& points, std::vector<GridPoint>& hull) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) {
    hull = points;
    return;
  }
  hull.resize(2 * points.size());
  std::size_t k = 0;
  for (const GridPoint& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
}

// Distance from p to the region bounded by ring (0 inside), for any simple ring.
double distance_to_polygon(Vec2 p, const Ring& ring) {
  bool inside = false;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
    best = std::min(best, point_segment_distance_squared(p, a, b));
  }
  return inside ? 0.0 : std::sqrt(best);
}

// Two-sided Hausdorff distance of two simple polygons whose farthest points are vertices (true
// for convex polygons: the distance to a convex set is a convex function).
double hausdorff(const Ring& a, const Ring& b) {
  double worst = 0.0;
  for (const Vec2& p : a) worst = std::max(worst, distance_to_polygon(p, b));
  for (const Vec2& p : b) worst = std::max(worst, distance_to_polygon(p, a));
  return worst;
}

struct QuantizedHull {
  HullRecord record{};
  std::vector<VertexRecord> vertices;
};

struct QuantizedAsset {
  float step = 0.0f;
  std::vector<std::vector<QuantizedHull>> levels;
};

[[noreturn]] void fail(const CookedAsset& asset, const std::string& problem) {
  throw OutputError("bundle: asset '" + asset.name + "': " + problem);
}

enum class Attempt { ok, too_coarse, too_wide };

// How a hull vertex meets the grid. nearest: the closest grid point. outward: of the corners of
// the grid cell holding it that lie as close (step/√2, the error bound readers report), the one
// farthest from the hull's vertex centroid. A hull thinner than a quantum rounds to a segment;
// the finer steps that would keep it a polygon may no longer store the asset's largest hull in
// 16-bit deltas, while pushing its sides apart may keep it one at the same step.
enum class Rounding { nearest, outward };

// The grid point for p at quantum; centroid only for outward.
GridPoint round_to_grid(Vec2 p, double quantum, Rounding rounding, Vec2 centroid) {
  if (rounding == Rounding::nearest)
    return {static_cast<std::int64_t>(std::nearbyint(p.x / quantum)),
            static_cast<std::int64_t>(std::nearbyint(p.y / quantum))};
  const double low_x = std::floor(p.x / quantum), low_y = std::floor(p.y / quantum);
  GridPoint best = round_to_grid(p, quantum, Rounding::nearest, centroid);
  const Vec2 away = p - centroid;
  double best_reach = glm::dot(Vec2{best.x * quantum, best.y * quantum} - p, away);
  for (int corner = 0; corner < 4; ++corner) {
    const double gx = low_x + (corner & 1), gy = low_y + (corner >> 1);
    const Vec2 moved{gx * quantum - p.x, gy * quantum - p.y};
    if (glm::dot(moved, moved) > 0.5 * quantum * quantum) continue;
    const double reach = glm::dot(moved, away);
    if (reach > best_reach) {
      best_reach = reach;
      best = {static_cast<std::int64_t>(gx), static_cast<std::int64_t>(gy)};
    }
  }
  return best;
}

// Quantizes one hull at step; too_coarse when the rounded hull degenerates or strays beyond
// the bound (a finer step may fix both), too_wide when it spans more than 16-bit deltas hold.
Attempt quantize_hull(const CookedAsset& asset, const Ring& hull, float step, double bound,
                      Rounding rounding, QuantizedHull& out, double& extent) {
  const double quantum = step;
  // Scratch, reused: one hull after the other.
  thread_local std::vector<GridPoint> points, grid;
  points.clear();
  Vec2 centroid{0.0, 0.0};
  if (rounding == Rounding::outward) {
    for (const Vec2& p : hull) centroid += p;
    centroid /= static_cast<double>(hull.size());
  }
  // The farthest a vertex moves [output units, squared], and the largest coordinate.
  double moved_squared = 0.0, size = 0.0;
  for (const Vec2& p : hull) {
    // Keep |base| + 2^15 within int32.
    if (std::fabs(p.x / quantum) > 2.0e9 || std::fabs(p.y / quantum) > 2.0e9) {
      fail(asset, "a hull vertex at (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                      ") is too far from the origin for the bundle's 32-bit grid (at most " +
                      std::to_string(2.0e9 * quantum) + " output units at its step of " +
                      std::to_string(quantum) +
                      "); move the input nearer the origin, or write glTF");
    }
    const GridPoint q = round_to_grid(p, quantum, rounding, centroid);
    points.push_back(q);
    // format::dequantize gives the grid point's value as qx * quantum exactly.
    const double dx = static_cast<double>(q.x) * quantum - p.x;
    const double dy = static_cast<double>(q.y) * quantum - p.y;
    moved_squared = std::max(moved_squared, dx * dx + dy * dy);
    size = std::max({size, std::fabs(p.x), std::fabs(p.y)});
  }
  strict_convex_hull(points, grid);
  if (grid.size() < format::kMinHullVertices) return Attempt::too_coarse;

  std::int64_t min_x = grid[0].x, max_x = min_x, min_y = grid[0].y, max_y = min_y;
  for (const GridPoint& p : grid) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  constexpr std::int64_t kDeltaRange = 65535;  // int16 span
  if (max_x - min_x > kDeltaRange || max_y - min_y > kDeltaRange) {
    extent = static_cast<double>(std::max(max_x - min_x, max_y - min_y)) * quantum;
    return Attempt::too_wide;
  }
  // Centre the base so that deltas fall in [-32768, 32767].
  const std::int64_t base_x = min_x + 32768, base_y = min_y + 32768;
  out.record.base_x = static_cast<std::int32_t>(base_x);
  out.record.base_y = static_cast<std::int32_t>(base_y);
  out.vertices.clear();
  out.vertices.reserve(grid.size());
  for (const GridPoint& p : grid) {
    out.vertices.push_back(
        {static_cast<std::int16_t>(p.x - base_x), static_cast<std::int16_t>(p.y - base_y)});
  }
  // Each stored vertex is a hull vertex moved, and each hull vertex moved lies in the stored
  // (convex) hull: no vertex of either is farther from the other polygon than the farthest move.
  // The margin covers the rounding of hausdorff() below, which then could not say otherwise.
  if (std::sqrt(moved_squared) <= bound - 1e-12 * size) return Attempt::ok;
  Ring stored;
  stored.reserve(grid.size());
  for (const VertexRecord& v : out.vertices) {
    stored.push_back({format::dequantize(out.record.base_x, v.dx, step),
                      format::dequantize(out.record.base_y, v.dy, step)});
  }
  return hausdorff(hull, stored) <= bound ? Attempt::ok : Attempt::too_coarse;
}

QuantizedAsset quantize_asset(const CookedAsset& asset, const std::vector<CookedLevel>& levels) {
  // A large sprite's hulls may extend beyond 65 535 quanta at 1 % of τ: the quantum grows with
  // them (SPEC §9) rather than the asset being refused.
  double largest_extent = 0.0;
  for (const CookedLevel& level : levels) {
    for (const Ring& hull : level.hulls) {
      if (hull.empty()) continue;
      double min_x = hull[0].x, max_x = min_x, min_y = hull[0].y, max_y = min_y;
      for (const Vec2& p : hull) {
        min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
        min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
      }
      largest_extent = std::max({largest_extent, max_x - min_x, max_y - min_y});
    }
  }
  const double bound =
      format::quantization_error_bound(levels[0].tau, asset.pixels_per_unit, largest_extent);
  QuantizedAsset result;
  // Rounding alone moves a vertex by at most step/√2 = bound; halving covers dropped vertices.
  // The f32 step is rounded down, so that step/√2 never exceeds the bound: rounded up, a vertex
  // half a quantum off in x and y could miss the bound and halve a step that large hulls need.
  result.step = static_cast<float>(bound * std::sqrt(2.0));
  if (static_cast<double>(result.step) > bound * std::sqrt(2.0)) {
    result.step = std::nextafter(result.step, 0.0f);
  }
  if (asset.tile) {
    // Half a pixel over the largest power of two that fits: the cell's borders, at whole or half
    // pixels from the pivot, fall on the grid (and stay on it when the step is halved below), so
    // neighbouring tiles' hulls meet exactly.
    const double half_pixel = 0.5 / asset.pixels_per_unit;
    double aligned = half_pixel;
    while (aligned > result.step && aligned > 0.0) aligned *= 0.5;
    // Exact when pixels per unit is a power of two; otherwise the borders are off by the f32
    // rounding of the step, far below any engine's slop.
    if (aligned > 0.0) result.step = static_cast<float>(aligned);
  }
  // A tiny pixels per unit makes the 1/64 px floor of the bound huge (issue 19's fuzzing of link:
  // 2.9e-39 px per unit); readers refuse a step beyond kMaxQuantStep.
  if (!(result.step <= format::kMaxQuantStep)) {
    fail(asset, "pixels per unit too small for the bundle's quantization grid (a step of " +
                    std::to_string(result.step) + " output units)");
  }
  // At each step each hull is rounded to the nearest grid points, else outward (which may keep a
  // hull thinner than a quantum a polygon); the step is halved until every hull is stored within
  // the bound.
  double too_wide_extent = 0.0;
  const float first_step = result.step;
  bool refined = false;  // whether the step that spanned too many quanta was halved
  for (int attempt = 0; attempt < 24 && too_wide_extent == 0.0; ++attempt, result.step *= 0.5f) {
    if (!(result.step > 0.0f)) break;
    result.levels.assign(levels.size(), {});
    Attempt outcome = Attempt::ok;
    for (std::size_t l = 0; l < levels.size() && outcome == Attempt::ok; ++l) {
      for (const Ring& hull : levels[l].hulls) {
        QuantizedHull quantized;
        for (Rounding rounding : {Rounding::nearest, Rounding::outward}) {
          outcome =
              quantize_hull(asset, hull, result.step, bound, rounding, quantized, too_wide_extent);
          if (outcome != Attempt::too_coarse) break;
        }
        if (outcome != Attempt::ok) break;
        result.levels[l].push_back(std::move(quantized));
      }
    }
    if (outcome == Attempt::ok) return result;
    if (outcome == Attempt::too_wide) refined = result.step < first_step;
  }
  if (too_wide_extent > 0.0) {
    // The step is first halved for a hull that rounds to a segment, a sliver of the outline
    // that simplifying it (--simplify) or a larger tau removes.
    fail(asset, "a hull spans " + std::to_string(too_wide_extent) +
                    " output units, more than the 65535 quanta of 16-bit deltas at the required "
                    "precision of " +
                    std::to_string(bound) + " units" +
                    (refined ? " once the step is refined for a hull thinner than it; cook it with "
                               "--simplify or a larger tau"
                             : "; cook it with a larger tau"));
  }
  fail(asset, "a hull is too thin to be stored as a convex polygon within " +
                  std::to_string(bound) + " output units");
}

void check_asset(const CookedAsset& asset, const std::vector<CookedLevel>& levels) {
  if (asset.name.empty()) fail(asset, "empty name");
  if (asset.name.size() > 0xFFFF) fail(asset, "name longer than 65535 bytes");
  if (asset.image_width < 0 || asset.image_width > 0xFFFF || asset.image_height < 0 ||
      asset.image_height > 0xFFFF)
    fail(asset, "image side outside [0, 65535] px");
  if (!std::isfinite(asset.pixels_per_unit) || !(static_cast<float>(asset.pixels_per_unit) > 0) ||
      !std::isfinite(static_cast<float>(asset.pixels_per_unit)))
    fail(asset, "pixels per unit must be a positive, finite 32-bit float");
  if (!std::isfinite(static_cast<float>(asset.pivot.x)) ||
      !std::isfinite(static_cast<float>(asset.pivot.y)))
    fail(asset, "non-finite pivot");
  double previous_tau = 0.0;
  for (const CookedLevel& level : levels) {
    if (!std::isfinite(static_cast<float>(level.tau)) || level.tau < previous_tau)
      fail(asset, "levels must have finite, non-negative tau from finest to coarsest");
    previous_tau = level.tau;
    for (const Ring& hull : level.hulls) {
      if (hull.size() < format::kMinHullVertices) fail(asset, "a hull has fewer than 3 vertices");
      for (const Vec2& p : hull)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(asset, "non-finite hull vertex");
    }
  }
  if (asset.physics) {
    const PhysicsProperties& physics = *asset.physics;
    for (float value : {physics.density, physics.friction, physics.restitution})
      if (!std::isfinite(value) || value < 0.0f)
        fail(asset, "physics properties must be finite and non-negative");
  }
}

template <typename T>
void put(std::string& bytes, std::size_t offset, const T& value) {
  std::memcpy(bytes.data() + offset, &value, sizeof(T));
}

std::uint16_t measure_code(const std::string& measure) {
  for (std::uint16_t code = 1; code < format::kMeasureCount; ++code)
    if (measure == format::kMeasureNames[code]) return code;
  return 0;
}

std::uint32_t to_u32(std::size_t value) {
  if (value > std::numeric_limits<std::uint32_t>::max())
    throw OutputError("bundle: larger than 4 GiB, the format's limit");
  return static_cast<std::uint32_t>(value);
}

// The name table (SPEC §6), linear probing at the writers' load factor. Names that cluster
// beyond the readers' probe budget (practically only crafted ones) get more slots; names sharing
// their whole 32-bit hash cluster at any slot count, so growth stops at a sane table size.
std::vector<std::uint32_t> name_table(const std::vector<CookedAsset>& assets) {
  const std::uint32_t asset_count = to_u32(assets.size());
  const std::uint64_t max_slot_count = std::min<std::uint64_t>(
      64 * std::uint64_t{asset_count} + 64, std::numeric_limits<std::uint32_t>::max());
  for (std::uint64_t slot_count = format::writer_slot_count(asset_count);
       slot_count <= max_slot_count; slot_count += slot_count / 2 + 1) {
    std::vector<std::uint32_t> slots(slot_count, format::kEmptySlot);
    for (std::size_t i = 0; i < assets.size(); ++i) {
      std::uint64_t slot =
          format::name_hash(assets[i].name.data(), assets[i].name.size()) % slot_count;
      while (slots[slot] != format::kEmptySlot) slot = (slot + 1) % slot_count;
      slots[slot] = static_cast<std::uint32_t>(i);
    }
    const auto slot_at = [&slots](std::uint32_t slot) { return slots[slot]; };
    if (format::name_table_probe_cost(static_cast<std::uint32_t>(slot_count), slot_at) <=
        format::name_table_probe_budget(static_cast<std::uint32_t>(slot_count)))
      return slots;
  }
  throw OutputError(
      "bundle: too many asset names share their FNV-1a hash for the name table; rename some");
}

// An asset's records, ready to be placed in a bundle: its quantized hulls (first_vertex counted
// from the asset's first vertex) and the shape of its levels.
struct AssetRecords {
  AssetShape shape;
  std::vector<HullRecord> hulls;
  std::vector<VertexRecord> vertices;
};

AssetRecords asset_records(const CookedAsset& asset) {
  // An asset without levels is stored with one empty level at its τ. The levels are read in
  // place, not copied: a cook's memory at scale is mostly its hulls.
  const std::vector<CookedLevel> no_levels{{asset.tau, {}}};
  const std::vector<CookedLevel>& levels = asset.levels.empty() ? no_levels : asset.levels;
  check_asset(asset, levels);
  QuantizedAsset quantized = quantize_asset(asset, levels);
  AssetRecords records;
  records.shape.step = quantized.step;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    records.shape.level_taus.push_back(static_cast<float>(levels[l].tau));
    records.shape.level_hulls.push_back(to_u32(quantized.levels[l].size()));
    for (QuantizedHull& hull : quantized.levels[l]) {
      HullRecord record = hull.record;
      record.first_vertex = to_u32(records.vertices.size());
      records.hulls.push_back(record);
      records.vertices.insert(records.vertices.end(), hull.vertices.begin(), hull.vertices.end());
    }
  }
  records.shape.hull_count = to_u32(records.hulls.size());
  records.shape.vertex_count = to_u32(records.vertices.size());
  return records;
}

// Where assemble reads each asset's records: held in memory (write_bundle) or spilled to a file
// as a cook goes (BundleStream).
class RecordSource {
 public:
  virtual ~RecordSource() = default;
  virtual const AssetShape& shape(std::size_t asset) const = 0;
  virtual void read(std::size_t asset, std::vector<HullRecord>& hulls,
                    std::vector<VertexRecord>& vertices) const = 0;
};

class RecordsInMemory : public RecordSource {
 public:
  explicit RecordsInMemory(std::vector<AssetRecords> records) : records_(std::move(records)) {}
  const AssetShape& shape(std::size_t asset) const override { return records_[asset].shape; }
  void read(std::size_t asset, std::vector<HullRecord>& hulls,
            std::vector<VertexRecord>& vertices) const override {
    hulls = records_[asset].hulls;
    vertices = records_[asset].vertices;
  }

 private:
  std::vector<AssetRecords> records_;
};

// Lays the bundle out (SPEC §2) and hands its bytes to append in file order, the header first
// (checksum 0); returns the header with its checksum, for the caller to put at offset 0.
template <typename Append>
BundleHeader assemble(const std::vector<CookedAsset>& assets, const RecordSource& source,
                      Append&& append) {
  std::set<std::string_view> names;
  bool any_physics = false;
  std::size_t level_count = 0, hull_count = 0, vertex_count = 0, strings_size = 0;
  for (std::size_t i = 0; i < assets.size(); ++i) {
    if (!names.insert(assets[i].name).second) fail(assets[i], "two assets have this name");
    const AssetShape& shape = source.shape(i);
    any_physics = any_physics || assets[i].physics.has_value();
    level_count += shape.level_taus.size();
    hull_count += shape.hull_count;
    vertex_count += shape.vertex_count;
    strings_size += assets[i].name.size() + 1;
  }

  BundleHeader header{};
  std::memcpy(header.magic, format::kMagic, sizeof(header.magic));
  header.version_major = format::kVersionMajor;
  header.version_minor = format::kVersionMinor;
  header.flags = any_physics ? format::kBundleHasPhysics : 0;
  header.asset_count = to_u32(assets.size());
  const std::vector<std::uint32_t> slots = name_table(assets);
  header.slot_count = to_u32(slots.size());
  header.level_count = to_u32(level_count);
  header.hull_count = to_u32(hull_count);
  header.vertex_count = to_u32(vertex_count);
  std::size_t end = sizeof(BundleHeader);
  auto place = [&end](std::size_t count, std::size_t record_size) {
    const std::size_t offset = end;
    end += count * record_size;
    return to_u32(offset);
  };
  header.assets_offset = place(assets.size(), sizeof(AssetRecord));
  header.physics_offset = any_physics ? place(assets.size(), sizeof(PhysicsRecord)) : 0;
  header.slots_offset = place(header.slot_count, sizeof(std::uint32_t));
  header.levels_offset = place(level_count, sizeof(LevelRecord));
  header.hulls_offset = place(hull_count, sizeof(HullRecord));
  header.vertices_offset = place(vertex_count, sizeof(VertexRecord));
  header.strings_offset = place(strings_size, 1);
  header.total_size = to_u32(end);

  std::uint32_t crc = 0;
  auto put_bytes = [&](const void* data, std::size_t size) {
    if (size == 0) return;  // an empty vector's data() may be null
    crc = format::crc32(crc, data, size);
    append(data, size);
  };
  auto put_record = [&](const auto& record) { put_bytes(&record, sizeof record); };
  append(&header, sizeof header);

  std::uint32_t level_index = 0, name_offset = 0;
  for (std::size_t i = 0; i < assets.size(); ++i) {
    const CookedAsset& asset = assets[i];
    AssetRecord record{};
    record.name_offset = name_offset;
    record.name_length = static_cast<std::uint16_t>(asset.name.size());
    record.flags =
        static_cast<std::uint16_t>((asset.physics ? format::kAssetHasPhysics : 0) |
                                   (asset.transform.flip_y ? format::kAssetFlipY : 0) |
                                   (measure_code(asset.measure) << format::kAssetMeasureShift));
    record.first_level = level_index;
    record.image_width = static_cast<std::uint16_t>(asset.image_width);
    record.image_height = static_cast<std::uint16_t>(asset.image_height);
    record.pixels_per_unit = static_cast<float>(asset.pixels_per_unit);
    record.pivot_u = static_cast<float>(asset.pivot.x);
    record.pivot_v = static_cast<float>(asset.pivot.y);
    record.quant_step = source.shape(i).step;
    put_record(record);
    level_index += static_cast<std::uint32_t>(source.shape(i).level_taus.size());
    name_offset += static_cast<std::uint32_t>(asset.name.size() + 1);
  }
  if (any_physics) {
    for (const CookedAsset& asset : assets) {
      PhysicsRecord physics{};
      if (asset.physics) {
        physics.density = asset.physics->density;
        physics.friction = asset.physics->friction;
        physics.restitution = asset.physics->restitution;
        physics.category_bits = asset.physics->category_bits;
        physics.mask_bits = asset.physics->mask_bits;
        physics.flags = asset.physics->sensor ? format::kPhysicsSensor : 0;
      }
      put_record(physics);
    }
  }
  put_bytes(slots.data(), slots.size() * sizeof(std::uint32_t));
  std::uint32_t hull_index = 0;
  for (std::size_t i = 0; i < assets.size(); ++i) {
    const AssetShape& shape = source.shape(i);
    for (std::size_t l = 0; l < shape.level_taus.size(); ++l) {
      put_record(LevelRecord{shape.level_taus[l], hull_index});
      hull_index += shape.level_hulls[l];
    }
  }
  // Hulls, then vertices: each asset's records are read twice rather than all held at once.
  std::vector<HullRecord> hulls;
  std::vector<VertexRecord> vertices;
  std::uint32_t vertex_index = 0;
  for (std::size_t i = 0; i < assets.size(); ++i) {
    source.read(i, hulls, vertices);
    for (HullRecord& hull : hulls) hull.first_vertex += vertex_index;
    put_bytes(hulls.data(), hulls.size() * sizeof(HullRecord));
    vertex_index += source.shape(i).vertex_count;
  }
  for (std::size_t i = 0; i < assets.size(); ++i) {
    source.read(i, hulls, vertices);
    put_bytes(vertices.data(), vertices.size() * sizeof(VertexRecord));
  }
  for (const CookedAsset& asset : assets) put_bytes(asset.name.c_str(), asset.name.size() + 1);
  header.checksum = crc;
  return header;
}

// fwrite of size bytes; an empty vector's data() may be null, which it must not get.
bool write_all(std::FILE* file, const void* data, std::size_t size) {
  return size == 0 || std::fwrite(data, 1, size, file) == size;
}
// Reads first_size bytes into first then second_size into second, from offset in the file.
bool read_at(int fd, std::size_t offset, void* first, std::size_t first_size, void* second,
             std::size_t second_size) {
  iovec parts[2] = {{first, first_size}, {second, second_size}};
  iovec* part = parts;
  int count = 2;
  while (count > 0) {
    if (part->iov_len == 0) {
      ++part, --count;
      continue;
    }
    const ssize_t got = ::preadv(fd, part, count, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    offset += static_cast<std::size_t>(got);
    for (std::size_t left = static_cast<std::size_t>(got); left > 0;) {
      const std::size_t taken = std::min(left, part->iov_len);
      part->iov_base = static_cast<char*>(part->iov_base) + taken;
      part->iov_len -= taken;
      left -= taken;
      if (part->iov_len == 0) ++part, --count;
    }
  }
  return true;
}

[[noreturn]] void spill_failed(const char* what) {
  throw OutputError(std::string("bundle: cannot ") + what +
                    " the temporary file of a streamed bundle: " + std::strerror(errno));
}

}  // namespace

std::string write_bundle(const std::vector<CookedAsset>& assets) {
  std::vector<AssetRecords> records;
  records.reserve(assets.size());
  for (const CookedAsset& asset : assets) records.push_back(asset_records(asset));
  std::string bytes;
  const BundleHeader header = assemble(
      assets, RecordsInMemory(std::move(records)),
      [&](const void* data, std::size_t n) { bytes.append(static_cast<const char*>(data), n); });
  put(bytes, 0, header);
  return bytes;
}

// ---- BundleStream ------------------------------------------------------------------------------

BundleStream::BundleStream() : spill_(std::tmpfile()) {
  if (!spill_) spill_failed("create");
}

BundleStream::~BundleStream() {
  if (spill_) std::fclose(spill_);
}

void BundleStream::add(std::size_t key, const CookedAsset& asset) {
  AssetRecords records = asset_records(asset);
  const std::lock_guard<std::mutex> lock(mutex_);
  if (key >= stored_.size()) stored_.resize(key + 1);
  Stored& stored = stored_[key];
  stored.shape = std::move(records.shape);
  stored.offset = spilled_;
  const std::size_t hull_bytes = records.hulls.size() * sizeof(HullRecord);
  const std::size_t vertex_bytes = records.vertices.size() * sizeof(VertexRecord);
  if (!write_all(spill_, records.hulls.data(), hull_bytes) ||
      !write_all(spill_, records.vertices.data(), vertex_bytes)) {
    spill_failed("write");
  }
  spilled_ += hull_bytes + vertex_bytes;
  stored.added = true;
}

void BundleStream::write(std::FILE* out, const std::vector<CookedAsset>& assets,
                         const std::vector<std::size_t>& keys) const {
  // The records of assets[i] were added under keys[i].
  class Spilled : public RecordSource {
   public:
    Spilled(const BundleStream& stream, const std::vector<std::size_t>& keys)
        : stream_(stream), keys_(keys) {}
    const AssetShape& shape(std::size_t asset) const override { return stored(asset).shape; }
    void read(std::size_t asset, std::vector<HullRecord>& hulls,
              std::vector<VertexRecord>& vertices) const override {
      const Stored& at = stored(asset);
      hulls.resize(at.shape.hull_count);
      vertices.resize(at.shape.vertex_count);
      const std::size_t hull_bytes = hulls.size() * sizeof(HullRecord);
      const std::size_t vertex_bytes = vertices.size() * sizeof(VertexRecord);
      // One positioned read of both: a seek through the FILE* dropped its buffer and cost a seek
      // and a read per 4 KiB, per asset (40,000 calls for 10,000 sprites).
      if (std::fflush(stream_.spill_) != 0 ||
          !read_at(fileno(stream_.spill_), at.offset, hulls.data(), hull_bytes, vertices.data(),
                   vertex_bytes)) {
        spill_failed("read");
      }
    }

   private:
    const Stored& stored(std::size_t asset) const {
      const std::size_t key = keys_.at(asset);
      if (key >= stream_.stored_.size() || !stream_.stored_[key].added) {
        throw std::logic_error("bundle: an asset was written that was never added");
      }
      return stream_.stored_[key];
    }
    const BundleStream& stream_;
    const std::vector<std::size_t>& keys_;
  };
  if (keys.size() != assets.size()) throw std::logic_error("bundle: one key per asset");
  const std::lock_guard<std::mutex> lock(mutex_);
  const long start = std::ftell(out);
  const BundleHeader header =
      assemble(assets, Spilled(*this, keys), [&](const void* data, std::size_t n) {
        if (!write_all(out, data, n)) throw OutputError(std::strerror(errno));
      });
  if (std::fseek(out, start, SEEK_SET) != 0 ||
      std::fwrite(&header, 1, sizeof header, out) != sizeof header) {
    throw OutputError(std::strerror(errno));
  }
  std::fseek(out, 0, SEEK_END);
}

}  // namespace hullcook
