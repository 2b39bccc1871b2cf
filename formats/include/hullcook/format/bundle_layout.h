// The byte layout of the hull bundle (.hcb), version 1.0, exactly as formats/SPEC.md describes
// it. Shared by the writer (tool/cook/src/bundle_writer.cpp) and the reader (runtime/): one
// definition of every record, constant and formula. C++17, standard library only.
//
// Records are plain structs whose layout equals the file's (checked below); read them with
// load() from a byte pointer, which is alignment- and aliasing-safe and compiles to plain loads.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "hullcook bundles are little-endian; big-endian hosts are not supported"
#endif

namespace hullcook::format {

inline constexpr std::uint8_t kMagic[4] = {0x48, 0x43, 0x42, 0x1A};  // "HCB" Ctrl-Z
inline constexpr std::uint8_t kVersionMajor = 1;
inline constexpr std::uint8_t kVersionMinor = 0;

// Every section starts at a multiple of this [bytes]; so must the buffer holding the bundle.
inline constexpr std::size_t kAlignment = 4;

// Header flags (BundleHeader::flags).
inline constexpr std::uint16_t kBundleHasPhysics = 1u << 0;
inline constexpr std::uint16_t kBundleKnownFlags = kBundleHasPhysics;
// Asset flags (AssetRecord::flags).
inline constexpr std::uint16_t kAssetHasPhysics = 1u << 0;
inline constexpr std::uint16_t kAssetFlipY = 1u << 1;  // output y up: image y was negated
inline constexpr int kAssetMeasureShift = 2;           // bits 2-4: index into kMeasureNames
inline constexpr std::uint16_t kAssetMeasureMask = 7u << kAssetMeasureShift;
inline constexpr std::uint16_t kAssetKnownFlags =
    kAssetHasPhysics | kAssetFlipY | kAssetMeasureMask;
// The concavity measures by their code in the asset flags; "" when unknown.
inline constexpr const char* kMeasureNames[] = {"", "sl", "sp", "h1", "h2"};
inline constexpr std::uint16_t kMeasureCount = 5;
// Physics flags (PhysicsRecord::flags).
inline constexpr std::uint32_t kPhysicsSensor = 1u << 0;
inline constexpr std::uint32_t kPhysicsKnownFlags = kPhysicsSensor;

// A hash slot holding no asset.
inline constexpr std::uint32_t kEmptySlot = 0xFFFFFFFFu;

// A hull has at least this many vertices.
inline constexpr std::uint32_t kMinHullVertices = 3;
// The largest quantization step a reader accepts (SPEC §11): beyond it a 16-bit delta times the
// step overflows a float.
inline constexpr float kMaxQuantStep = 1e28f;
// The 32-bit float nearest to value, as a double: what a reader holds of value. Through a
// volatile float, because GCC 12's SLP vectorizer at -O2 and above drops the rounding when an x
// and a y are converted to float and back side by side (the result was value itself).
inline double nearest_float(double value) noexcept {
  const volatile float rounded = static_cast<float>(value);
  return rounded;
}

// The spacing of 32-bit floats at coordinate [output units]: the gap from the float nearest to
// |coordinate| to the next one up (at least 2^-23 of it, at most 2^-24 below 2^23 of it).
inline double float_spacing(double coordinate) noexcept {
  const float magnitude = static_cast<float>(std::fabs(coordinate));
  return static_cast<double>(std::nextafter(magnitude, std::numeric_limits<float>::infinity())) -
         static_cast<double>(magnitude);
}

// Whether 32-bit floats resolve a grid of step at coordinate (SPEC §9): their spacing there is
// at most the step, so that a reader's f32 vertex lies within step / 2 per coordinate of its
// grid point and distinct grid points stay distinct floats. Below 2^23 steps from the origin
// always (the spacing is at most 2^-23 of the coordinate); the coordinate must fit a float.
inline bool floats_resolve(double coordinate, double step) noexcept {
  const double magnitude = std::fabs(coordinate);
  if (magnitude <= 8388608.0 * step) return true;
  return magnitude <= static_cast<double>(std::numeric_limits<float>::max()) &&
         float_spacing(magnitude) <= step;
}

struct BundleHeader {
  std::uint8_t magic[4];
  std::uint8_t version_major;
  std::uint8_t version_minor;
  std::uint16_t flags;
  std::uint32_t total_size;  // [bytes] header included
  std::uint32_t checksum;    // CRC-32 of bytes [sizeof(BundleHeader), total_size)
  std::uint32_t asset_count;
  std::uint32_t slot_count;
  std::uint32_t level_count;
  std::uint32_t hull_count;
  std::uint32_t vertex_count;
  std::uint32_t assets_offset;   // [bytes] from the start of the bundle
  std::uint32_t physics_offset;  // 0 without kBundleHasPhysics
  std::uint32_t slots_offset;
  std::uint32_t levels_offset;
  std::uint32_t hulls_offset;
  std::uint32_t vertices_offset;
  std::uint32_t strings_offset;  // the strings run to total_size
};

struct AssetRecord {
  std::uint32_t name_offset;  // [bytes] inside the strings section; a 0 byte follows the name
  std::uint16_t name_length;  // [bytes] without the 0 byte, >= 1
  std::uint16_t flags;
  std::uint32_t first_level;
  std::uint16_t image_width;   // [px] 0 when not an image
  std::uint16_t image_height;  // [px]
  float pixels_per_unit;       // [px / output unit]
  float pivot_u;               // normalised image x of the output origin
  float pivot_v;               // normalised image y of the output origin (0 = top)
  float quant_step;            // [output units] per quantum
};

struct PhysicsRecord {
  float density;  // [kg / output unit²]
  float friction;
  float restitution;
  std::uint16_t category_bits;
  std::uint16_t mask_bits;
  std::uint32_t flags;
};

struct LevelRecord {
  float tau;  // [output units]
  std::uint32_t first_hull;
};

struct HullRecord {
  std::uint32_t first_vertex;
  std::int32_t base_x;  // [quanta]
  std::int32_t base_y;  // [quanta]
};

struct VertexRecord {
  std::int16_t dx;  // [quanta] from the hull's base
  std::int16_t dy;
};

#define HULLCOOK_CHECK_FIELD(record, field, offset) \
  static_assert(offsetof(record, field) == (offset), #record "::" #field " is at " #offset)

static_assert(sizeof(BundleHeader) == 64);
HULLCOOK_CHECK_FIELD(BundleHeader, version_major, 4);
HULLCOOK_CHECK_FIELD(BundleHeader, version_minor, 5);
HULLCOOK_CHECK_FIELD(BundleHeader, flags, 6);
HULLCOOK_CHECK_FIELD(BundleHeader, total_size, 8);
HULLCOOK_CHECK_FIELD(BundleHeader, checksum, 12);
HULLCOOK_CHECK_FIELD(BundleHeader, asset_count, 16);
HULLCOOK_CHECK_FIELD(BundleHeader, slot_count, 20);
HULLCOOK_CHECK_FIELD(BundleHeader, level_count, 24);
HULLCOOK_CHECK_FIELD(BundleHeader, hull_count, 28);
HULLCOOK_CHECK_FIELD(BundleHeader, vertex_count, 32);
HULLCOOK_CHECK_FIELD(BundleHeader, assets_offset, 36);
HULLCOOK_CHECK_FIELD(BundleHeader, physics_offset, 40);
HULLCOOK_CHECK_FIELD(BundleHeader, slots_offset, 44);
HULLCOOK_CHECK_FIELD(BundleHeader, levels_offset, 48);
HULLCOOK_CHECK_FIELD(BundleHeader, hulls_offset, 52);
HULLCOOK_CHECK_FIELD(BundleHeader, vertices_offset, 56);
HULLCOOK_CHECK_FIELD(BundleHeader, strings_offset, 60);

static_assert(sizeof(AssetRecord) == 32);
HULLCOOK_CHECK_FIELD(AssetRecord, name_length, 4);
HULLCOOK_CHECK_FIELD(AssetRecord, flags, 6);
HULLCOOK_CHECK_FIELD(AssetRecord, first_level, 8);
HULLCOOK_CHECK_FIELD(AssetRecord, image_width, 12);
HULLCOOK_CHECK_FIELD(AssetRecord, image_height, 14);
HULLCOOK_CHECK_FIELD(AssetRecord, pixels_per_unit, 16);
HULLCOOK_CHECK_FIELD(AssetRecord, pivot_u, 20);
HULLCOOK_CHECK_FIELD(AssetRecord, pivot_v, 24);
HULLCOOK_CHECK_FIELD(AssetRecord, quant_step, 28);

static_assert(sizeof(PhysicsRecord) == 20);
HULLCOOK_CHECK_FIELD(PhysicsRecord, friction, 4);
HULLCOOK_CHECK_FIELD(PhysicsRecord, restitution, 8);
HULLCOOK_CHECK_FIELD(PhysicsRecord, category_bits, 12);
HULLCOOK_CHECK_FIELD(PhysicsRecord, mask_bits, 14);
HULLCOOK_CHECK_FIELD(PhysicsRecord, flags, 16);

static_assert(sizeof(LevelRecord) == 8);
HULLCOOK_CHECK_FIELD(LevelRecord, first_hull, 4);
static_assert(sizeof(HullRecord) == 12);
HULLCOOK_CHECK_FIELD(HullRecord, base_x, 4);
HULLCOOK_CHECK_FIELD(HullRecord, base_y, 8);
static_assert(sizeof(VertexRecord) == 4);
HULLCOOK_CHECK_FIELD(VertexRecord, dy, 2);

#undef HULLCOOK_CHECK_FIELD

static_assert(std::is_trivially_copyable_v<BundleHeader> &&
              std::is_trivially_copyable_v<AssetRecord> &&
              std::is_trivially_copyable_v<PhysicsRecord> &&
              std::is_trivially_copyable_v<LevelRecord> &&
              std::is_trivially_copyable_v<HullRecord> &&
              std::is_trivially_copyable_v<VertexRecord>);
static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559,
              "the bundle stores IEEE-754 binary32");

// Reads a record of type T at bytes (no alignment or aliasing assumption).
template <typename T>
inline T load(const unsigned char* bytes) noexcept {
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

// 32-bit FNV-1a of a name's bytes: the hash of the name table (SPEC §6).
inline std::uint32_t name_hash(const char* name, std::size_t length) noexcept {
  std::uint32_t hash = 2166136261u;
  for (std::size_t i = 0; i < length; ++i) {
    hash ^= static_cast<unsigned char>(name[i]);
    hash *= 16777619u;
  }
  return hash;
}

// Whether a hull's vertices (count VertexRecords at vertices) are strictly convex and
// counter-clockwise on the integer grid (SPEC §8): every turn strictly left, and the boundary
// winds exactly once. Exact: within-hull differences fit 17 bits, their cross products 35.
//
// The winding is counted as the edges whose direction passes from the lower half-plane (angle in
// [-pi, 0)) into the upper one ([0, pi)): with every turn in (0, pi), the direction's angle grows
// monotonically by 2 pi k in total and passes 0 exactly once per turn of the boundary, so k is
// that count. This equals SPEC §8's sign-change rule (k = 1 changes each sign twice, k >= 2 the
// sign of y at least four times) and reads each vertex once, without branches: opening a bundle
// runs it on every stored vertex.
inline bool hull_is_strictly_convex(const unsigned char* vertices, std::uint32_t count) noexcept {
  if (count < kMinHullVertices) return false;
  struct Edge {
    std::int32_t x, y;
  };
  auto upper = [](Edge e) { return static_cast<unsigned>(e.y > 0 || (e.y == 0 && e.x > 0)); };
  const VertexRecord first = load<VertexRecord>(vertices);
  VertexRecord from = load<VertexRecord>(vertices + 4);
  const Edge first_edge{from.dx - first.dx, from.dy - first.dy};
  Edge previous = first_edge;
  unsigned previous_upper = upper(first_edge);
  bool left_turns = true;
  unsigned rises = 0;
  auto turn = [&](Edge edge) {
    left_turns &= std::int64_t{previous.x} * edge.y - std::int64_t{previous.y} * edge.x > 0;
    const unsigned edge_upper = upper(edge);
    rises += ~previous_upper & edge_upper;
    previous = edge;
    previous_upper = edge_upper;
  };
  for (std::uint32_t i = 2; i < count; ++i) {
    const VertexRecord to = load<VertexRecord>(vertices + 4 * std::size_t{i});
    turn({to.dx - from.dx, to.dy - from.dy});
    from = to;
  }
  turn({first.dx - from.dx, first.dy - from.dy});  // the closing edge
  turn(first_edge);                                // and the turn back onto the first
  return left_turns && rises == 1;
}

// The slot count a writer starts from for asset_count assets: load factor <= 0.75, one slot always
// empty; more only if the table would exceed name_table_probe_budget.
inline constexpr std::uint32_t writer_slot_count(std::uint32_t asset_count) noexcept {
  return asset_count + asset_count / 3 + 1;
}

// The name table's probe budget (SPEC §6). Names crafted to share a start slot make every lookup
// walk one long run, so looking every asset up to validate the table takes quadratic time;
// readers look assets up within this budget and check the rest in one pass, and writers keep
// their tables within it, so that their files get the full check and lookups stay short. A random
// table at the writers' load factor (<= 0.75) costs about 7.5 per slot, but sequential names
// cluster: 1.4 % of realistic name sets exceed 16 per slot at the writers' first slot count.
inline constexpr std::uint64_t kNameTableProbesPerSlot = 16;

inline constexpr std::uint64_t name_table_probe_budget(std::uint32_t slot_count) noexcept {
  return kNameTableProbesPerSlot * slot_count;
}

// A name table's probe cost (SPEC §6): the occupied slots probed by looking up, once from every
// slot, a name the bundle lacks, i.e. the sum of L (L + 1) / 2 over the cyclic runs of L occupied
// slots. It also bounds the probes of finding every asset by its name (each asset sits within
// its home slot's run), which is why one number suffices for validation and for Bundle::find.
// slot_at(s) returns slot s's content; the cost is UINT64_MAX when no slot is empty (lookups of
// absent names would never end). Allocation-free, linear in slot_count.
template <typename SlotAt>
std::uint64_t name_table_probe_cost(std::uint32_t slot_count, SlotAt&& slot_at) noexcept {
  std::uint32_t empty = 0;
  while (empty < slot_count && slot_at(empty) != kEmptySlot) ++empty;
  if (empty == slot_count) return std::numeric_limits<std::uint64_t>::max();
  // Start after an empty slot so that the run wrapping past the last slot is counted whole.
  std::uint64_t cost = 0, run = 0;
  for (std::uint64_t i = 1; i <= slot_count; ++i) {
    const std::uint64_t slot = (empty + i) % slot_count;
    run = slot_at(static_cast<std::uint32_t>(slot)) == kEmptySlot ? 0 : run + 1;
    cost += run;
  }
  return cost;
}

// The largest extent, in x or y, of a hull that 16-bit deltas store at quant_step: 65 535 quanta,
// less a margin for the rounding of its end points and of quant_step to f32.
inline constexpr double kHullExtentInQuanta = 65000.0;

// The quantization error bound E of an asset (SPEC §9) [output units]: 1 % of the finest τ or
// 1/64 px, whichever is larger; or, for an asset whose largest hull extends more than 65 000
// quanta of that, the bound at which it extends 65 000 (quant_step = √2 E).
inline double quantization_error_bound(double finest_tau, double pixels_per_unit,
                                       double largest_hull_extent = 0.0) noexcept {
  return std::fmax(std::fmax(0.01 * finest_tau, 1.0 / (64.0 * pixels_per_unit)),
                   largest_hull_extent / (kHullExtentInQuanta * 1.4142135623730951));
}

// A --tile cell's step (SPEC §9) [output units]: half a pixel over the largest power of two that
// is not larger than step, so that the cell's borders, at whole or half pixels from the pivot,
// fall on the grid (and stay on it when the step is halved); 0 for a pixels per unit that leaves
// none. Exact when pixels per unit is a power of two.
inline double tile_step(double pixels_per_unit, double step) noexcept {
  double aligned = 0.5 / pixels_per_unit;
  while (aligned > step && aligned > 0.0) aligned *= 0.5;
  return aligned;
}

// A quantized coordinate in output units (SPEC §8): exact integer sum, one rounding to double.
inline double dequantize(std::int32_t base, std::int16_t delta, float quant_step) noexcept {
  return static_cast<double>(static_cast<std::int64_t>(base) + delta) *
         static_cast<double>(quant_step);
}

}  // namespace hullcook::format
