// Fragments (formats/FRAGMENT.md): lossless for every writer, deterministic, and every malformed
// or truncated fragment refused as bad input naming the file.
#include "hullcook/cook/fragment.h"
#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/cook.h"
#include "hullcook/cook/gltf_writer.h"
#include "hullcook/core/error.h"
#include "hullcook/format/crc32.h"
#include "hullcook/format/fragment_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

namespace hullcook {
namespace {

const std::filesystem::path kSprites =
    std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";

// A small sprite with holes and several pieces, and one more: a fragment of two assets.
std::vector<std::filesystem::path> two_sprites() {
  return {kSprites / "pingus__groundpieces__bridge__space__grid1.png",
          kSprites / "frozen-bubble__balls__bubble-1-mini.png"};
}

Settings rich_settings() {
  Settings settings;
  settings.tau = Tolerance{1.0, false};
  settings.lods = {Tolerance{4.0, false}, Tolerance{12.0, false}};
  settings.pixels_per_unit = 32;
  settings.physics = PhysicsProperties{2.5f, 0.7f, 0.1f, true, 0x0004, 0x00F0};
  return settings;
}

// Small, so that sweeps over every byte stay quick, but with two assets, levels and physics.
std::string fragment_bytes() {
  const Settings settings = rich_settings();
  const std::vector<std::filesystem::path> small = {
      kSprites / "frozen-bubble__balls__stick_effect_2.png",
      kSprites / "frozen-bubble__balls__bubble-1-mini.png"};
  return write_fragment(cook(small, settings).assets, settings);
}

// Parses bytes and returns the InputError's message ("" if it parsed).
std::string refusal(const std::string& bytes) {
  try {
    parse_fragment(bytes, "sprites.hcf");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void restamp_checksum(std::string& bytes) {
  std::memset(bytes.data() + offsetof(format::FragmentHeader, checksum), 0, 4);
  const std::uint32_t checksum = format::crc32(0, bytes.data(), bytes.size());
  std::memcpy(bytes.data() + offsetof(format::FragmentHeader, checksum), &checksum, 4);
}

TEST(Fragment, ReadsBackWhatEveryWriterNeeds) {
  const Settings settings = rich_settings();
  CookResult cooked = cook(two_sprites(), settings);
  cooked.assets[0].quantization_error = 0.125;  // set only when read back from a bundle
  const std::string bytes = write_fragment(cooked.assets, settings);
  const Fragment fragment = parse_fragment(bytes, "sprites.hcf");
  ASSERT_EQ(fragment.assets.size(), 2u);
  EXPECT_EQ(fragment.tool_version, tool_version());
  EXPECT_EQ(fragment.settings, settings_text(settings));
  // Re-encoding what was read gives the same bytes: the reader drops nothing the writer stores.
  EXPECT_EQ(write_fragment(fragment.assets, settings), bytes);
  // The writers see the same assets, but for the source, kept as a file name.
  for (CookedAsset& asset : cooked.assets) {
    asset.source = std::filesystem::path(asset.source).filename().string();
  }
  EXPECT_EQ(write_bundle(fragment.assets), write_bundle(cooked.assets));
  EXPECT_EQ(write_gltf(fragment.assets, {true, false}), write_gltf(cooked.assets, {true, false}));
  EXPECT_EQ(fragment.assets[1].levels.size(), 3u);
  EXPECT_TRUE(fragment.assets[1].physics->sensor);
  EXPECT_EQ(fragment.assets[0].quantization_error, 0.125);
}

TEST(Fragment, SameBytesWhateverTheThreadCount) {
  Settings settings = rich_settings();
  settings.threads = 1;
  const std::string one = write_fragment(cook(two_sprites(), settings).assets, settings);
  settings.threads = 2;
  EXPECT_EQ(write_fragment(cook(two_sprites(), settings).assets, settings), one);
}

TEST(Fragment, SettingsTextSeesEverySettingThatChangesAnAsset) {
  const Settings base = rich_settings();
  std::vector<Settings> changed(13, base);
  changed[0].tau.value = 1.0000001;
  changed[1].tau.relative = true;
  changed[2].measure = "sp";
  changed[3].lods.pop_back();
  changed[4].alpha = 127;
  changed[5].color_key = std::array<std::uint8_t, 3>{255, 0, 255};
  changed[6].simplify = 0.25;
  changed[7].pixels_per_unit = 33;
  changed[8].pivot_v = 1.0;
  changed[9].max_verts = 0;
  changed[10].weld = 0.01;
  changed[11].physics->mask_bits = 1;
  changed[12].grid = Grid{64, 64, 0, 0};
  for (std::size_t i = 0; i < changed.size(); ++i) {
    EXPECT_NE(settings_text(changed[i]), settings_text(base)) << "change " << i;
  }
  Settings unchanged = base;
  unchanged.threads = 7;
  unchanged.draco = true;
  EXPECT_EQ(settings_text(unchanged), settings_text(base));
}

TEST(Fragment, EveryTruncationIsRefusedNamingTheFile) {
  const std::string bytes = fragment_bytes();
  ASSERT_GT(bytes.size(), 1000u);
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    const std::string message = refusal(bytes.substr(0, size));
    ASSERT_NE(message.find("sprites.hcf: "), std::string::npos) << size << ": " << message;
  }
  EXPECT_EQ(refusal(bytes), "");
  EXPECT_NE(refusal(bytes + '\0').find("bytes where its header says"), std::string::npos);
}

// The header's size and checksum catch a plain truncation; these prefixes claim to be whole, so
// that every read of the payload's decoder meets the end of the bytes.
TEST(Fragment, EveryPrefixPassedOffAsWholeIsRefusedByTheDecoder) {
  const std::string bytes = fragment_bytes();
  for (std::size_t size = sizeof(format::FragmentHeader); size < bytes.size(); ++size) {
    std::string prefix = bytes.substr(0, size);
    const std::uint64_t total_size = size;
    std::memcpy(prefix.data() + offsetof(format::FragmentHeader, total_size), &total_size, 8);
    restamp_checksum(prefix);
    const std::string message = refusal(prefix);
    ASSERT_NE(message.find("sprites.hcf: malformed fragment: "), std::string::npos)
        << size << ": " << message;
  }
}

TEST(Fragment, EveryFlippedByteIsRefused) {
  const std::string bytes = fragment_bytes();
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::string corrupt = bytes;
    corrupt[at] = static_cast<char>(corrupt[at] ^ 0x40);
    ASSERT_NE(refusal(corrupt), "") << "byte " << at;
  }
}

TEST(Fragment, AnotherVersionIsRefusedAsSuch) {
  std::string other_format = fragment_bytes();
  other_format[offsetof(format::FragmentHeader, format_version)] = 2;
  EXPECT_NE(refusal(other_format).find("fragment format version 2"), std::string::npos)
      << refusal(other_format);
  std::string other_tool = fragment_bytes();
  std::memcpy(other_tool.data() + offsetof(format::FragmentHeader, tool_version), "9.9.9", 5);
  EXPECT_NE(refusal(other_tool).find("cooked by hullcook 9.9.9"), std::string::npos)
      << refusal(other_tool);
}

TEST(Fragment, AHugeCountWithAGoodChecksumIsRefusedNotAllocated) {
  std::string bytes = fragment_bytes();
  const std::uint32_t huge = 0xFFFFFFF0u;
  std::memcpy(bytes.data() + sizeof(format::FragmentHeader), &huge, 4);  // the settings' length
  restamp_checksum(bytes);
  EXPECT_NE(refusal(bytes).find("too large"), std::string::npos) << refusal(bytes);
}

// Stop 58, a helper's hostile fragments: a hull's bytes changed and the checksum made to match
// (a clockwise hull, one with a repeated vertex) were linked into glTF and debug JSON as they
// were, with exit 0. Every hull read is checked as the contract checks the cook's own: refused,
// naming which.
TEST(Fragment, Stop59_AHullThatIsNotConvexAndCounterClockwiseIsRefused) {
  const Settings settings = rich_settings();
  const std::vector<CookedAsset> cooked =
      cook({kSprites / "frozen-bubble__balls__bubble-1-mini.png"}, settings).assets;
  ASSERT_EQ(cooked.size(), 1u);
  ASSERT_GE(cooked[0].levels.size(), 2u);
  ASSERT_GE(cooked[0].levels[1].hulls.at(0).size(), 3u);
  EXPECT_EQ(refusal(write_fragment(cooked, settings)), "");
  struct Forgery {
    std::string what, expected;
    std::function<void(CookedAsset&)> forge;
  };
  const std::vector<Forgery> forgeries{
      {"a clockwise hull of level 2", "level 2, hull 1: its hull is clockwise",
       [](CookedAsset& a) {
         std::reverse(a.levels[1].hulls[0].begin(), a.levels[1].hulls[0].end());
       }},
      {"a repeated vertex", "level 1, hull 1: its hull is not convex at its vertex",
       [](CookedAsset& a) {
         Ring& hull = a.levels[0].hulls[0];
         hull.insert(hull.begin() + 1, hull[1]);
       }},
      {"a folded hull", "level 1, hull 1: its hull is not convex at its vertex",
       [](CookedAsset& a) {
         Ring& hull = a.levels[0].hulls[0];
         std::swap(hull[0], hull[1]);
       }},
      {"a piece's clockwise hull", "piece 1: its hull is clockwise",
       [](CookedAsset& a) { std::reverse(a.pieces[0].hull.begin(), a.pieces[0].hull.end()); }}};
  for (const Forgery& forgery : forgeries) {
    SCOPED_TRACE(forgery.what);
    std::vector<CookedAsset> forged = cooked;
    forgery.forge(forged[0]);
    const std::string message = refusal(write_fragment(forged, settings));
    EXPECT_NE(message.find("sprites.hcf: malformed fragment: " + forgery.expected),
              std::string::npos)
        << message;
  }
}

// Stop 58, a helper's hostile fragments: one followed by a gigabyte of other bytes was read whole
// (20 s, a gigabyte of memory) before its size was found wrong. The header is read first: a
// sparse file of 64 GB is refused at once, not read.
TEST(Fragment, Stop59_AFragmentLongerThanItsHeaderSaysIsRefusedUnread) {
  const auto dir = std::filesystem::path(HULLCOOK_BINARY_DIR) / "test-scratch" /
                   "fragment_longer_than_its_header_says";
  std::filesystem::create_directories(dir);
  const auto path = dir / "long.hcf";
  const std::string bytes = fragment_bytes();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  EXPECT_EQ(read_fragment(path).assets.size(), 2u);
  std::error_code error;
  std::filesystem::resize_file(path, std::uintmax_t{64} << 30, error);
  if (error) GTEST_SKIP() << "no sparse file of 64 GB here: " << error.message();
  try {
    read_fragment(path);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("long.hcf: malformed fragment: 68719476736 bytes where "
                                         "its header says " +
                                         std::to_string(bytes.size())),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

TEST(Fragment, NotAFragment) {
  EXPECT_NE(refusal("\x89PNG\r\n\x1a\n").find("not a hullcook fragment"), std::string::npos);
}

}  // namespace
// Issue 19's fuzzing of link: a fragment whose pixels per unit (5.6e-309) is positive as a double
// but 0 as the bundle's f32 was linked into a bundle the runtime refuses, with exit 0. The reader
// refuses it, the bundle writer too, and so does `cook --ppu` (a usage error).
TEST(Issue19Fuzz, PixelsPerUnitBelowTheSmallestFloatIsRefused) {
  Settings settings;
  settings.threads = 1;
  std::vector<CookedAsset> assets =
      cook({kSprites / "frozen-bubble__balls__bubble-1-mini.png"}, settings).assets;
  ASSERT_EQ(assets.size(), 1u);
  assets[0].pixels_per_unit = 5.56268464651108e-309;
  EXPECT_THROW(write_bundle(assets), OutputError);
  const std::string message = refusal(write_fragment(assets, settings));
  EXPECT_NE(message.find("sprites.hcf"), std::string::npos) << message;
  EXPECT_NE(message.find("pixels per unit"), std::string::npos) << message;

  // A positive f32 still too small: its quantization step (from the 1/64 px floor) is beyond
  // what readers accept; the fuzzer's second finding, 2.9e-39.
  assets[0].pixels_per_unit = 2.938735877055719e-39;
  EXPECT_THROW(write_bundle(assets), OutputError);

  settings.pixels_per_unit = 1e-300;
  EXPECT_THROW(cook({kSprites / "frozen-bubble__balls__bubble-1-mini.png"}, settings), UsageError);
}

}  // namespace hullcook
