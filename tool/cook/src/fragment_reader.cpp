#include "hullcook/cook/fragment.h"

#include "hullcook/cook/contract.h"

#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/format/crc32.h"
#include "hullcook/format/fragment_layout.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

namespace hullcook {
namespace {

using format::FragmentHeader;

// Reads the payload's encoding (FRAGMENT.md §3) with every read bounded, so that a malformed
// fragment is refused, never read past its end.
class Decoder {
 public:
  Decoder(std::string_view bytes, std::size_t at, const std::string& file)
      : bytes_(bytes), at_(at), file_(file) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(file_ + ": malformed fragment: " + problem + " (at byte " +
                     std::to_string(at_) + "); cook it again");
  }

  template <typename T>
  T raw(const char* what) {
    if (bytes_.size() - at_ < sizeof(T)) fail(std::string("it ends inside ") + what);
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  double f64(const char* what) {
    const double value = raw<double>(what);
    if (!std::isfinite(value)) fail(std::string("a non-finite ") + what);
    return value;
  }
  Vec2 point(const char* what) {
    const double x = f64(what);
    return {x, f64(what)};
  }
  // A count of items at least item_size bytes each: never more than the bytes left could hold,
  // so that a corrupt count cannot make us allocate without bound.
  std::size_t count(const char* what, std::size_t item_size) {
    const std::uint32_t n = raw<std::uint32_t>(what);
    if (n > (bytes_.size() - at_) / item_size)
      fail(std::string("a count of ") + what + " too large");
    return n;
  }
  std::string string(const char* what) {
    const std::size_t length = count(what, 1);
    std::string text(bytes_.substr(at_, length));
    at_ += length;
    return text;
  }
  Ring ring(const char* what, std::size_t min_size) {
    const std::size_t n = count(what, 16);
    if (n < min_size)
      fail(std::string("a ring of fewer than ") + std::to_string(min_size) + " " + what);
    Ring ring;
    ring.reserve(n);
    for (std::size_t i = 0; i < n; ++i) ring.push_back(point(what));
    return ring;
  }
  // A hull, which the writers take as convex and counter-clockwise: a corrupt one (its bytes
  // changed and the checksum made to match) was written on as it was, clockwise or folded.
  Ring hull(const std::string& which) {
    const std::size_t start = at_;
    Ring ring = this->ring("hull vertices", 3);
    if (std::optional<std::string> defect = hull_shape_defect(ring)) {
      at_ = start;
      fail(which + ": " + *defect);
    }
    return ring;
  }
  Region region() {
    Region region;
    region.outer = ring("outline vertices", 3);
    const std::size_t holes = count("holes", 4);
    region.holes.reserve(holes);
    for (std::size_t h = 0; h < holes; ++h) region.holes.push_back(ring("hole vertices", 3));
    return region;
  }
  std::size_t at() const { return at_; }

 private:
  std::string_view bytes_;
  std::size_t at_;
  const std::string& file_;
};

CookedAsset decode_asset(Decoder& in) {
  CookedAsset asset;
  asset.name = in.string("name");
  if (asset.name.empty()) in.fail("an asset without a name");
  asset.source = in.string("source");
  asset.image_width = in.raw<std::int32_t>("image width");
  asset.image_height = in.raw<std::int32_t>("image height");
  if (asset.image_width < 0 || asset.image_height < 0) in.fail("a negative image size");
  asset.pixels_per_unit = in.f64("pixels per unit");
  if (!stores_as_positive_float(asset.pixels_per_unit)) {
    in.fail("pixels per unit not a positive 32-bit float");
  }
  asset.pivot = in.point("pivot");
  asset.transform.scale = in.f64("transform");
  asset.transform.origin = in.point("transform");
  const auto flags = in.raw<std::uint32_t>("asset flags");
  if (flags & ~format::kFragmentKnownFlags) in.fail("unknown asset flags");
  asset.transform.flip_y = (flags & format::kFragmentFlipY) != 0;
  asset.tile = (flags & format::kFragmentTile) != 0;
  asset.tau = in.f64("tau");
  if (!(asset.tau >= 0)) in.fail("a negative tau");
  asset.measure = in.string("measure");
  if (!parse_measure(asset.measure)) {
    in.fail("an unknown measure '" + asset.measure + "'");
  }
  const std::size_t regions = in.count("regions", 8);
  for (std::size_t r = 0; r < regions; ++r) asset.regions.push_back(in.region());
  const std::size_t pieces = in.count("pieces", 8);
  for (std::size_t p = 0; p < pieces; ++p) {
    CookedPiece piece;
    piece.component = in.region();
    piece.hull = in.hull("piece " + std::to_string(p + 1));
    piece.concavity = in.f64("concavity");
    asset.pieces.push_back(std::move(piece));
  }
  const std::size_t levels = in.count("levels", 12);
  for (std::size_t l = 0; l < levels; ++l) {
    CookedLevel level;
    level.tau = in.f64("level tau");
    if (!(level.tau >= 0)) in.fail("a negative level tau");
    const std::size_t hulls = in.count("hulls", 4);
    for (std::size_t h = 0; h < hulls; ++h) {
      level.hulls.push_back(
          in.hull("level " + std::to_string(l + 1) + ", hull " + std::to_string(h + 1)));
    }
    asset.levels.push_back(std::move(level));
  }
  if (flags & format::kFragmentHasPhysics) {
    PhysicsProperties physics;
    physics.density = in.raw<float>("physics");
    physics.friction = in.raw<float>("physics");
    physics.restitution = in.raw<float>("physics");
    for (float value : {physics.density, physics.friction, physics.restitution}) {
      if (!(value >= 0) || !std::isfinite(value)) in.fail("a physics property not finite and >= 0");
    }
    physics.category_bits = in.raw<std::uint16_t>("physics");
    physics.mask_bits = in.raw<std::uint16_t>("physics");
    const auto physics_flags = in.raw<std::uint32_t>("physics");
    if (physics_flags & ~format::kFragmentSensor) in.fail("unknown physics flags");
    physics.sensor = (physics_flags & format::kFragmentSensor) != 0;
    asset.physics = physics;
  }
  if (flags & format::kFragmentHasQuantizationError) {
    asset.quantization_error = in.f64("quantization error");
  }
  const std::size_t warnings = in.count("warnings", 4);
  for (std::size_t w = 0; w < warnings; ++w) asset.warnings.push_back(in.string("warning"));
  asset.stats.traced_vertices = in.raw<std::uint64_t>("statistics");
  asset.stats.pieces = in.raw<std::uint64_t>("statistics");
  asset.stats.max_concavity = in.f64("statistics");
  asset.stats.convexity = in.f64("statistics");
  return asset;
}

// The header's own checks, for a file of file_size bytes that starts with start (its first
// bytes, at least the header's when the file holds them): a reader learns from them alone
// whether the file is worth reading whole.
FragmentHeader check_header(std::string_view start, std::uint64_t file_size,
                            const std::string& file) {
  const std::size_t magic_size = sizeof(format::kFragmentMagic);
  if (std::memcmp(start.data(), format::kFragmentMagic, std::min(start.size(), magic_size)) != 0) {
    throw InputError(file + ": not a hullcook fragment (.hcf, written by hullcook cook -o X.hcf)");
  }
  if (file_size < sizeof(FragmentHeader) || start.size() < sizeof(FragmentHeader)) {
    throw InputError(file + ": truncated fragment: " + std::to_string(file_size) +
                     " bytes, shorter than its header");
  }
  FragmentHeader header;
  std::memcpy(&header, start.data(), sizeof(header));
  if (header.format_version != format::kFragmentVersion) {
    throw InputError(file + ": fragment format version " + std::to_string(header.format_version) +
                     ", this hullcook links version " + std::to_string(format::kFragmentVersion) +
                     " only; cook it again");
  }
  const std::string version(header.tool_version,
                            strnlen(header.tool_version, sizeof(header.tool_version)));
  if (version != tool_version()) {
    throw InputError(file + ": cooked by hullcook " + version + ", this is hullcook " +
                     tool_version() + "; cook it again");
  }
  if (header.total_size > file_size) {
    throw InputError(file + ": truncated fragment: " + std::to_string(file_size) + " bytes of " +
                     std::to_string(header.total_size));
  }
  if (header.total_size < file_size) {
    throw InputError(file + ": malformed fragment: " + std::to_string(file_size) +
                     " bytes where its header says " + std::to_string(header.total_size));
  }
  return header;
}

FragmentHeader read_header(std::string_view bytes, const std::string& file) {
  const FragmentHeader header = check_header(bytes, bytes.size(), file);
  FragmentHeader unsummed = header;
  unsummed.checksum = 0;
  std::uint32_t checksum = format::crc32(0, &unsummed, sizeof(unsummed));
  checksum = format::crc32(checksum, bytes.data() + sizeof(header), bytes.size() - sizeof(header));
  if (checksum != header.checksum) {
    throw InputError(file + ": corrupt fragment: bad checksum; cook it again");
  }
  if (header.flags != 0) {
    throw InputError(file + ": malformed fragment: unknown header flags; cook it again");
  }
  return header;
}

}  // namespace

Fragment parse_fragment(std::string_view bytes, const std::string& file) {
  const FragmentHeader header = read_header(bytes, file);
  Fragment fragment;
  fragment.tool_version = tool_version();
  fragment.settings_hash = header.settings_hash;
  Decoder in(bytes, sizeof(FragmentHeader), file);
  fragment.settings = in.string("settings");
  if (format::fnv1a_64(fragment.settings.data(), fragment.settings.size()) !=
      header.settings_hash) {
    in.fail("the settings do not match their hash");
  }
  if (header.asset_count > bytes.size()) in.fail("an asset count too large");
  fragment.assets.reserve(header.asset_count);
  for (std::uint32_t a = 0; a < header.asset_count; ++a) {
    fragment.assets.push_back(decode_asset(in));
  }
  if (in.at() != bytes.size()) in.fail("bytes after the last asset");
  return fragment;
}

Fragment read_fragment(const std::filesystem::path& path) {
  refuse_unless_regular_file(path);
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(path.string() + ": a directory, not a fragment (.hcf)");
  }
  if (!std::filesystem::exists(path, error) && !error) {
    throw InputError(path.string() + ": no such file or directory");
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path.string() + ": cannot read");
  // The header first: a fragment with a gigabyte of anything after it was read whole (20 s and
  // a gigabyte of memory) before its size was found wrong.
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error) throw InputError(path.string() + ": cannot read");
  std::string start(std::min<std::uint64_t>(size, sizeof(FragmentHeader)), '\0');
  stream.read(start.data(), static_cast<std::streamsize>(start.size()));
  if (!stream) throw InputError(path.string() + ": cannot read");
  check_header(start, size, path.string());
  std::ostringstream bytes;
  bytes << start << stream.rdbuf();
  if (!stream && !stream.eof()) throw InputError(path.string() + ": cannot read");
  return parse_fragment(bytes.view(), path.string());
}

}  // namespace hullcook
