#include "hullcook/cook/bundle_writer.h"

#include "quantize.h"

#include "hullcook/core/error.h"
#include "hullcook/format/bundle_layout.h"
#include "hullcook/format/crc32.h"

#include <sys/uio.h>
#include <unistd.h>

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
#include <string>
#include <string_view>

namespace hullcook {
namespace {

using format::AssetRecord;
using format::BundleHeader;
using format::HullRecord;
using format::LevelRecord;
using format::PhysicsRecord;
using format::VertexRecord;

// Asked where the bundle is laid out, of the names it is laid out with: a stream's assets are
// renamed (cook --name) after their levels were spilled, and a name made longer than the 16-bit
// length then went out truncated, with exit 0 (stop 60).
void check_name(const CookedAsset& asset) {
  if (asset.name.empty()) bundle_asset_error(asset, "empty name");
  if (asset.name.size() > 0xFFFF) bundle_asset_error(asset, "name longer than 65535 bytes");
}

void check_asset(const CookedAsset& asset, const std::vector<CookedLevel>& levels) {
  check_bundle_image_size(asset.name, asset.source, asset.image_width, asset.image_height);
  if (!stores_as_positive_float(asset.pixels_per_unit))
    bundle_asset_error(asset, "pixels per unit must be a positive, finite 32-bit float");
  if (!std::isfinite(static_cast<float>(asset.pivot.x)) ||
      !std::isfinite(static_cast<float>(asset.pivot.y)))
    bundle_asset_error(asset, "non-finite pivot");
  double previous_tau = 0.0;
  for (const CookedLevel& level : levels) {
    if (!std::isfinite(static_cast<float>(level.tau)) || level.tau < previous_tau)
      bundle_asset_error(asset,
                         "levels must have finite, non-negative tau from finest to coarsest");
    previous_tau = level.tau;
    for (const Ring& hull : level.hulls) {
      if (hull.size() < format::kMinHullVertices)
        bundle_asset_error(asset, "a hull has fewer than 3 vertices");
      for (const Vec2& p : hull)
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
          bundle_asset_error(asset, "non-finite hull vertex");
    }
  }
  if (asset.physics) {
    const PhysicsProperties& physics = *asset.physics;
    for (float value : {physics.density, physics.friction, physics.restitution})
      if (!std::isfinite(value) || value < 0.0f)
        bundle_asset_error(asset, "physics properties must be finite and non-negative");
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
    check_name(assets[i]);
    if (!names.insert(assets[i].name).second)
      bundle_asset_error(assets[i], "two assets have this name");
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

static_assert(kBundleLargestImageSide ==
              std::numeric_limits<decltype(AssetRecord::image_width)>::max());

void check_bundle_image_size(const std::string& name, const std::string& source, int width,
                             int height) {
  if (width < 0 || width > kBundleLargestImageSide || height < 0 ||
      height > kBundleLargestImageSide) {
    bundle_asset_error(name, "its image (" + source + ") is " + std::to_string(width) + " x " +
                                 std::to_string(height) + " px, a side more than the bundle's " +
                                 std::to_string(kBundleLargestImageSide) +
                                 "; cut it into cells with --grid, or write glTF (.glb), which "
                                 "has no such limit");
  }
}

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
