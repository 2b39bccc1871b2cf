// The runtime's game-facing API on bundles written by write_bundle().
#include "synthetic_assets.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/format/bundle_layout.h"
#include "hullcook/format/crc32.h"
#include "hullcook/runtime.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hullcook {
namespace {

using runtime::Bundle;
using runtime::Status;

double cross(runtime::Vec2 o, runtime::Vec2 a, runtime::Vec2 b) {
  return (double{a.x} - o.x) * (double{b.y} - o.y) - (double{a.y} - o.y) * (double{b.x} - o.x);
}

TEST(Runtime, FindsEveryAssetOfALargeBundleAndNothingElse) {
  std::vector<CookedAsset> assets;
  for (int i = 0; i < 3000; ++i)
    assets.push_back(test::make_asset("sprites/enemy_" + std::to_string(i) + ".png",
                                      {{1.0, {test::rectangle(0, 0, 1 + i % 7, 2)}}}));
  const std::string bytes = write_bundle(assets);
  Bundle bundle;
  ASSERT_EQ(bundle.open(bytes.data(), bytes.size()), Status::ok);
  ASSERT_EQ(bundle.asset_count(), assets.size());
  for (std::size_t i = 0; i < assets.size(); ++i) {
    const runtime::Asset asset = bundle.find(assets[i].name);
    ASSERT_TRUE(asset) << assets[i].name;
    EXPECT_EQ(asset.index(), i);
    EXPECT_EQ(asset.name().data()[asset.name().size()], '\0');
    EXPECT_FALSE(bundle.find(assets[i].name + "x"));
  }
  EXPECT_FALSE(bundle.find("sprites/enemy_3000.png"));
}

TEST(Runtime, SelectsTheFinestLevelWhoseTauIsAtLeastTheRequestedOne) {
  const std::string bytes = write_bundle(test::synthetic_assets());
  Bundle bundle;
  ASSERT_EQ(bundle.open(bytes.data(), bytes.size()), Status::ok);
  const runtime::Asset hill = bundle.find("terrain/hill.png");  // τ = 2, 8, 24
  ASSERT_EQ(hill.level_count(), 3u);
  const struct {
    float requested, expected_tau;
  } cases[] = {{0.0f, 2.0f},  {2.0f, 2.0f},   {2.1f, 8.0f},     {8.0f, 8.0f},
               {9.0f, 24.0f}, {24.0f, 24.0f}, {1000.0f, 24.0f}, {-1.0f, 2.0f}};
  for (const auto& c : cases) EXPECT_EQ(hill.select_level(c.requested).tau(), c.expected_tau);
  EXPECT_EQ(hill.select_level(2.0f).hull_count(), 6u);
  EXPECT_EQ(hill.select_level(1000.0f).hull_count(), 1u);
  // Coarser levels hold fewer hulls and vertices.
  EXPECT_GT(hill.level(0).vertex_count(), hill.level(2).vertex_count());
  EXPECT_EQ(hill.level(3).hull_count(), 0u);
  EXPECT_EQ(hill.level(0).hull(99).vertex_count(), 0u);
}

TEST(Runtime, PlacementScalesAndMirrorsKeepingHullsCounterClockwise) {
  const std::string bytes = write_bundle(test::synthetic_assets());
  Bundle bundle;
  ASSERT_EQ(bundle.open(bytes.data(), bytes.size()), Status::ok);
  const runtime::Hull hull = bundle.find("terrain/hill.png").level(2).hull(0);
  ASSERT_EQ(hull.vertex_count(), 5u);
  runtime::Vec2 plain[8], mirrored[8];
  ASSERT_EQ(hull.copy_vertices(plain, 8), 5u);
  ASSERT_EQ(hull.copy_vertices(mirrored, 8, {0.5f, true}), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_FLOAT_EQ(mirrored[i].x, -0.5f * plain[4 - i].x);
    EXPECT_FLOAT_EQ(mirrored[i].y, 0.5f * plain[4 - i].y);
    EXPECT_GT(cross(mirrored[i], mirrored[(i + 1) % 5], mirrored[(i + 2) % 5]), 0.0);
  }
  // A short buffer gets what fits and learns the count.
  runtime::Vec2 two[2];
  EXPECT_EQ(hull.copy_vertices(two, 2), 5u);
  EXPECT_FLOAT_EQ(two[1].x, plain[1].x);
  EXPECT_EQ(hull.copy_vertices(nullptr, 0), 5u);
}

TEST(Runtime, AreaAndCentroidOfAHull) {
  const std::string bytes =
      write_bundle({test::make_asset("r", {{0.0, {test::rectangle(1, 2, 4, 10)}}})});
  Bundle bundle;
  ASSERT_EQ(bundle.open(bytes.data(), bytes.size()), Status::ok);
  const runtime::Hull hull = bundle.find("r").level(0).hull(0);
  const double error = bundle.find("r").quantization_error();
  EXPECT_NEAR(hull.area(), 24.0, 2 * 22 * error);
  EXPECT_NEAR(hull.centroid().x, 2.5, 2 * error);
  EXPECT_NEAR(hull.centroid().y, 6.0, 2 * error);
}

TEST(Runtime, EmptyViewsAreHarmless) {
  Bundle bundle;
  EXPECT_TRUE(bundle.empty());
  EXPECT_EQ(bundle.asset_count(), 0u);
  EXPECT_FALSE(bundle.find("x"));
  const runtime::Asset asset;
  EXPECT_EQ(asset.level_count(), 0u);
  EXPECT_TRUE(asset.name().empty());
  EXPECT_EQ(asset.select_level(1.0f).hull_count(), 0u);
  EXPECT_FALSE(asset.has_physics());
  EXPECT_EQ(asset.physics().density, runtime::Physics{}.density);
  EXPECT_STREQ(asset.measure(), "");
  EXPECT_EQ(runtime::Level{}.hull(0).vertex_count(), 0u);
  EXPECT_GT(std::string(hullcook::runtime_version()).size(), 0u);
}

// Distinct names whose FNV-1a hash is a multiple of modulus: they all start at slot 0 of a table
// of modulus slots (or of any divisor of it).
std::vector<std::string> names_hashing_to_slot_zero(std::size_t count, std::uint32_t modulus) {
  std::vector<std::string> names;
  for (int i = 0; names.size() < count; ++i) {
    std::string name = "clash_" + std::to_string(i);
    if (format::name_hash(name.data(), name.size()) % modulus == 0) names.push_back(name);
  }
  return names;
}

// A bundle of assets with one empty level each, laid out by hand because write_bundle chooses
// its own slot count; the slots are filled by linear probing in the names' order.
std::string bundle_with_slot_count(const std::vector<std::string>& names,
                                   std::uint32_t slot_count) {
  const auto count = static_cast<std::uint32_t>(names.size());
  format::BundleHeader header{};
  std::memcpy(header.magic, format::kMagic, sizeof(header.magic));
  header.version_major = format::kVersionMajor;
  header.version_minor = format::kVersionMinor;
  header.asset_count = count;
  header.slot_count = slot_count;
  header.level_count = count;
  header.assets_offset = sizeof(format::BundleHeader);
  header.slots_offset = header.assets_offset + count * sizeof(format::AssetRecord);
  header.levels_offset = header.slots_offset + slot_count * 4;
  header.hulls_offset = header.levels_offset + count * sizeof(format::LevelRecord);
  header.vertices_offset = header.hulls_offset;
  header.strings_offset = header.vertices_offset;

  std::string bytes(header.strings_offset, '\0');
  std::string strings;
  std::vector<std::uint32_t> slots(slot_count, format::kEmptySlot);
  for (std::uint32_t i = 0; i < count; ++i) {
    format::AssetRecord asset{};
    asset.name_offset = static_cast<std::uint32_t>(strings.size());
    asset.name_length = static_cast<std::uint16_t>(names[i].size());
    asset.first_level = i;
    asset.pixels_per_unit = 1.0f;
    asset.pivot_u = asset.pivot_v = 0.5f;
    asset.quant_step = 0.01f;
    std::memcpy(bytes.data() + header.assets_offset + i * sizeof(asset), &asset, sizeof(asset));
    const format::LevelRecord level{0.0f, 0};
    std::memcpy(bytes.data() + header.levels_offset + i * sizeof(level), &level, sizeof(level));
    strings += names[i] + '\0';
    std::uint32_t slot = format::name_hash(names[i].data(), names[i].size()) % slot_count;
    while (slots[slot] != format::kEmptySlot) slot = (slot + 1) % slot_count;
    slots[slot] = i;
  }
  std::memcpy(bytes.data() + header.slots_offset, slots.data(), slots.size() * 4);
  bytes += strings;
  header.total_size = static_cast<std::uint32_t>(bytes.size());
  header.checksum = format::crc32(0, bytes.data() + sizeof(header), bytes.size() - sizeof(header));
  std::memcpy(bytes.data(), &header, sizeof(header));
  return bytes;
}

void expect_finds_every_name(const std::string& bytes, const std::vector<std::string>& names) {
  Bundle bundle;
  ASSERT_EQ(bundle.open(bytes.data(), bytes.size()), Status::ok);
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(bundle.find(names[i]).index(), i);
  EXPECT_FALSE(bundle.find("absent"));
}

// The shape of a crafted bundle that took quadratic time to open: every name starts at slot 0,
// so the table is one run and finding the k-th asset probes k slots. Past the probe budget the
// reader checks only that every slot is reachable (SPEC §6): the table opens, every name is
// found, and a slot its name's lookup cannot reach is still refused.
TEST(Runtime, OpensAClusteredNameTable) {
  const std::vector<std::string> clashing = names_hashing_to_slot_zero(1023, 1024);
  expect_finds_every_name(bundle_with_slot_count(clashing, 1024), clashing);
  expect_finds_every_name(bundle_with_slot_count(clashing, 2048), clashing);
  // Sequential names cluster without any crafting (SPEC §6).
  std::vector<std::string> sequential;
  for (int i = 0; i < 1867; ++i) sequential.push_back("obj" + std::to_string(i));
  expect_finds_every_name(bundle_with_slot_count(sequential, format::writer_slot_count(1867)),
                          sequential);
}

TEST(Runtime, RefusesAnUnreachableSlotOfAClusteredNameTable) {
  // A one-run table with slot 1000 swapped for the empty slot after the run: the assets from 1000
  // on lie in a run that their start slot 0 is not in. They are looked up after the probe budget
  // runs out, so the one-pass check must find them.
  const std::vector<std::string> clashing = names_hashing_to_slot_zero(1023, 2048);
  std::string bytes = bundle_with_slot_count(clashing, 2048);
  format::BundleHeader header;
  std::memcpy(&header, bytes.data(), sizeof(header));
  char* slots = bytes.data() + header.slots_offset;
  std::uint32_t moved = 0, empty = 0;
  std::memcpy(&moved, slots + 4 * 1000, 4);
  std::memcpy(&empty, slots + 4 * 1023, 4);
  ASSERT_EQ(empty, format::kEmptySlot);
  std::memcpy(slots + 4 * 1000, &empty, 4);
  std::memcpy(slots + 4 * 1023, &moved, 4);
  header.checksum = format::crc32(0, bytes.data() + sizeof(header), bytes.size() - sizeof(header));
  std::memcpy(bytes.data(), &header, sizeof(header));
  Bundle bundle;
  EXPECT_EQ(bundle.open(bytes.data(), bytes.size()), Status::malformed);
}

TEST(Runtime, ChecksNamesFullyWithinTheProbeBudget) {
  // One run of `length` assets from slot 0 costs length (length + 1) / 2 probes to look up.
  constexpr std::uint32_t kSlots = 64;
  const std::uint64_t budget = format::name_table_probe_budget(kSlots);
  std::uint32_t length = 0;
  while (std::uint64_t{length + 1} * (length + 2) / 2 <= budget) ++length;
  ASSERT_LT(length + 2, kSlots);
  // The last name a duplicate. Within the budget, its lookup finds the first one: refused.
  std::vector<std::string> within = names_hashing_to_slot_zero(length, kSlots);
  within.back() = within.front();
  Bundle bundle;
  std::string bytes = bundle_with_slot_count(within, kSlots);
  EXPECT_EQ(bundle.open(bytes.data(), bytes.size()), Status::malformed);
  // Two assets more: the budget runs out before the duplicate's lookup, and the one-pass check
  // lets it through (lookups find the first; SPEC §6).
  std::vector<std::string> past = names_hashing_to_slot_zero(length + 2, kSlots);
  past.back() = past.front();
  bytes = bundle_with_slot_count(past, kSlots);
  EXPECT_EQ(bundle.open(bytes.data(), bytes.size()), Status::ok);
}

TEST(MappedFile, MapsAFileForBundleOpen) {
  const std::filesystem::path dir =
      std::filesystem::path(HULLCOOK_BINARY_DIR) / "tests/runtime/mapped_file_test";
  std::filesystem::create_directories(dir);
  const std::string bytes = write_bundle(test::synthetic_assets());
  std::ofstream(dir / "a.hcb", std::ios::binary) << bytes;
  std::ofstream(dir / "empty.hcb", std::ios::binary).flush();

  runtime::MappedFile file;
  ASSERT_EQ(file.open((dir / "a.hcb").c_str()), Status::ok);
  EXPECT_EQ(file.size(), bytes.size());
  runtime::MappedFile moved = std::move(file);
  EXPECT_EQ(file.data(), nullptr);
  Bundle bundle;
  ASSERT_EQ(bundle.open(moved.data(), moved.size()), Status::ok);
  EXPECT_TRUE(bundle.find("box"));

  runtime::MappedFile other;
  EXPECT_EQ(other.open((dir / "missing.hcb").c_str()), Status::io_error);
  EXPECT_EQ(other.open(dir.c_str()), Status::io_error);
  EXPECT_EQ(other.open(nullptr), Status::invalid_argument);
  ASSERT_EQ(other.open((dir / "empty.hcb").c_str()), Status::ok);
  EXPECT_EQ(other.size(), 0u);
  EXPECT_EQ(bundle.open(other.data(), other.size()), Status::truncated);
}

}  // namespace
}  // namespace hullcook
