// hullcook runtime: loads cooked hull bundles (.hcb, formats/SPEC.md) inside a game.
//
// C++17 and the standard library only; no exceptions, no RTTI, no global state, and no heap
// allocation in Bundle::open() or in any lookup or accessor. Thread-safe for concurrent readers:
// every object below is a small immutable view.
//
// Usage:
//   hullcook::runtime::MappedFile file;                 // or any buffer you own
//   hullcook::runtime::Bundle bundle;
//   if (file.open("level1.hcb") != Status::ok ||
//       bundle.open(file.data(), file.size()) != Status::ok) { ... status_string(...) ... }
//   hullcook::runtime::Asset crate = bundle.find("props/crate.png");
//   hullcook::runtime::Level level = crate.select_level(0.05f);
//   for (std::size_t h = 0; h < level.hull_count(); ++h) {
//     hullcook::runtime::Vec2 points[hullcook::runtime::kMaxStackVertices];
//     std::size_t n = level.hull(h).copy_vertices(points, std::size(points));
//     ...
//   }
//
// Units: coordinates are in output units (the cooker's world units: pixels / pixels-per-unit,
// y up unless cooked with --y-down), relative to the asset's pivot. Hulls are convex and
// counter-clockwise with no repeated or collinear vertex; Placement keeps them so.
//
// Lifetime: Bundle, Asset, Level and Hull point into the caller's buffer, which must outlive
// them and stay unchanged. Default-constructed views are empty (every count is 0).
#pragma once

#include "hullcook/format/bundle_layout.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace hullcook {

// The runtime's version as "major.minor.patch"; a static string, never null.
const char* runtime_version() noexcept;

namespace runtime {

// The newest bundle format version this runtime reads (it reads every older minor version of
// the same major, SPEC §12).
inline constexpr int kFormatVersionMajor = 1;
inline constexpr int kFormatVersionMinor = 0;

// The required alignment [bytes] of a bundle buffer's start address (mmap and malloc give it).
inline constexpr std::size_t kBundleAlignment = 4;

// A convenient stack buffer size for one hull: the cooker's default cap (Box2D's 8) with room.
inline constexpr std::size_t kMaxStackVertices = 64;

// The outcome of opening a file or validating a bundle. Every failure has its own code; pass it
// to status_string() for a message.
enum class Status : std::uint8_t {
  ok = 0,
  invalid_argument,           // null data with a non-zero size, or a null path
  io_error,                   // MappedFile: the file could not be opened, mapped or read
  truncated,                  // shorter than the 64-byte header or than the header's total size
  misaligned,                 // the buffer does not start at a 4-byte aligned address
  bad_magic,                  // not a hullcook bundle
  unsupported_major_version,  // written for a newer major format version than this runtime's
  unsupported_minor_version,  // same major, newer minor version than this runtime's
  bad_checksum,               // the CRC-32 of the bytes after the header does not match
  out_of_bounds,              // a section, name or index range reaches outside its section
  malformed,                  // inconsistent content: reserved bits, non-finite or negative
                              // numbers, unordered ranges, a non-convex hull, a bad name table
};

// A short English description of status, e.g. "bad checksum (the file is corrupted)".
// A static string, never null, also for values outside the enum.
const char* status_string(Status status) noexcept;

// A point or vector [output units].
struct Vec2 {
  float x = 0.0f;
  float y = 0.0f;
};

// Optional physics properties of an asset, from `hullcook cook --density ...` or a sidecar JSON.
struct Physics {
  float density = 1.0f;      // [kg / output unit²] >= 0
  float friction = 0.2f;     // >= 0
  float restitution = 0.0f;  // >= 0
  bool sensor = false;
  std::uint16_t category_bits = 0x0001;
  std::uint16_t mask_bits = 0xFFFF;
};

// How to place a hull's vertices in the game, applied by the accessors (and so by the
// adapters) in one place: p' = mirror(p) * scale, where mirror negates x when mirror_x is set.
// Mirroring reverses the vertex order so that hulls stay counter-clockwise.
struct Placement {
  float scale = 1.0f;  // [game units / output unit] > 0
  bool mirror_x = false;
};

// One convex hull: 3 or more vertices, counter-clockwise, strictly convex.
class Hull {
 public:
  Hull() = default;
  std::size_t vertex_count() const noexcept { return count_; }
  // Vertex i (i < vertex_count()) [output units], dequantized; undefined for i out of range.
  Vec2 vertex(std::size_t i) const noexcept {
    const auto v = format::load<format::VertexRecord>(vertices_ + 4u * i);
    return {static_cast<float>(format::dequantize(base_x_, v.dx, step_)),
            static_cast<float>(format::dequantize(base_y_, v.dy, step_))};
  }
  // Vertex i of the placed hull [game units]: mirrored hulls are read backwards so that they
  // stay counter-clockwise. i < vertex_count().
  Vec2 placed_vertex(std::size_t i, Placement placement) const noexcept {
    if (!placement.mirror_x) {
      const Vec2 p = vertex(i);
      return {p.x * placement.scale, p.y * placement.scale};
    }
    const Vec2 p = vertex(count_ - 1 - i);
    return {-p.x * placement.scale, p.y * placement.scale};
  }
  // Writes min(vertex_count(), capacity) vertices, placed, counter-clockwise, to out and returns
  // vertex_count() (so a return value > capacity means out was too small and is incomplete).
  std::size_t copy_vertices(Vec2* out, std::size_t capacity,
                            Placement placement = {}) const noexcept;
  // The hull's area [output units²] (> 0) and its area centroid [output units], unplaced.
  double area() const noexcept;
  Vec2 centroid() const noexcept;

 private:
  friend class Level;
  const unsigned char* vertices_ = nullptr;
  std::size_t count_ = 0;
  std::int32_t base_x_ = 0, base_y_ = 0;
  float step_ = 0.0f;
};

// One level of detail: the decomposition at tolerance tau.
class Level {
 public:
  Level() = default;
  // [output units] the concavity tolerance τ of this level's decomposition.
  float tau() const noexcept { return tau_; }
  std::size_t hull_count() const noexcept { return hull_count_; }
  // Hull i (i < hull_count()); an empty Hull when out of range.
  Hull hull(std::size_t i) const noexcept;
  // The total number of vertices of the level's hulls.
  std::size_t vertex_count() const noexcept;

 private:
  friend class Asset;
  const unsigned char* hull_records_ = nullptr;      // the bundle's hull section
  const unsigned char* vertex_records_ = nullptr;    // the bundle's vertex section
  std::uint32_t hull_total_ = 0, vertex_total_ = 0;  // the bundle's counts
  std::uint32_t first_hull_ = 0;
  std::size_t hull_count_ = 0;
  float tau_ = 0.0f;
  float step_ = 0.0f;
};

// One cooked sprite or polygon. A default or failed-lookup Asset is empty: valid() is false,
// name() is empty, level_count() is 0.
class Asset {
 public:
  Asset() = default;
  bool valid() const noexcept { return bundle_ != nullptr; }
  explicit operator bool() const noexcept { return valid(); }

  // Its index in the bundle, in [0, Bundle::asset_count()).
  std::size_t index() const noexcept { return index_; }
  // The name given by the cooker (the path relative to the input root, '/'-separated). Points
  // into the bundle and is followed by a 0 byte, so name().data() is also a C string.
  std::string_view name() const noexcept;
  // [px] the source image's size; 0 when the asset was cooked from a polygon file.
  int image_width() const noexcept;
  int image_height() const noexcept;
  // [px / output unit]
  float pixels_per_unit() const noexcept;
  // Normalised image coordinates of the output origin: (0, 0) top left, (1, 1) bottom right.
  Vec2 pivot() const noexcept;
  // Whether output y points up (the cooker negated image y, its default) rather than down.
  bool flip_y() const noexcept;
  // The concavity measure of the decomposition: "sl", "sp", "h1", "h2", or "" when unknown.
  // A static string, never null.
  const char* measure() const noexcept;
  // [output units] the worst distance between a cooked hull and the stored one (SPEC §9).
  float quantization_error() const noexcept;

  // Levels from finest (0) to coarsest; at least one for a valid asset.
  std::size_t level_count() const noexcept { return level_count_; }
  // Level i (i < level_count()); an empty Level when out of range.
  Level level(std::size_t i) const noexcept;
  // The finest level whose τ is at least tau [output units], or the coarsest level when none is:
  // use a larger tau for far-away or cheap bodies.
  Level select_level(float tau) const noexcept;

  // Whether the cooker stored physics properties for this asset; physics() returns them, or
  // the defaults of Physics when it did not.
  bool has_physics() const noexcept;
  Physics physics() const noexcept;

 private:
  friend class Bundle;
  const unsigned char* bundle_ = nullptr;
  const unsigned char* record_ = nullptr;
  std::size_t index_ = 0;
  std::size_t level_count_ = 0;
};

// A validated bundle in a caller-owned buffer. Copying a Bundle copies the view only.
class Bundle {
 public:
  Bundle() = default;

  // Validates size bytes at data completely (bounds, counts, offsets, alignment, checksum,
  // version, hull convexity, the name table: formats/SPEC.md §11) and on success makes this
  // view refer to them. Returns the first problem found; on failure the Bundle is empty.
  // Costs one pass over the bytes (CRC-32) plus one over the records; allocates nothing.
  // data must be 4-byte aligned; bytes after the bundle's total size are ignored.
  Status open(const void* data, std::size_t size) noexcept;

  bool empty() const noexcept { return bytes_ == nullptr; }
  // [bytes] the bundle's total size (its header's), 0 when empty.
  std::size_t size() const noexcept { return size_; }
  // The format version of the opened bundle.
  int version_major() const noexcept;
  int version_minor() const noexcept;

  std::size_t asset_count() const noexcept { return asset_count_; }
  // Asset i (i < asset_count()); an empty Asset when out of range.
  Asset asset(std::size_t i) const noexcept;
  // The asset with exactly this name (byte comparison), in O(1) expected time; an empty Asset
  // when there is none.
  Asset find(std::string_view name) const noexcept;

  // Totals over all assets and levels.
  std::size_t level_count() const noexcept;
  std::size_t hull_count() const noexcept;
  std::size_t vertex_count() const noexcept;

 private:
  const unsigned char* bytes_ = nullptr;
  std::size_t size_ = 0;
  std::size_t asset_count_ = 0;
};

// A read-only view of a whole file: memory-mapped where the platform has POSIX mmap, else read
// into a buffer allocated once with std::malloc. Move-only; unmaps or frees on destruction.
// The data are page aligned (mmap) or malloc aligned, so they can be passed to Bundle::open.
class MappedFile {
 public:
  MappedFile() = default;
  ~MappedFile();
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  // Maps the file at path (closing any file held before). Returns ok, invalid_argument (null
  // path) or io_error. An empty file opens with data() == nullptr and size() == 0.
  Status open(const char* path) noexcept;
  void close() noexcept;

  const void* data() const noexcept { return data_; }
  std::size_t size() const noexcept { return size_; }

 private:
  void* data_ = nullptr;
  std::size_t size_ = 0;
  bool mapped_ = false;
};

}  // namespace runtime
}  // namespace hullcook
