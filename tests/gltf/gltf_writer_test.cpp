// The glTF writer: round trips through an independent reader (tinygltf, nlohmann, the Draco
// decoder), determinism, the GLB container, the buffer's layout and size, and the physics
// extensions' references.
#include "gltf_test_support.h"
#include "sample_assets.h"

#include "hullcook/cook/cook.h"
#include "hullcook/cook/gltf_writer.h"
#include "hullcook/core/error.h"
#include "hullcook/core/predicates.h"
#include "hullcook/format/bundle_layout.h"

#include <draco/compression/decode.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>

namespace hullcook {
namespace {

using json = nlohmann::json;
using test::accessor_values;
using test::all_sample_assets;
using test::parse;
using test::Parsed;

using Point3 = std::array<float, 3>;

tinygltf::Model load_with_tinygltf(const std::string& bytes, bool binary) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  bool ok = binary
                ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned>(bytes.size()))
                : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                             static_cast<unsigned>(bytes.size()), "");
  EXPECT_TRUE(ok) << error;
  EXPECT_EQ(error, "");
  return model;
}

std::vector<Point3> read_positions(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& accessor = model.accessors.at(accessor_index);
  EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(accessor.type, TINYGLTF_TYPE_VEC3);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  EXPECT_EQ(view.target, TINYGLTF_TARGET_ARRAY_BUFFER);
  EXPECT_EQ((view.byteOffset + accessor.byteOffset) % 4, 0u);
  EXPECT_EQ(view.byteStride, 12u);
  EXPECT_LE(accessor.byteOffset + accessor.count * 12, view.byteLength);
  const auto& data = model.buffers.at(view.buffer).data;
  std::vector<Point3> points(accessor.count);
  std::memcpy(points.data(), data.data() + view.byteOffset + accessor.byteOffset,
              accessor.count * 12);
  for (int axis = 0; axis < 3; ++axis) {
    float min = std::numeric_limits<float>::infinity(), max = -min;
    for (const Point3& p : points) min = std::min(min, p[axis]), max = std::max(max, p[axis]);
    EXPECT_EQ(accessor.minValues.at(axis), double{min});
    EXPECT_EQ(accessor.maxValues.at(axis), double{max});
  }
  return points;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& accessor = model.accessors.at(accessor_index);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  EXPECT_EQ(view.target, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  const auto& data = model.buffers.at(view.buffer).data;
  const unsigned char* start = data.data() + view.byteOffset + accessor.byteOffset;
  std::vector<std::uint32_t> indices(accessor.count);
  for (std::size_t i = 0; i < accessor.count; ++i) {
    if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      std::uint16_t value;
      std::memcpy(&value, start + 2 * i, 2);
      indices[i] = value;
    } else {
      EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
      std::memcpy(&indices[i], start + 4 * i, 4);
    }
  }
  return indices;
}

// Twice the signed area of the ring with its vertices rounded to floats, as in the files.
double float_twice_area(const Ring& ring) {
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % ring.size()];
    twice += format::nearest_float(a.x) * format::nearest_float(b.y) -
             format::nearest_float(a.y) * format::nearest_float(b.x);
  }
  return twice;
}

// The asset's level as written: each hull's vertices as (x, y) floats.
std::vector<std::vector<Point3>> written_level(const Parsed& parsed, const json& level) {
  std::vector<std::vector<Point3>> hulls;
  if (!level.contains("counts")) return hulls;
  const std::vector<double> counts = accessor_values(parsed, level["counts"]);
  const json& accessor = parsed.root["accessors"][level["vertices"].get<std::size_t>()];
  EXPECT_EQ(accessor["componentType"], 5126);  // FLOAT without --meshopt
  const std::size_t components = accessor["type"] == "VEC2" ? 2 : 3;
  const std::vector<double> values = accessor_values(parsed, level["vertices"]);
  std::size_t next = 0;
  for (double count : counts) {
    std::vector<Point3>& hull = hulls.emplace_back();
    for (std::size_t i = 0; i < count; ++i, ++next) {
      hull.push_back(
          {static_cast<float>(values.at(next * components)),
           static_cast<float>(values.at(next * components + 1)),
           components == 3 ? static_cast<float>(values.at(next * components + 2)) : 0.0f});
    }
  }
  EXPECT_EQ(next * components, values.size());
  return hulls;
}

std::vector<Point3> as_floats(const Ring& hull) {
  std::vector<Point3> points;
  for (const Vec2& v : hull)
    points.push_back({static_cast<float>(v.x), static_cast<float>(v.y), 0.0f});
  return points;
}

const json& asset_node(const json& root, std::size_t a) {
  return root["nodes"][root["scenes"][0]["nodes"][a].get<std::size_t>()];
}

// Every combination of the writer's options.
std::vector<GltfOptions> all_options() {
  std::vector<GltfOptions> options;
  for (bool binary : {false, true}) {
    for (bool draco : {false, true}) options.push_back({.binary = binary, .draco = draco});
    options.push_back({.binary = binary, .meshopt = true});
  }
  return options;
}

class GltfFormats : public ::testing::TestWithParam<bool> {};

// The mesh of each asset (uncompressed, read by tinygltf) is its finest level: every hull's
// vertices as floats at z = 0, hull after hull, and triangle fans facing +z that cover each hull
// with an area exactly once.
TEST_P(GltfFormats, MeshIsTheFinestLevel) {
  const bool binary = GetParam();
  const std::vector<CookedAsset> assets = all_sample_assets();
  const std::string bytes = write_gltf(assets, {.binary = binary, .draco = false});
  tinygltf::Model model = load_with_tinygltf(bytes, binary);

  ASSERT_EQ(model.scenes.size(), 1u);
  ASSERT_EQ(model.scenes[0].nodes.size(), assets.size());
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const CookedAsset& asset = assets[a];
    const tinygltf::Node& node = model.nodes.at(model.scenes[0].nodes[a]);
    EXPECT_EQ(node.name, asset.name);
    EXPECT_TRUE(node.children.empty());
    const std::vector<Ring>& hulls = asset.levels.front().hulls;
    if (hulls.empty()) {
      EXPECT_EQ(node.mesh, -1);
      continue;
    }
    const tinygltf::Mesh& mesh = model.meshes.at(node.mesh);
    ASSERT_EQ(mesh.primitives.size(), 1u);
    const tinygltf::Primitive& primitive = mesh.primitives[0];
    EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
    const std::vector<Point3> points = read_positions(model, primitive.attributes.at("POSITION"));
    const std::vector<std::uint32_t> indices = read_indices(model, primitive.indices);

    std::vector<Point3> expected;
    std::vector<double> twice_areas(hulls.size(), 0.0);
    std::vector<std::size_t> first;
    for (const Ring& hull : hulls) {
      first.push_back(expected.size());
      for (const Point3& p : as_floats(hull)) expected.push_back(p);
    }
    first.push_back(expected.size());
    EXPECT_EQ(points, expected) << asset.name;
    ASSERT_EQ(indices.size() % 3, 0u);
    for (std::size_t t = 0; t < indices.size(); t += 3) {
      const std::size_t h =
          std::upper_bound(first.begin(), first.end(), indices[t]) - first.begin() - 1;
      for (int c = 0; c < 3; ++c) {
        ASSERT_GE(indices[t + c], first[h]) << "a triangle across two hulls";
        ASSERT_LT(indices[t + c], first[h + 1]) << "a triangle across two hulls";
      }
      const Point3& p = points[indices[t]];
      const Point3& q = points[indices[t + 1]];
      const Point3& r = points[indices[t + 2]];
      const double twice = (double{q[0]} - p[0]) * (double{r[1]} - p[1]) -
                           (double{q[1]} - p[1]) * (double{r[0]} - p[0]);
      EXPECT_GE(twice, 0.0) << "a triangle facing -z";
      twice_areas[h] += twice;
    }
    for (std::size_t h = 0; h < hulls.size(); ++h) {
      const double area = std::abs(float_twice_area(hulls[h]));
      EXPECT_NEAR(twice_areas[h], area, 1e-9 * std::max(1.0, area)) << asset.name << " hull " << h;
    }
  }
}

// The extras hold every level: metadata exactly, each vertex as the float of its double.
TEST_P(GltfFormats, ExtrasHoldEveryLevel) {
  const bool binary = GetParam();
  const std::vector<CookedAsset> assets = all_sample_assets();
  for (bool draco : {false, true}) {
    Parsed parsed = parse(write_gltf(assets, {.binary = binary, .draco = draco}), binary);
    for (std::size_t a = 0; a < assets.size(); ++a) {
      const CookedAsset& asset = assets[a];
      const json& node = asset_node(parsed.root, a);
      ASSERT_EQ(node["name"], asset.name);
      const json& extras = node["extras"]["hullcook"];
      EXPECT_EQ(extras["version"], 2);
      EXPECT_EQ(extras["version"], kGltfExtrasVersion);
      EXPECT_EQ(extras["source"], asset.name);  // never an absolute path (issue 19)
      EXPECT_EQ(extras["image_size"], json::array({asset.image_width, asset.image_height}));
      EXPECT_EQ(extras["pixels_per_unit"].get<double>(), asset.pixels_per_unit);
      EXPECT_EQ(extras["pivot"][0].get<double>(), asset.pivot.x);
      EXPECT_EQ(extras["pivot"][1].get<double>(), asset.pivot.y);
      EXPECT_EQ(extras["transform"]["scale"].get<double>(), asset.transform.scale);
      EXPECT_EQ(extras["transform"]["flip_y"].get<bool>(), asset.transform.flip_y);
      EXPECT_EQ(extras["tau"].get<double>(), asset.tau);
      EXPECT_EQ(extras["measure"], asset.measure);
      ASSERT_EQ(extras["levels"].size(), asset.levels.size());
      for (std::size_t l = 0; l < asset.levels.size(); ++l) {
        const CookedLevel& level = asset.levels[l];
        EXPECT_EQ(extras["levels"][l]["tau"].get<double>(), level.tau);
        const auto hulls = written_level(parsed, extras["levels"][l]);
        ASSERT_EQ(hulls.size(), level.hulls.size());
        for (std::size_t h = 0; h < level.hulls.size(); ++h) {
          EXPECT_EQ(hulls[h], as_floats(level.hulls[h])) << asset.name << " level " << l;
        }
      }
      EXPECT_EQ(extras.contains("physics"), asset.physics.has_value());
      if (asset.physics) {
        const json& physics = extras["physics"];
        EXPECT_EQ(physics["density"].get<float>(), asset.physics->density);
        EXPECT_EQ(physics["friction"].get<float>(), asset.physics->friction);
        EXPECT_EQ(physics["restitution"].get<float>(), asset.physics->restitution);
        EXPECT_EQ(physics["sensor"].get<bool>(), asset.physics->sensor);
        EXPECT_EQ(physics["category_bits"].get<int>(), asset.physics->category_bits);
        EXPECT_EQ(physics["mask_bits"].get<int>(), asset.physics->mask_bits);
      }
    }
  }
}

// Each asset's Draco primitive decodes to its finest level's vertices within the quantization
// bound, with one triangle per fan triangle, and its accessors describe the decoded data exactly.
TEST_P(GltfFormats, DracoMeshesDecodeToTheHulls) {
  const bool binary = GetParam();
  const std::vector<CookedAsset> assets = all_sample_assets();
  const std::string bytes = write_gltf(assets, {.binary = binary, .draco = true});
  Parsed parsed = parse(bytes, binary);
  const json& root = parsed.root;
  ASSERT_TRUE(root.contains("extensionsRequired"));
  EXPECT_EQ(root["extensionsRequired"], json::array({"KHR_draco_mesh_compression"}));

  std::size_t compressed = 0;
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const std::vector<Ring>& hulls = assets[a].levels.front().hulls;
    const json& node = asset_node(root, a);
    if (hulls.empty()) {
      EXPECT_FALSE(node.contains("mesh"));
      continue;
    }
    const json& primitive = root["meshes"][node["mesh"].get<int>()]["primitives"][0];
    const json& extension = primitive["extensions"]["KHR_draco_mesh_compression"];
    const json& view = root["bufferViews"][extension["bufferView"].get<int>()];
    EXPECT_FALSE(view.contains("target"));
    const std::size_t offset = view.value("byteOffset", 0), length = view["byteLength"];
    ASSERT_LE(offset + length, parsed.buffer.size());
    compressed += length;

    draco::DecoderBuffer input;
    input.Init(parsed.buffer.data() + offset, length);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&input);
    ASSERT_TRUE(decoded.ok()) << decoded.status().error_msg_string();
    const draco::Mesh& mesh = *decoded.value();
    const draco::PointAttribute* attribute =
        mesh.GetAttributeByUniqueId(extension["attributes"]["POSITION"].get<std::uint32_t>());
    ASSERT_NE(attribute, nullptr);

    const json& positions = root["accessors"][primitive["attributes"]["POSITION"].get<int>()];
    const json& indices = root["accessors"][primitive["indices"].get<int>()];
    EXPECT_FALSE(positions.contains("bufferView"));
    EXPECT_FALSE(indices.contains("bufferView"));
    EXPECT_EQ(positions["count"].get<std::size_t>(), mesh.num_points());
    EXPECT_EQ(indices["count"].get<std::size_t>(), 3 * mesh.num_faces());
    std::size_t fan_triangles = 0;
    for (const Ring& hull : hulls) fan_triangles += hull.size() - 2;
    EXPECT_EQ(mesh.num_faces(), fan_triangles);

    std::vector<Point3> points(mesh.num_points());
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
      attribute->GetMappedValue(p, points[p.value()].data());
    }
    for (int axis = 0; axis < 3; ++axis) {
      float min = std::numeric_limits<float>::infinity(), max = -min;
      for (const Point3& p : points) min = std::min(min, p[axis]), max = std::max(max, p[axis]);
      EXPECT_EQ(positions["min"][axis].get<double>(), double{min});
      EXPECT_EQ(positions["max"][axis].get<double>(), double{max});
    }
    // Each expected vertex has a decoded one within the quantization step, and vice versa.
    std::vector<Point3> expected;
    for (const Ring& hull : hulls) {
      for (const Point3& p : as_floats(hull)) expected.push_back(p);
    }
    double extent = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
      float min = 1e30f, max = -1e30f;
      for (const Point3& p : expected) min = std::min(min, p[axis]), max = std::max(max, p[axis]);
      extent = std::max(extent, double{max} - double{min});
    }
    const double bound = extent / ((1 << kGltfDracoPositionBits) - 1) + 1e-6 * extent;
    auto near = [&](const Point3& p, const Point3& q) {
      for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(double{p[axis]} - double{q[axis]}) > bound) return false;
      }
      return true;
    };
    for (const Point3& e : expected) {
      EXPECT_TRUE(std::any_of(points.begin(), points.end(), [&](auto& p) { return near(p, e); }));
    }
    for (const Point3& p : points) {
      EXPECT_TRUE(
          std::any_of(expected.begin(), expected.end(), [&](auto& e) { return near(p, e); }));
    }
  }
  EXPECT_GT(compressed, 0u);
}

INSTANTIATE_TEST_SUITE_P(TextAndBinary, GltfFormats, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "glb" : "gltf"; });

TEST(GltfWriter, SameBytesEveryRun) {
  for (const GltfOptions& options : all_options()) {
    EXPECT_EQ(write_gltf(all_sample_assets(), options), write_gltf(all_sample_assets(), options))
        << "binary " << options.binary << " draco " << options.draco;
  }
}

// However many hulls and assets, the uncompressed buffer has one bufferView per kind of data
// (positions, indices, 2D vertices, hull vertex counts), and no JSON object per hull.
TEST(GltfWriter, OneBufferViewPerKindOfData) {
  std::vector<CookedAsset> assets = all_sample_assets();
  assets.push_back(test::many_hulls_asset(400));
  assets.back().name = "more";
  Parsed parsed = parse(write_gltf(assets, {.binary = true}), true);
  EXPECT_EQ(parsed.root["bufferViews"].size(), 4u);
  std::set<std::size_t> views;
  for (const json& accessor : parsed.root["accessors"]) {
    views.insert(accessor["bufferView"].get<std::size_t>());
  }
  EXPECT_EQ(views.size(), 4u);
  EXPECT_EQ(parsed.root["nodes"].size(), assets.size());
  EXPECT_EQ(parsed.root["meshes"].size(), assets.size() - 1);  // the blank asset has none
  EXPECT_LE(parsed.root["accessors"].size(), 4 * assets.size());
}

// The sizes issue 20 asks for, on the sample sprites at --tau 2 --ppu 32, in bytes per hull
// vertex over all levels: a .glb of at most 24, a .gltf of at most 40, a --meshopt .glb of at
// most 8.
TEST(GltfWriter, SampleSpritesAreLean) {
  const std::vector<CookedAsset> assets = test::sample_sprites();
  const std::size_t vertices = test::vertex_count(assets);
  ASSERT_GT(vertices, 10000u);
  const std::size_t glb = write_gltf(assets, {.binary = true}).size();
  const std::size_t gltf = write_gltf(assets, {.binary = false}).size();
  const std::size_t meshopt = write_gltf(assets, {.binary = true, .meshopt = true}).size();
  EXPECT_LE(glb, 24 * vertices) << double(glb) / vertices << " bytes per vertex";
  EXPECT_LE(gltf, 40 * vertices) << double(gltf) / vertices << " bytes per vertex";
  EXPECT_LE(meshopt, 8 * vertices) << double(meshopt) / vertices << " bytes per vertex";
}

TEST(GltfWriter, GlbContainerIsWellFormed) {
  for (bool draco : {false, true}) {
    const std::string bytes = write_gltf(all_sample_assets(), {.binary = true, .draco = draco});
    ASSERT_EQ(bytes.size() % 4, 0u);
    test::GlbChunks chunks = test::split_glb(bytes);  // throws on a bad length or chunk
    ASSERT_FALSE(chunks.bin.empty());
    // JSON padded with spaces; the document itself ends with its closing brace.
    std::size_t end = chunks.json.find_last_not_of(' ');
    EXPECT_EQ(chunks.json[end], '}');
    EXPECT_LT(chunks.json.size() - end - 1, 4u);
    json root = json::parse(chunks.json);
    EXPECT_FALSE(root["buffers"][0].contains("uri"));
    const std::size_t length = root["buffers"][0]["byteLength"];
    EXPECT_LE(length, chunks.bin.size());
    EXPECT_LT(chunks.bin.size() - length, 4u);
    for (std::size_t i = length; i < chunks.bin.size(); ++i) EXPECT_EQ(chunks.bin[i], '\0');
    for (const json& view : root["bufferViews"]) {
      EXPECT_EQ(view.value("byteOffset", std::size_t{0}) % 4, 0u);
      EXPECT_LE(view.value("byteOffset", std::size_t{0}) + view["byteLength"].get<std::size_t>(),
                length);
    }
  }
}

TEST(GltfWriter, AssetsWithoutHullsNeedNoBuffer) {
  for (bool binary : {false, true}) {
    const std::string bytes = write_gltf({test::empty_asset()}, {.binary = binary, .draco = true});
    if (binary) {
      EXPECT_TRUE(test::split_glb(bytes).bin.empty());
    }
    Parsed parsed = parse(bytes, binary);
    EXPECT_FALSE(parsed.root.contains("buffers"));
    EXPECT_FALSE(parsed.root.contains("meshes"));
    EXPECT_FALSE(parsed.root.contains("extensionsUsed"));
    EXPECT_FALSE(parsed.root.contains("extensionsRequired"));
    EXPECT_EQ(parsed.root["nodes"][0]["extras"]["hullcook"]["levels"][0],
              json({{"tau", test::empty_asset().tau}}));
  }
  // No asset at all is still a valid document with one empty scene.
  json root = json::parse(write_gltf({}, {}));
  EXPECT_EQ(root["asset"]["version"], "2.0");
  EXPECT_EQ(root["scenes"], json::array({json::object()}));
}

// Each asset node's mesh is its collider in both physics drafts (a triangle mesh); the physics
// properties become a KHR physics material and collision filter; a sensor's becomes a trigger.
TEST(GltfWriter, PhysicsExtensionsReferenceTheAssetMeshes) {
  const std::vector<CookedAsset> assets = all_sample_assets();
  json root = json::parse(write_gltf(assets, {}));
  EXPECT_EQ(root["extensionsUsed"],
            json::array({"KHR_physics_rigid_bodies", "OMI_physics_body", "OMI_physics_shape"}));
  EXPECT_FALSE(root.contains("extensionsRequired"));
  const json& shapes = root["extensions"]["OMI_physics_shape"]["shapes"];
  const json& khr = root["extensions"]["KHR_physics_rigid_bodies"];
  std::set<int> meshes_seen;
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const CookedAsset& asset = assets[a];
    const json& node = asset_node(root, a);
    if (!node.contains("mesh")) {
      EXPECT_TRUE(asset.levels[0].hulls.empty());
      EXPECT_FALSE(node.contains("extensions"));
      continue;
    }
    const bool sensor = asset.physics && asset.physics->sensor;
    const char* role = sensor ? "trigger" : "collider";
    const int mesh = node["mesh"];
    EXPECT_TRUE(meshes_seen.insert(mesh).second) << "a mesh shared by two assets";
    const json& collider = node["extensions"]["KHR_physics_rigid_bodies"][role];
    EXPECT_EQ(collider["geometry"]["node"], root["scenes"][0]["nodes"][a]);
    EXPECT_EQ(collider["geometry"]["convexHull"], false);
    const json& shape = shapes[node["extensions"]["OMI_physics_body"][role]["shape"].get<int>()];
    EXPECT_EQ(shape["type"], "trimesh");
    EXPECT_EQ(shape["trimesh"]["mesh"], mesh);
    EXPECT_EQ(root["meshes"][mesh]["primitives"].size(), 1u);

    EXPECT_EQ(collider.contains("physicsMaterial"), asset.physics && !sensor);
    if (collider.contains("physicsMaterial")) {
      const json& material = khr["physicsMaterials"][collider["physicsMaterial"].get<int>()];
      EXPECT_EQ(material["staticFriction"].get<float>(), asset.physics->friction);
      EXPECT_EQ(material["dynamicFriction"].get<float>(), asset.physics->friction);
      EXPECT_EQ(material["restitution"].get<float>(), asset.physics->restitution);
    }
    const bool default_filter =
        !asset.physics || (asset.physics->category_bits == 1 && asset.physics->mask_bits == 0xFFFF);
    EXPECT_EQ(collider.contains("collisionFilter"), !default_filter);
    if (asset.name == "crate") {
      const json& filter = khr["collisionFilters"][collider["collisionFilter"].get<int>()];
      EXPECT_EQ(filter["collisionSystems"], json::array({"bit1", "bit2"}));
      EXPECT_EQ(filter["collideWithSystems"],
                json::array({"bit0", "bit4", "bit5", "bit6", "bit7"}));
    }
    if (asset.name == "zone") {
      const json& filter = khr["collisionFilters"][collider["collisionFilter"].get<int>()];
      EXPECT_EQ(filter["notCollideWithSystems"].size(), 16u);
    }
  }
  EXPECT_EQ(meshes_seen.size(), root["meshes"].size());
}

// Hulls against the contract never crash the writer: one without area gets no triangle (its
// vertices stay in the level's data), a clockwise one gets a fan that still faces +z.
TEST(GltfWriter, DegenerateAndClockwiseHullsAreMirroredSafely) {
  CookedAsset asset = test::base_asset("odd");
  const Ring clockwise = {{0.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {1.0, 0.0}};
  asset.levels.push_back({0.0,
                          {{{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}},
                           {{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}},
                           {{0.0, 0.0}, {1.0, 0.0}},
                           clockwise}});
  for (const GltfOptions& options : all_options()) {
    Parsed parsed = parse(write_gltf({asset}, options), options.binary);
    if (options.meshopt) continue;  // quantized: gltf_meshopt_test reads those
    const auto hulls =
        written_level(parsed, parsed.root["nodes"][0]["extras"]["hullcook"]["levels"][0]);
    ASSERT_EQ(hulls.size(), 4u);
    EXPECT_EQ(hulls[3], as_floats(clockwise));
  }
  tinygltf::Model model = load_with_tinygltf(write_gltf({asset}, {}), false);
  const tinygltf::Primitive& primitive = model.meshes.at(0).primitives.at(0);
  std::vector<Point3> points = read_positions(model, primitive.attributes.at("POSITION"));
  std::vector<std::uint32_t> indices = read_indices(model, primitive.indices);
  ASSERT_EQ(indices.size(), 6u);  // the square's two triangles, nothing for the others
  for (std::size_t t = 0; t < indices.size(); t += 3) {
    const Point3& p = points[indices[t]];
    const Point3& q = points[indices[t + 1]];
    const Point3& r = points[indices[t + 2]];
    EXPECT_GT((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]), 0.0f);
  }
}

// Stop 60, a helper's hunt: names are UTF-8 text in glTF and JSON, where a byte that is not
// becomes U+FFFD, so the fragments of x\xff and x\xfe linked into two assets both named x\uFFFD
// (exit 0), which a game cannot tell apart; a bundle keeps the bytes. Such outputs are refused,
// naming the file and both names; one name alone is written with its U+FFFD, as before.
TEST(GltfWriter, Stop60_NamesThatUtf8WouldMakeOneAreRefused) {
  CookedAsset first = test::box_asset(), second = test::box_asset();
  first.name = "x\xff", second.name = "x\xfe";
  CookResult result;
  result.assets = {second, first};
  for (const char* output : {"x.gltf", "x.glb", "x.json"}) {
    try {
      output_files(result, {output}, Settings{}, {});
      ADD_FAILURE() << output << ": two assets named x\\uFFFD were written";
    } catch (const OutputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(std::string(output) + ": cannot write: ", 0), 0u) << message;
      EXPECT_NE(message.find("'x\\xfe' and 'x\\xff' would both be named 'x\xEF\xBF\xBD'"),
                std::string::npos)
          << message;
    }
  }
  EXPECT_NO_THROW(output_files(result, {"x.hcb"}, Settings{}, {}));
  second.name = "x\xc3\xbe";  // x\u00FE: valid, kept
  result.assets = {first, second};
  EXPECT_NO_THROW(output_files(result, {"x.gltf"}, Settings{}, {}));
  const Parsed parsed = parse(write_gltf({first, second}, {}), false);
  std::set<std::string> names;
  for (const json& node : parsed.root["nodes"]) names.insert(node["name"].get<std::string>());
  EXPECT_EQ(names, (std::set<std::string>{"x\xEF\xBF\xBD", "x\xc3\xbe"}));
}

TEST(GltfWriter, NonFiniteCoordinatesAreRefusedNamingTheAsset) {
  CookedAsset asset = test::box_asset();
  asset.levels[1].hulls[0][2].y = std::numeric_limits<double>::quiet_NaN();
  try {
    write_gltf({asset}, {});
    FAIL() << "no error";
  } catch (const OutputError& error) {
    EXPECT_NE(std::string(error.what()).find("box"), std::string::npos) << error.what();
  }
  asset = test::box_asset();
  asset.levels[0].hulls[0][0].x = 1e300;  // finite as a double, not as a float
  EXPECT_THROW(write_gltf({asset}, {}), OutputError);
}

// Found by stop 46's adversarial polygons: a 4 x 3 hull at (1e9, 1e9) was written with exit 0
// as four copies of one float (floats are 64 apart there), and a triangle scaled by 1e-100 as
// zeros. The writer now refuses a hull that the nearest floats flatten to a line or a point,
// naming the asset, the hull and its level; what floats keep a polygon is written as before.
TEST(GltfWriter, AdversarialHullsThatFloatsFlattenAreRefusedNamingTheAsset) {
  auto write = [](std::vector<Ring> hulls) {
    CookedAsset asset = test::base_asset("far");
    asset.levels.push_back({asset.tau, std::move(hulls)});
    try {
      write_gltf({asset}, {.binary = true});
      return std::string("written");
    } catch (const OutputError& error) {
      return std::string(error.what());
    }
  };
  auto quad = [](double x, double y, double w, double h) {
    return Ring{{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
  };
  EXPECT_EQ(write({quad(1e6, -1e6, 4, 3)}), "written");
  EXPECT_EQ(write({quad(-1000.0, 0.0, 0.001, 0.001)}), "written");
  EXPECT_EQ(write({quad(3e7, 3e7, 4, 3)}), "written");  // floats 2 apart: a 4 x 2 rectangle
  const Ring tiny{{1e-100, 0.0}, {2e-100, 0.0}, {1.5e-100, 1e-100}};
  const Ring sliver{{1.0, 1.0}, {2.0, 1.0}, {1.5, 1.0 + 1e-12}};
  for (const Ring& flat : {quad(1e9, 1e9, 4, 3), quad(1e6, 1e6, 0.004, 0.003), tiny, sliver}) {
    const std::string message = write({quad(0, 0, 1, 1), flat});
    EXPECT_NE(message.find("asset far: hull 1 of level 0"), std::string::npos) << message;
    EXPECT_NE(message.find("would reach a reader as a line or a point"), std::string::npos)
        << message;
  }
  // The advice follows the figures (stop 53's sweep of real pixel art at --weld 0 met a triangle
  // 7.7e-6 px thick at x = -202, floats 1.5e-5 apart, and was told --pivot first, which cannot
  // help a sliver; review 53: a weld cannot help a hull that is only too far out). A sliver,
  // thinner than floats resolve even at its own size: a weld.
  for (const Ring& thin : {sliver, tiny}) {
    const std::string message = write({quad(0, 0, 1, 1), thin});
    EXPECT_NE(message.find("it is a sliver: cook it with a larger tau or a weld"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find("--pivot"), std::string::npos) << message;
  }
  EXPECT_NE(write({quad(0, 0, 1, 1), sliver})
                .find("1.00009e-12 output units thick where 32-bit floats are 2.38419e-07 apart"),
            std::string::npos);
  // An asset too far out, not thin: nearer the origin, where a pivot can bring it.
  for (const Ring& far : {quad(1e9, 1e9, 4, 3), quad(1e6, 1e6, 0.004, 0.003)}) {
    const std::string message = write({far});
    EXPECT_NE(message.find("move it nearer the origin (for an image, --pivot)"), std::string::npos)
        << message;
    EXPECT_EQ(message.find("--weld"), std::string::npos) << message;
  }
  EXPECT_NE(
      write({quad(1e9, 1e9, 4, 3)}).find("3 output units thick where 32-bit floats are 64 apart"),
      std::string::npos);
}

// From the review of that check: it refused only hulls that floats flatten wholly. A 4-gon at
// (1e9, 1e9) whose first two vertices, 1 apart, round to one float was written with a repeated
// vertex (and so a collinear triple), against the promise of docs/gltf-extras.md. Such vertices
// are now left out: the hull is written as the floats' strictly convex polygon.
TEST(GltfWriter, ReviewVerticesThatFloatsMakeRepeatedAreLeftOut) {
  CookedAsset asset = test::base_asset("far");
  const double o = 1e9;
  const Ring cooked{{o, o}, {o + 1, o}, {o + 300, o + 10}, {o + 150, o + 300}};
  const Ring square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  asset.levels.push_back({asset.tau, {square, cooked}});
  const Parsed parsed = parse(write_gltf({asset}, {.binary = true}), true);
  const auto hulls =
      written_level(parsed, parsed.root["nodes"][0]["extras"]["hullcook"]["levels"][0]);
  ASSERT_EQ(hulls.size(), 2u);
  EXPECT_EQ(hulls[0].size(), 4u);  // the unit square, as cooked
  ASSERT_EQ(hulls[1].size(), 3u);
  Ring written;
  for (const Point3& p : hulls[1]) written.push_back({p[0], p[1]});
  for (std::size_t i = 0; i < written.size(); ++i) {
    EXPECT_GT(orientation(written[i], written[(i + 1) % 3], written[(i + 2) % 3]), 0) << i;
    // Each is the float of a cooked vertex.
    EXPECT_TRUE(std::any_of(cooked.begin(), cooked.end(), [&](Vec2 v) {
      return format::nearest_float(v.x) == written[i].x &&
             format::nearest_float(v.y) == written[i].y;
    })) << i;
  }
}

}  // namespace
}  // namespace hullcook
