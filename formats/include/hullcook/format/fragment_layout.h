// The byte layout of a cooked fragment (.hcf), version 1, exactly as formats/FRAGMENT.md
// describes it: the header's record and the constants of the payload's encoding. A fragment is
// the tool's own intermediate (`hullcook cook X -o x.hcf`, then `hullcook link`); games never
// read it. C++17, standard library only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "hullcook fragments are little-endian; big-endian hosts are not supported"
#endif

namespace hullcook::format {

inline constexpr std::uint8_t kFragmentMagic[4] = {0x48, 0x43, 0x46, 0x1A};  // "HCF" Ctrl-Z
// Any change of the payload's encoding changes it: link reads exactly its own version.
inline constexpr std::uint16_t kFragmentVersion = 1;
// [bytes] of the tool version field, a NUL-padded string such as "0.1.0".
inline constexpr std::size_t kToolVersionSize = 32;

// Asset flags in the payload (FRAGMENT.md §4).
inline constexpr std::uint32_t kFragmentFlipY = 1u << 0;
inline constexpr std::uint32_t kFragmentHasPhysics = 1u << 1;
inline constexpr std::uint32_t kFragmentHasQuantizationError = 1u << 2;
inline constexpr std::uint32_t kFragmentTile = 1u << 3;
inline constexpr std::uint32_t kFragmentKnownFlags =
    kFragmentFlipY | kFragmentHasPhysics | kFragmentHasQuantizationError | kFragmentTile;
// Physics flags in the payload.
inline constexpr std::uint32_t kFragmentSensor = 1u << 0;

struct FragmentHeader {
  std::uint8_t magic[4];
  std::uint16_t format_version;
  std::uint16_t flags;  // reserved, 0
  std::uint32_t asset_count;
  std::uint32_t checksum;       // CRC-32 of the whole fragment, this field read as 0
  std::uint64_t total_size;     // [bytes] header included
  std::uint64_t settings_hash;  // FNV-1a 64 of the settings text, the payload's first string
  char tool_version[kToolVersionSize];
};

#define HULLCOOK_CHECK_FIELD(record, field, offset) \
  static_assert(offsetof(record, field) == (offset), #record "::" #field " is at " #offset)

static_assert(sizeof(FragmentHeader) == 64);
HULLCOOK_CHECK_FIELD(FragmentHeader, format_version, 4);
HULLCOOK_CHECK_FIELD(FragmentHeader, flags, 6);
HULLCOOK_CHECK_FIELD(FragmentHeader, asset_count, 8);
HULLCOOK_CHECK_FIELD(FragmentHeader, checksum, 12);
HULLCOOK_CHECK_FIELD(FragmentHeader, total_size, 16);
HULLCOOK_CHECK_FIELD(FragmentHeader, settings_hash, 24);
HULLCOOK_CHECK_FIELD(FragmentHeader, tool_version, 32);
static_assert(std::is_trivially_copyable_v<FragmentHeader>);

#undef HULLCOOK_CHECK_FIELD

// 64-bit FNV-1a: the settings hash.
inline std::uint64_t fnv1a_64(const char* bytes, std::size_t length) noexcept {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < length; ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace hullcook::format
