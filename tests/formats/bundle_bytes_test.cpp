// The .hcb format's bytes: golden files of every version written and read, and rejection of every
// truncation, flipped byte and mutation with its own status; the checksum against its definition.
#include "bundle_bytes.h"
#include "synthetic_assets.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/cook.h"
#include "hullcook/format/bundle_layout.h"
#include "hullcook/format/crc32.h"
#include "hullcook/runtime.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace hullcook {
namespace {

using runtime::Bundle;
using runtime::Status;
using test::AlignedBytes;
using test::kGoldenDir;
using test::read_file;
namespace fs = std::filesystem;

Status open_bytes(const std::string& bytes, Bundle* out = nullptr) {
  AlignedBytes aligned(bytes);
  Bundle bundle;
  const Status status = bundle.open(aligned.data(), aligned.size);
  if (status == Status::ok) test::touch_everything(bundle);
  if (out) *out = Bundle{};
  return status;
}

void fix_checksum(std::string& bytes) {
  format::BundleHeader header =
      format::load<format::BundleHeader>(reinterpret_cast<const unsigned char*>(bytes.data()));
  if (header.total_size < sizeof(header) || header.total_size > bytes.size()) return;
  header.checksum =
      format::crc32(0, bytes.data() + sizeof(header), header.total_size - sizeof(header));
  std::memcpy(bytes.data(), &header, sizeof(header));
}

// ---- Golden files -----------------------------------------------------------------------------

TEST(Golden, WriterReproducesTheCurrentVersionByteForByte) {
  const fs::path golden = kGoldenDir / "v1.0/synthetic.hcb";
  const std::string bytes = write_bundle(test::synthetic_assets());
  if (const char* update = std::getenv("HULLCOOK_UPDATE_GOLDEN");
      update && std::string(update) == "1") {
    fs::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << bytes;
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; run with HULLCOOK_UPDATE_GOLDEN=1";
  EXPECT_TRUE(read_file(golden) == bytes)
      << golden << " differs from the writer's output: a format change needs a new version";
}

// The settings of tests/formats/golden/v*/sprites.hcb: every sample sprite, τ = 2 px with an
// 8 px level of detail, 32 px per unit.
Settings golden_sprite_settings() {
  Settings settings;
  settings.tau = Tolerance{2.0, false};
  settings.lods = {Tolerance{8.0, false}};
  settings.pixels_per_unit = 32;
  return settings;
}

TEST(Golden, RecookingTheSamplesReproducesTheGoldenBundle) {
  const fs::path golden = kGoldenDir / "v1.0/sprites.hcb";
  const CookResult result =
      cook({fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites"}, golden_sprite_settings());
  const std::string bytes = write_bundle(result.assets);
  if (const char* update = std::getenv("HULLCOOK_UPDATE_GOLDEN");
      update && std::string(update) == "1") {
    std::ofstream(golden, std::ios::binary) << bytes;
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; run with HULLCOOK_UPDATE_GOLDEN=1";
  EXPECT_TRUE(read_file(golden) == bytes)
      << golden << " differs from a re-cook of samples/sprites: the cooker's output changed";
}

TEST(Golden, ReaderAcceptsEveryGoldenFileOfEverySupportedVersion) {
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kGoldenDir)) {
    if (entry.path().extension() != ".hcb") continue;
    ++files;
    const std::string bytes = read_file(entry.path());
    AlignedBytes aligned(bytes);
    Bundle bundle;
    ASSERT_EQ(bundle.open(aligned.data(), aligned.size), Status::ok) << entry.path();
    const std::string folder = entry.path().parent_path().filename().string();
    EXPECT_EQ(folder, "v" + std::to_string(bundle.version_major()) + "." +
                          std::to_string(bundle.version_minor()))
        << entry.path();
    EXPECT_GT(bundle.asset_count(), 0u);
    for (std::size_t i = 0; i < bundle.asset_count(); ++i)
      EXPECT_EQ(bundle.find(bundle.asset(i).name()).index(), i) << entry.path();
    test::touch_everything(bundle);
  }
  EXPECT_GE(files, 1u);
}

// ---- Corruption -------------------------------------------------------------------------------

std::string golden_bytes() { return read_file(kGoldenDir / "v1.0/synthetic.hcb"); }

TEST(Corruption, EveryTruncatedPrefixIsRejectedAsTruncated) {
  const std::string bytes = golden_bytes();
  ASSERT_FALSE(bytes.empty());
  for (std::size_t length = 0; length < bytes.size(); ++length)
    ASSERT_EQ(open_bytes(bytes.substr(0, length)), Status::truncated) << "prefix " << length;
  EXPECT_EQ(open_bytes(bytes), Status::ok);
  EXPECT_EQ(open_bytes(bytes + std::string(5, '\x7f')), Status::ok) << "trailing bytes are ignored";
}

// The status a flipped byte at offset must produce (SPEC §11 order).
Status expected_for_flip(std::size_t offset, std::uint8_t original, std::uint8_t flipped) {
  if (offset < 4) return Status::bad_magic;
  if (offset == 4)
    return flipped > original ? Status::unsupported_major_version : Status::malformed;
  if (offset == 5) return Status::unsupported_minor_version;  // the goldens have minor 0
  return Status::ok;  // any other failure status (checked by the caller)
}

TEST(Corruption, EverySingleFlippedByteOrBitIsRejected) {
  const std::string bytes = golden_bytes();
  ASSERT_FALSE(bytes.empty());
  for (std::size_t offset = 0; offset < bytes.size(); ++offset) {
    for (unsigned mask : {0xFFu, 0x01u, 0x80u, 0x10u}) {
      std::string corrupt = bytes;
      corrupt[offset] = static_cast<char>(corrupt[offset] ^ mask);
      const Status status = open_bytes(corrupt);
      ASSERT_NE(status, Status::ok) << "offset " << offset << " mask " << mask;
      const Status expected = expected_for_flip(offset, static_cast<std::uint8_t>(bytes[offset]),
                                                static_cast<std::uint8_t>(corrupt[offset]));
      if (expected != Status::ok) {
        ASSERT_EQ(status, expected) << "offset " << offset;
      } else if (offset >= 12) {
        // The checksum field itself, the payload, and a smaller total size all fail the CRC;
        // a larger total size is truncation; counts and offsets fail the layout checks.
        if (offset >= 64 || offset < 16) {
          ASSERT_EQ(status, Status::bad_checksum) << "offset " << offset;
        } else {
          ASSERT_TRUE(status == Status::malformed || status == Status::out_of_bounds ||
                      status == Status::misaligned || status == Status::truncated)
              << "offset " << offset << ": " << runtime::status_string(status);
        }
      } else {  // flags and total size
        ASSERT_TRUE(status == Status::malformed || status == Status::truncated ||
                    status == Status::bad_checksum)
            << "offset " << offset << ": " << runtime::status_string(status);
      }
    }
  }
}

// Flips with the checksum repaired reach the structural checks; each must still be caught or,
// when the mutation happens to produce a valid bundle (a different but legal coordinate), be
// readable without any out-of-bounds access (the sanitizers watch touch_everything).
TEST(Corruption, FlipsWithARepairedChecksumReachTheStructuralChecks) {
  const std::string bytes = golden_bytes();
  std::size_t rejected = 0;
  for (std::size_t offset = 16; offset < bytes.size(); ++offset) {
    std::string corrupt = bytes;
    corrupt[offset] = static_cast<char>(corrupt[offset] ^ 0xFF);
    fix_checksum(corrupt);
    if (open_bytes(corrupt) != Status::ok) ++rejected;
  }
  EXPECT_GT(rejected, (bytes.size() - 16) / 4);
}

TEST(Corruption, FuzzedMutationsNeverCrash) {
  const std::string golden = golden_bytes();
  ASSERT_FALSE(golden.empty());
  std::mt19937 random(0x5EED);
  std::size_t accepted = 0;
  for (int round = 0; round < 6000; ++round) {
    std::string bytes = golden;
    const int edits = 1 + static_cast<int>(random() % 8);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = random() % bytes.size();
      switch (random() % 5) {
        case 0:
          bytes[at] = static_cast<char>(random());
          break;
        case 1:
          bytes[at] = static_cast<char>(bytes[at] ^ (1u << (random() % 8)));
          break;
        case 2: {  // an extreme 32-bit value, aligned
          const std::uint32_t values[] = {0, 1, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0xFFFF};
          const std::size_t word = (at & ~std::size_t{3});
          if (word + 4 <= bytes.size()) std::memcpy(bytes.data() + word, &values[random() % 6], 4);
          break;
        }
        case 3:
          bytes.resize(at + 1);
          break;
        default:
          bytes.insert(at, 1, static_cast<char>(random()));
          break;
      }
    }
    if (random() % 2) fix_checksum(bytes);
    if (open_bytes(bytes) == Status::ok) ++accepted;
  }
  // Most mutations are caught; some (e.g. a legal vertex moved) are valid bundles.
  EXPECT_LT(accepted, 6000u / 2);
}

TEST(Corruption, DistinctStatusesForDistinctProblems) {
  const std::string bytes = golden_bytes();
  ASSERT_FALSE(bytes.empty());
  Bundle bundle;
  EXPECT_EQ(bundle.open(nullptr, 10), Status::invalid_argument);
  EXPECT_EQ(bundle.open(nullptr, 0), Status::truncated);

  std::string copy = bytes;
  copy[0] = 'X';
  EXPECT_EQ(open_bytes(copy), Status::bad_magic);
  copy = bytes;
  copy[4] = 2;
  EXPECT_EQ(open_bytes(copy), Status::unsupported_major_version);
  copy = bytes;
  copy[5] = 1;
  EXPECT_EQ(open_bytes(copy), Status::unsupported_minor_version);
  copy = bytes;
  copy[100] ^= 1;
  EXPECT_EQ(open_bytes(copy), Status::bad_checksum);

  // A buffer at an odd address.
  std::vector<std::uint32_t> words(bytes.size() / 4 + 2);
  auto* odd = reinterpret_cast<unsigned char*>(words.data()) + 1;
  std::memcpy(odd, bytes.data(), bytes.size());
  EXPECT_EQ(bundle.open(odd, bytes.size()), Status::misaligned);
  EXPECT_TRUE(bundle.empty());

  // A misaligned section offset, with a valid checksum.
  copy = bytes;
  format::BundleHeader header =
      format::load<format::BundleHeader>(reinterpret_cast<const unsigned char*>(copy.data()));
  header.levels_offset += 2;
  std::memcpy(copy.data(), &header, sizeof(header));
  EXPECT_EQ(open_bytes(copy), Status::misaligned);

  // A hull made reflex, with a valid checksum.
  copy = bytes;
  header = format::load<format::BundleHeader>(reinterpret_cast<const unsigned char*>(copy.data()));
  const format::VertexRecord first = format::load<format::VertexRecord>(
      reinterpret_cast<const unsigned char*>(copy.data()) + header.vertices_offset);
  // Move vertex 1 of hull 0 onto vertex 0: a repeated vertex.
  std::memcpy(copy.data() + header.vertices_offset + 4, &first, 4);
  fix_checksum(copy);
  EXPECT_EQ(open_bytes(copy), Status::malformed);

  // Two assets with the same name, with a valid checksum.
  const std::string with_names =
      write_bundle({test::make_asset("aa", {{0.0, {test::rectangle(0, 0, 1, 1)}}}),
                    test::make_asset("ab", {{0.0, {test::rectangle(0, 0, 1, 1)}}})});
  copy = with_names;
  const auto pos = copy.rfind("ab");
  copy[pos + 1] = 'a';
  fix_checksum(copy);
  EXPECT_EQ(open_bytes(copy), Status::malformed);

  for (int s = 0; s <= static_cast<int>(Status::malformed) + 1; ++s)
    EXPECT_GT(std::strlen(runtime::status_string(static_cast<Status>(s))), 1u);
}

}  // namespace
}  // namespace hullcook

namespace hullcook {
namespace {

TEST(Crc32, MatchesTheStandardCheckValueAtEveryLengthAndSplit) {
  EXPECT_EQ(format::crc32(0, "123456789", 9), 0xCBF43926u);  // CRC-32/ISO-HDLC check value
  // The 8-byte path against the bytewise definition, on every length and alignment.
  std::string text;
  for (int i = 0; i < 100; ++i) text.push_back(static_cast<char>(i * 37 + 11));
  auto bitwise = [](const std::string& s) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char byte : s) {
      c ^= byte;
      for (int b = 0; b < 8; ++b) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return ~c;
  };
  for (std::size_t start = 0; start < 8; ++start)
    for (std::size_t length = 0; start + length <= text.size(); ++length) {
      const std::string part = text.substr(start, length);
      ASSERT_EQ(format::crc32(0, text.data() + start, length), bitwise(part));
      const std::size_t half = length / 3;
      ASSERT_EQ(
          format::crc32(format::crc32(0, part.data(), half), part.data() + half, length - half),
          bitwise(part));
    }
}

// Large inputs run as several chains whose states are combined, or are folded 64 bytes at a time
// (crc32.cpp): around the sizes where those start, and at sizes that leave every kind of
// remainder, against the bitwise definition. crc32 folds with PCLMULQDQ where the CPU has it;
// crc32_portable is the slicing method everywhere.
TEST(Crc32, LargeInputsMatchTheBitwiseDefinitionByEitherMethod) {
  std::string bytes(3 * 4096 * 5 + 77, '\0');
  std::uint32_t seed = 12345;
  for (char& byte : bytes) byte = static_cast<char>((seed = seed * 1103515245u + 12345u) >> 23);
  auto bitwise = [](std::uint32_t crc, const char* data, std::size_t size) {
    std::uint32_t c = ~crc;
    for (std::size_t i = 0; i < size; ++i) {
      c ^= static_cast<unsigned char>(data[i]);
      for (int b = 0; b < 8; ++b) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return ~c;
  };
  const std::initializer_list<std::size_t> sizes = {63,
                                                    64,
                                                    65,
                                                    79,
                                                    80,
                                                    127,
                                                    128,
                                                    129,
                                                    3 * 4096 - 1,
                                                    3 * 4096,
                                                    3 * 4096 + 15,
                                                    3 * 4096 + 47,
                                                    3 * 4096 + 48,
                                                    3 * 4096 * 2 + 33,
                                                    bytes.size() - 3};
  for (auto crc32 : {format::crc32, format::crc32_portable})
    for (std::size_t size : sizes)
      for (std::size_t start : {0u, 1u, 3u}) {
        ASSERT_EQ(crc32(0, bytes.data() + start, size), bitwise(0, bytes.data() + start, size))
            << size << " bytes from " << start;
        // A running CRC continues through every path.
        ASSERT_EQ(crc32(0xDEADBEEFu, bytes.data() + start, size),
                  bitwise(0xDEADBEEFu, bytes.data() + start, size));
      }
}

}  // namespace
}  // namespace hullcook
