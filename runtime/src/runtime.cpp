#include "hullcook/runtime.h"

#include "hull_validation.h"
#include "hullcook/format/bundle_layout.h"
#include "hullcook/format/crc32.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace hullcook {

const char* runtime_version() noexcept { return "0.1.0"; }

namespace runtime {

static_assert(kBundleAlignment == format::kAlignment);
static_assert(kFormatVersionMajor == format::kVersionMajor &&
              kFormatVersionMinor == format::kVersionMinor);

namespace {

using format::AssetRecord;
using format::BundleHeader;
using format::HullRecord;
using format::LevelRecord;
using format::load;
using format::PhysicsRecord;
using format::VertexRecord;

BundleHeader header_of(const unsigned char* bytes) { return load<BundleHeader>(bytes); }

AssetRecord asset_record(const unsigned char* bytes, const BundleHeader& header, std::size_t i) {
  return load<AssetRecord>(bytes + header.assets_offset + i * sizeof(AssetRecord));
}
LevelRecord level_record(const unsigned char* bytes, const BundleHeader& header, std::size_t i) {
  return load<LevelRecord>(bytes + header.levels_offset + i * sizeof(LevelRecord));
}

// The end of a CSR range: the next record's first index, or the section's count after the last.
std::uint32_t level_end(const unsigned char* bytes, const BundleHeader& header, std::size_t asset) {
  return asset + 1 < header.asset_count ? asset_record(bytes, header, asset + 1).first_level
                                        : header.level_count;
}
std::uint32_t hull_end(const unsigned char* bytes, const BundleHeader& header, std::size_t level) {
  return level + 1 < header.level_count ? level_record(bytes, header, level + 1).first_hull
                                        : header.hull_count;
}

bool finite(float value) { return std::isfinite(value); }

// Looks a name up in the validated (or being validated: every index it follows is checked)
// hash table. Returns the asset index or kEmptySlot.
// probes, when given, counts the slots probed.
std::uint32_t lookup(const unsigned char* bytes, const BundleHeader& header, const char* name,
                     std::size_t length, std::uint64_t* probes = nullptr) {
  if (header.slot_count == 0) return format::kEmptySlot;
  const unsigned char* slots = bytes + header.slots_offset;
  const unsigned char* strings = bytes + header.strings_offset;
  std::uint32_t slot = format::name_hash(name, length) % header.slot_count;
  // Bounded by slot_count even though an empty slot always exists in a valid bundle.
  for (std::uint32_t probe = 0; probe < header.slot_count; ++probe) {
    if (probes) ++*probes;
    const auto index = load<std::uint32_t>(slots + 4u * slot);
    if (index == format::kEmptySlot || index >= header.asset_count) return format::kEmptySlot;
    const AssetRecord asset = asset_record(bytes, header, index);
    if (asset.name_length == length && std::memcmp(strings + asset.name_offset, name, length) == 0)
      return index;
    slot = slot + 1 == header.slot_count ? 0 : slot + 1;
  }
  return format::kEmptySlot;
}

// Section offsets must follow each other exactly (SPEC §2); returns the end of a section of
// count records of record_size bytes at offset, or 0 on overflow.
std::uint64_t section_end(std::uint32_t offset, std::uint32_t count, std::size_t record_size) {
  return std::uint64_t{offset} + std::uint64_t{count} * record_size;
}

Status validate_layout(const BundleHeader& header) {
  if ((header.flags & ~format::kBundleKnownFlags) != 0) return Status::malformed;
  const bool has_physics = (header.flags & format::kBundleHasPhysics) != 0;
  const std::uint32_t offsets[] = {
      header.assets_offset, header.physics_offset,  header.slots_offset,  header.levels_offset,
      header.hulls_offset,  header.vertices_offset, header.strings_offset};
  for (std::uint32_t offset : offsets)
    if (offset % format::kAlignment != 0) return Status::misaligned;
  if (has_physics != (header.physics_offset != 0)) return Status::malformed;
  if (header.assets_offset != sizeof(BundleHeader)) return Status::malformed;

  std::uint64_t end = section_end(header.assets_offset, header.asset_count, sizeof(AssetRecord));
  if (has_physics) {
    if (header.physics_offset != end) return Status::malformed;
    end = section_end(header.physics_offset, header.asset_count, sizeof(PhysicsRecord));
  }
  const struct {
    std::uint32_t offset, count;
    std::size_t record_size;
  } sections[] = {{header.slots_offset, header.slot_count, 4},
                  {header.levels_offset, header.level_count, sizeof(LevelRecord)},
                  {header.hulls_offset, header.hull_count, sizeof(HullRecord)},
                  {header.vertices_offset, header.vertex_count, sizeof(VertexRecord)}};
  for (const auto& section : sections) {
    if (section.offset != end) return Status::malformed;
    end = section_end(section.offset, section.count, section.record_size);
    if (end > header.total_size) return Status::out_of_bounds;
  }
  if (header.strings_offset != end) return Status::malformed;
  if (header.slot_count <= header.asset_count) return Status::malformed;
  // Every asset has a level; every hull has at least 3 vertices.
  if (header.level_count < header.asset_count) return Status::malformed;
  if (std::uint64_t{header.hull_count} * format::kMinHullVertices > header.vertex_count)
    return Status::malformed;
  return Status::ok;
}

Status validate_assets(const unsigned char* bytes, const BundleHeader& header) {
  const std::uint32_t strings_size = header.total_size - header.strings_offset;
  const unsigned char* strings = bytes + header.strings_offset;
  const bool bundle_has_physics = (header.flags & format::kBundleHasPhysics) != 0;
  for (std::size_t i = 0; i < header.asset_count; ++i) {
    const AssetRecord asset = asset_record(bytes, header, i);
    if (asset.name_length == 0) return Status::malformed;
    if (std::uint64_t{asset.name_offset} + asset.name_length >= strings_size)
      return Status::out_of_bounds;
    if (strings[asset.name_offset + asset.name_length] != 0) return Status::malformed;
    if ((asset.flags & ~format::kAssetKnownFlags) != 0) return Status::malformed;
    if ((asset.flags & format::kAssetMeasureMask) >> format::kAssetMeasureShift >=
        format::kMeasureCount)
      return Status::malformed;
    const bool has_physics = (asset.flags & format::kAssetHasPhysics) != 0;
    if (has_physics && !bundle_has_physics) return Status::malformed;
    if (!finite(asset.pixels_per_unit) || !(asset.pixels_per_unit > 0.0f)) return Status::malformed;
    if (!finite(asset.pivot_u) || !finite(asset.pivot_v)) return Status::malformed;
    // Dequantized coordinates ((2^31 + 2^15) quanta at most) must stay finite in float.
    if (!finite(asset.quant_step) || !(asset.quant_step > 0.0f) ||
        asset.quant_step > format::kMaxQuantStep)
      return Status::malformed;
    if (i == 0 && asset.first_level != 0) return Status::malformed;
    const std::uint32_t end = level_end(bytes, header, i);
    if (end > header.level_count) return Status::out_of_bounds;
    if (end <= asset.first_level) return Status::malformed;
    float previous_tau = 0.0f;
    for (std::uint32_t level = asset.first_level; level < end; ++level) {
      const float tau = level_record(bytes, header, level).tau;
      if (!finite(tau) || tau < 0.0f || tau < previous_tau) return Status::malformed;
      previous_tau = tau;
    }

    if (!bundle_has_physics) continue;
    const auto physics =
        load<PhysicsRecord>(bytes + header.physics_offset + i * sizeof(PhysicsRecord));
    if (!has_physics) {
      static constexpr unsigned char kZeros[sizeof(PhysicsRecord)] = {};
      if (std::memcmp(bytes + header.physics_offset + i * sizeof(PhysicsRecord), kZeros,
                      sizeof(PhysicsRecord)) != 0)
        return Status::malformed;
      continue;
    }
    for (float value : {physics.density, physics.friction, physics.restitution})
      if (!finite(value) || value < 0.0f) return Status::malformed;
    if ((physics.flags & ~format::kPhysicsKnownFlags) != 0) return Status::malformed;
  }
  return Status::ok;
}

Status validate_levels_and_hulls(const unsigned char* bytes, const BundleHeader& header) {
  for (std::size_t level = 0; level < header.level_count; ++level) {
    const LevelRecord record = level_record(bytes, header, level);
    if (level == 0 && record.first_hull != 0) return Status::malformed;
    const std::uint32_t end = hull_end(bytes, header, level);
    if (end > header.hull_count) return Status::out_of_bounds;
    if (end < record.first_hull) return Status::malformed;
  }
  return detail::validate_hulls(bytes + header.hulls_offset, header.hull_count,
                                bytes + header.vertices_offset, header.vertex_count);
}

// For a table too clustered to look every asset up (SPEC §6), in one pass over the slots: each
// slot's asset has its name's start slot in the same run of occupied slots, at or before it, so
// that a lookup of that name reaches it. Duplicate names go unnoticed (a lookup finds the first),
// which no memory access depends on.
Status check_every_slot_reachable(const unsigned char* bytes, const BundleHeader& header) {
  const unsigned char* slots = bytes + header.slots_offset;
  const auto* strings = reinterpret_cast<const char*>(bytes + header.strings_offset);
  const std::uint32_t count = header.slot_count;
  auto slot_at = [&](std::uint32_t slot) { return load<std::uint32_t>(slots + 4u * slot); };
  std::uint32_t empty = 0;
  while (empty < count && slot_at(empty) != format::kEmptySlot) ++empty;
  if (empty == count) return Status::malformed;
  // Positions are counted from the empty slot, so that runs do not wrap.
  std::uint32_t run_start = 0;
  for (std::uint32_t position = 1; position < count; ++position) {
    const std::uint32_t slot = (empty + position) % count;
    const std::uint32_t index = slot_at(slot);
    if (index == format::kEmptySlot) {
      run_start = 0;
      continue;
    }
    if (run_start == 0) run_start = position;
    const AssetRecord asset = asset_record(bytes, header, index);
    const std::uint32_t start =
        format::name_hash(strings + asset.name_offset, asset.name_length) % count;
    const std::uint32_t start_position = (start + count - empty) % count;
    if (start_position < run_start || start_position > position) return Status::malformed;
  }
  return Status::ok;
}

Status validate_name_table(const unsigned char* bytes, const BundleHeader& header) {
  const unsigned char* slots = bytes + header.slots_offset;
  std::uint32_t occupied = 0;
  for (std::uint32_t slot = 0; slot < header.slot_count; ++slot) {
    const auto index = load<std::uint32_t>(slots + 4u * slot);
    if (index == format::kEmptySlot) continue;
    if (index >= header.asset_count) return Status::out_of_bounds;
    ++occupied;
  }
  if (occupied != header.asset_count) return Status::malformed;
  // With exactly asset_count occupied slots, finding every asset by its own name proves that
  // each index appears once, is reachable, and that names are unique. It probes as many slots as
  // the table's probe cost (SPEC §6), which names crafted to share a start slot make quadratic
  // in the asset count; past the probe budget, only what keeps lookups right is checked, in one
  // pass (check_every_slot_reachable).
  const auto* strings = reinterpret_cast<const char*>(bytes + header.strings_offset);
  const std::uint64_t budget = format::name_table_probe_budget(header.slot_count);
  std::uint64_t probes = 0;
  for (std::uint32_t i = 0; i < header.asset_count; ++i) {
    const AssetRecord asset = asset_record(bytes, header, i);
    if (lookup(bytes, header, strings + asset.name_offset, asset.name_length, &probes) != i)
      return Status::malformed;
    if (probes > budget) return check_every_slot_reachable(bytes, header);
  }
  return Status::ok;
}

Status validate(const unsigned char* bytes, std::size_t size) {
  if (size < sizeof(BundleHeader)) return Status::truncated;
  if (reinterpret_cast<std::uintptr_t>(bytes) % format::kAlignment != 0) return Status::misaligned;
  const BundleHeader header = header_of(bytes);
  if (std::memcmp(header.magic, format::kMagic, sizeof(format::kMagic)) != 0)
    return Status::bad_magic;
  if (header.version_major > format::kVersionMajor) return Status::unsupported_major_version;
  if (header.version_major < format::kVersionMajor) return Status::malformed;  // never released
  if (header.version_minor > format::kVersionMinor) return Status::unsupported_minor_version;
  if (header.total_size > size) return Status::truncated;
  if (header.total_size < sizeof(BundleHeader)) return Status::malformed;
  const std::uint32_t checksum =
      format::crc32(0, bytes + sizeof(BundleHeader), header.total_size - sizeof(BundleHeader));
  if (checksum != header.checksum) return Status::bad_checksum;
  if (Status status = validate_layout(header); status != Status::ok) return status;
  if (Status status = validate_assets(bytes, header); status != Status::ok) return status;
  if (Status status = validate_levels_and_hulls(bytes, header); status != Status::ok) return status;
  return validate_name_table(bytes, header);
}

}  // namespace

const char* status_string(Status status) noexcept {
  switch (status) {
    case Status::ok:
      return "ok";
    case Status::invalid_argument:
      return "invalid argument (null data or path)";
    case Status::io_error:
      return "the file could not be opened or read";
    case Status::truncated:
      return "truncated (shorter than the 64-byte header, or than the size the header records)";
    case Status::misaligned:
      return "misaligned (the buffer or a section is not 4-byte aligned)";
    case Status::bad_magic:
      return "not a hullcook bundle (bad magic)";
    case Status::unsupported_major_version:
      return "unsupported major format version (written by a newer hullcook)";
    case Status::unsupported_minor_version:
      return "unsupported minor format version (written by a newer hullcook)";
    case Status::bad_checksum:
      return "bad checksum (the file is corrupted)";
    case Status::out_of_bounds:
      return "out of bounds (a range reaches outside its section)";
    case Status::malformed:
      return "malformed (inconsistent content)";
  }
  return "unknown status";
}

// ---- Bundle -----------------------------------------------------------------------------------

Status Bundle::open(const void* data, std::size_t size) noexcept {
  *this = Bundle{};
  if (data == nullptr) return size == 0 ? Status::truncated : Status::invalid_argument;
  const auto* bytes = static_cast<const unsigned char*>(data);
  const Status status = validate(bytes, size);
  if (status != Status::ok) return status;
  const BundleHeader header = header_of(bytes);
  bytes_ = bytes;
  size_ = header.total_size;
  asset_count_ = header.asset_count;
  return Status::ok;
}

int Bundle::version_major() const noexcept { return bytes_ ? header_of(bytes_).version_major : 0; }
int Bundle::version_minor() const noexcept { return bytes_ ? header_of(bytes_).version_minor : 0; }
std::size_t Bundle::level_count() const noexcept {
  return bytes_ ? header_of(bytes_).level_count : 0;
}
std::size_t Bundle::hull_count() const noexcept {
  return bytes_ ? header_of(bytes_).hull_count : 0;
}
std::size_t Bundle::vertex_count() const noexcept {
  return bytes_ ? header_of(bytes_).vertex_count : 0;
}

Asset Bundle::asset(std::size_t i) const noexcept {
  Asset asset;
  if (i >= asset_count_) return asset;
  const BundleHeader header = header_of(bytes_);
  asset.bundle_ = bytes_;
  asset.record_ = bytes_ + header.assets_offset + i * sizeof(AssetRecord);
  asset.index_ = i;
  asset.level_count_ = level_end(bytes_, header, i) - load<AssetRecord>(asset.record_).first_level;
  return asset;
}

Asset Bundle::find(std::string_view name) const noexcept {
  if (bytes_ == nullptr) return Asset{};
  const std::uint32_t index = lookup(bytes_, header_of(bytes_), name.data(), name.size());
  return index == format::kEmptySlot ? Asset{} : asset(index);
}

// ---- Asset ------------------------------------------------------------------------------------

std::string_view Asset::name() const noexcept {
  if (!record_) return {};
  const AssetRecord record = load<AssetRecord>(record_);
  const auto* strings = reinterpret_cast<const char*>(bundle_ + header_of(bundle_).strings_offset);
  return {strings + record.name_offset, record.name_length};
}
int Asset::image_width() const noexcept {
  return record_ ? load<AssetRecord>(record_).image_width : 0;
}
int Asset::image_height() const noexcept {
  return record_ ? load<AssetRecord>(record_).image_height : 0;
}
float Asset::pixels_per_unit() const noexcept {
  return record_ ? load<AssetRecord>(record_).pixels_per_unit : 0.0f;
}
Vec2 Asset::pivot() const noexcept {
  if (!record_) return {};
  const AssetRecord record = load<AssetRecord>(record_);
  return {record.pivot_u, record.pivot_v};
}
float Asset::quantization_error() const noexcept {
  return record_ ? load<AssetRecord>(record_).quant_step / std::sqrt(2.0f) : 0.0f;
}

Level Asset::level(std::size_t i) const noexcept {
  Level level;
  if (i >= level_count_) return level;
  const BundleHeader header = header_of(bundle_);
  const AssetRecord record = load<AssetRecord>(record_);
  const std::size_t global = record.first_level + i;
  const LevelRecord level_record_value = level_record(bundle_, header, global);
  level.hull_records_ = bundle_ + header.hulls_offset;
  level.vertex_records_ = bundle_ + header.vertices_offset;
  level.hull_total_ = header.hull_count;
  level.vertex_total_ = header.vertex_count;
  level.first_hull_ = level_record_value.first_hull;
  level.hull_count_ = hull_end(bundle_, header, global) - level_record_value.first_hull;
  level.tau_ = level_record_value.tau;
  level.step_ = record.quant_step;
  return level;
}

Level Asset::select_level(float tau) const noexcept {
  if (level_count_ == 0) return Level{};
  for (std::size_t i = 0; i < level_count_; ++i) {
    Level candidate = level(i);
    if (candidate.tau() >= tau) return candidate;
  }
  return level(level_count_ - 1);
}

bool Asset::flip_y() const noexcept {
  return record_ && (load<AssetRecord>(record_).flags & format::kAssetFlipY) != 0;
}

const char* Asset::measure() const noexcept {
  if (!record_) return "";
  return format::kMeasureNames[(load<AssetRecord>(record_).flags & format::kAssetMeasureMask) >>
                               format::kAssetMeasureShift];
}

bool Asset::has_physics() const noexcept {
  return record_ && (load<AssetRecord>(record_).flags & format::kAssetHasPhysics) != 0;
}

Physics Asset::physics() const noexcept {
  Physics physics;
  if (!has_physics()) return physics;
  const BundleHeader header = header_of(bundle_);
  const auto record =
      load<PhysicsRecord>(bundle_ + header.physics_offset + index_ * sizeof(PhysicsRecord));
  physics.density = record.density;
  physics.friction = record.friction;
  physics.restitution = record.restitution;
  physics.sensor = (record.flags & format::kPhysicsSensor) != 0;
  physics.category_bits = record.category_bits;
  physics.mask_bits = record.mask_bits;
  return physics;
}

// ---- Level and Hull ---------------------------------------------------------------------------

namespace {
// The end of hull `global`'s vertex range, from the level's cached section pointers.
std::uint32_t level_vertex_end(const unsigned char* hulls, std::uint32_t hull_total,
                               std::uint32_t vertex_total, std::size_t global) {
  return global + 1 < hull_total ? load<std::uint32_t>(hulls + (global + 1) * sizeof(HullRecord))
                                 : vertex_total;
}
}  // namespace

Hull Level::hull(std::size_t i) const noexcept {
  Hull hull;
  if (i >= hull_count_) return hull;
  const std::size_t global = first_hull_ + i;
  const HullRecord record = load<HullRecord>(hull_records_ + global * sizeof(HullRecord));
  hull.vertices_ = vertex_records_ + 4u * record.first_vertex;
  hull.count_ =
      level_vertex_end(hull_records_, hull_total_, vertex_total_, global) - record.first_vertex;
  hull.base_x_ = record.base_x;
  hull.base_y_ = record.base_y;
  hull.step_ = step_;
  return hull;
}

std::size_t Level::vertex_count() const noexcept {
  if (hull_count_ == 0) return 0;
  const std::size_t last = first_hull_ + hull_count_ - 1;
  return level_vertex_end(hull_records_, hull_total_, vertex_total_, last) -
         load<HullRecord>(hull_records_ + std::size_t{first_hull_} * sizeof(HullRecord))
             .first_vertex;
}

std::size_t Hull::copy_vertices(Vec2* out, std::size_t capacity,
                                Placement placement) const noexcept {
  const std::size_t n = count_ < capacity ? count_ : capacity;
  if (out == nullptr) return count_;
  for (std::size_t i = 0; i < n; ++i) out[i] = placed_vertex(i, placement);
  return count_;
}

double Hull::area() const noexcept {
  // Exact on the integer grid, relative to the first vertex.
  if (count_ < 3) return 0.0;
  const VertexRecord origin = load<VertexRecord>(vertices_);
  std::int64_t twice_area = 0;
  for (std::size_t i = 1; i + 1 < count_; ++i) {
    const VertexRecord a = load<VertexRecord>(vertices_ + 4u * i);
    const VertexRecord b = load<VertexRecord>(vertices_ + 4u * (i + 1));
    twice_area += (std::int64_t{a.dx} - origin.dx) * (std::int64_t{b.dy} - origin.dy) -
                  (std::int64_t{a.dy} - origin.dy) * (std::int64_t{b.dx} - origin.dx);
  }
  const double step = step_;
  return 0.5 * static_cast<double>(twice_area) * step * step;
}

Vec2 Hull::centroid() const noexcept {
  if (count_ < 3) return {};
  const VertexRecord origin = load<VertexRecord>(vertices_);
  double twice_area = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t i = 1; i + 1 < count_; ++i) {
    const VertexRecord a = load<VertexRecord>(vertices_ + 4u * i);
    const VertexRecord b = load<VertexRecord>(vertices_ + 4u * (i + 1));
    const double ax = a.dx - origin.dx, ay = a.dy - origin.dy;
    const double bx = b.dx - origin.dx, by = b.dy - origin.dy;
    const double cross = ax * by - ay * bx;
    twice_area += cross;
    cx += cross * (ax + bx) / 3.0;
    cy += cross * (ay + by) / 3.0;
  }
  const double x = static_cast<double>(std::int64_t{base_x_} + origin.dx) + cx / twice_area;
  const double y = static_cast<double>(std::int64_t{base_y_} + origin.dy) + cy / twice_area;
  return {static_cast<float>(x * step_), static_cast<float>(y * step_)};
}

}  // namespace runtime
}  // namespace hullcook
