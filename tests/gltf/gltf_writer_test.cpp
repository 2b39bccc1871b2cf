// The glTF writer: round trips through an independent reader (tinygltf, nlohmann, the Draco
// decoder), determinism, the GLB container, and the physics extensions' references.
#include "gltf_test_support.h"
#include "sample_assets.h"

#include "hullcook/cook/gltf_writer.h"
#include "hullcook/core/error.h"

#include <draco/compression/decode.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

namespace hullcook {
namespace {

using json = nlohmann::json;
using test::all_sample_assets;

using Point3 = std::array<float, 3>;

// The JSON of a written file, and its buffer's bytes.
struct Parsed {
  json root;
  std::string buffer;
};

Parsed parse(const std::string& bytes, bool binary) {
  Parsed parsed;
  if (binary) {
    test::GlbChunks chunks = test::split_glb(bytes);
    parsed.root = json::parse(chunks.json);
    parsed.buffer = chunks.bin;
  } else {
    parsed.root = json::parse(bytes);
    if (parsed.root.contains("buffers")) {
      std::string uri = parsed.root["buffers"][0]["uri"];
      const std::string prefix = "data:application/octet-stream;base64,";
      EXPECT_EQ(uri.rfind(prefix, 0), 0u);
      parsed.buffer = test::decode_base64(uri.substr(prefix.size()));
    }
  }
  if (parsed.root.contains("buffers")) {
    std::size_t length = parsed.root["buffers"][0]["byteLength"];
    EXPECT_LE(length, parsed.buffer.size());
    EXPECT_LT(parsed.buffer.size() - length, 4u);  // at most the GLB chunk's padding
  }
  return parsed;
}

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

double ring_area(const Ring& ring) {
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

double size_of_finest_level(const CookedAsset& asset) {
  double min_x = 1e300, min_y = 1e300, max_x = -1e300, max_y = -1e300;
  for (const Ring& hull : asset.levels.front().hulls) {
    for (const Vec2& v : hull) {
      min_x = std::min(min_x, v.x), max_x = std::max(max_x, v.x);
      min_y = std::min(min_y, v.y), max_y = std::max(max_y, v.y);
    }
  }
  return std::max(max_x - min_x, max_y - min_y);
}

// The prism a hull should become: its vertices as floats at z = ±h.
std::vector<Point3> expected_prism(const Ring& hull, double half_thickness) {
  std::vector<Point3> points;
  for (double z : {half_thickness, -half_thickness}) {
    for (const Vec2& v : hull) {
      points.push_back({static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(z)});
    }
  }
  std::sort(points.begin(), points.end());
  return points;
}

// The signed volume enclosed by triangles (divergence theorem): positive when they face out.
double enclosed_volume(const std::vector<Point3>& points,
                       const std::vector<std::uint32_t>& indices) {
  double six_volume = 0.0;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const Point3& a = points[indices[t]];
    const Point3& b = points[indices[t + 1]];
    const Point3& c = points[indices[t + 2]];
    six_volume += double{a[0]} * (double{b[1]} * c[2] - double{b[2]} * c[1]) -
                  double{a[1]} * (double{b[0]} * c[2] - double{b[2]} * c[0]) +
                  double{a[2]} * (double{b[0]} * c[1] - double{b[1]} * c[0]);
  }
  return six_volume / 6.0;
}

std::vector<Point3> read_positions(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& accessor = model.accessors.at(accessor_index);
  EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(accessor.type, TINYGLTF_TYPE_VEC3);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  EXPECT_EQ(view.target, TINYGLTF_TARGET_ARRAY_BUFFER);
  EXPECT_EQ(view.byteOffset % 4, 0u);
  EXPECT_EQ(view.byteLength, accessor.count * 12);
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

class GltfFormats : public ::testing::TestWithParam<bool> {};

// The meshes of the uncompressed files reproduce the finest level's hulls: the same vertices as
// floats, closed outward-facing prisms of the documented thickness.
TEST_P(GltfFormats, MeshesReproduceTheFinestHulls) {
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
    EXPECT_EQ(node.mesh, -1);
    const std::vector<Ring>& hulls = asset.levels.front().hulls;
    ASSERT_EQ(node.children.size(), hulls.size()) << asset.name;
    if (hulls.empty()) continue;
    const double half = kGltfHalfThickness * size_of_finest_level(asset);
    EXPECT_DOUBLE_EQ(node.extras.Get("hullcook").Get("mesh_half_thickness").GetNumberAsDouble(),
                     half);
    for (std::size_t h = 0; h < hulls.size(); ++h) {
      const tinygltf::Node& child = model.nodes.at(node.children[h]);
      EXPECT_EQ(child.extras.Get("hullcook").Get("hull").GetNumberAsInt(), static_cast<int>(h));
      const tinygltf::Mesh& mesh = model.meshes.at(child.mesh);
      ASSERT_EQ(mesh.primitives.size(), 1u);
      const tinygltf::Primitive& primitive = mesh.primitives[0];
      EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
      std::vector<Point3> points = read_positions(model, primitive.attributes.at("POSITION"));
      std::vector<std::uint32_t> indices = read_indices(model, primitive.indices);

      std::vector<Point3> sorted = points;
      std::sort(sorted.begin(), sorted.end());
      EXPECT_EQ(sorted, expected_prism(hulls[h], half)) << asset.name << " hull " << h;
      ASSERT_EQ(indices.size(), 3 * (4 * hulls[h].size() - 4));
      for (std::uint32_t index : indices) ASSERT_LT(index, points.size());
      const double volume = ring_area(hulls[h]) * 2.0 * half;
      EXPECT_NEAR(enclosed_volume(points, indices), volume, 1e-5 * volume);
    }
  }
}

// The extras hold every level exactly: the doubles read back bit for bit.
TEST_P(GltfFormats, ExtrasReproduceEveryLevelExactly) {
  const bool binary = GetParam();
  const std::vector<CookedAsset> assets = all_sample_assets();
  for (bool draco : {false, true}) {
    Parsed parsed = parse(write_gltf(assets, {.binary = binary, .draco = draco}), binary);
    const json& root = parsed.root;
    for (std::size_t a = 0; a < assets.size(); ++a) {
      const CookedAsset& asset = assets[a];
      const json& node = root["nodes"][root["scenes"][0]["nodes"][a].get<int>()];
      ASSERT_EQ(node["name"], asset.name);
      const json& extras = node["extras"]["hullcook"];
      EXPECT_EQ(extras["version"], 1);
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
        const json& written = extras["levels"][l];
        EXPECT_EQ(written["tau"].get<double>(), level.tau);
        ASSERT_EQ(written["hulls"].size(), level.hulls.size());
        for (std::size_t h = 0; h < level.hulls.size(); ++h) {
          const json& flat = written["hulls"][h];
          ASSERT_EQ(flat.size(), 2 * level.hulls[h].size());
          for (std::size_t v = 0; v < level.hulls[h].size(); ++v) {
            EXPECT_EQ(flat[2 * v].get<double>(), level.hulls[h][v].x);
            EXPECT_EQ(flat[2 * v + 1].get<double>(), level.hulls[h][v].y);
          }
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

// Draco primitives decode to the prism's vertex set within the quantization bound, and their
// accessors describe the decoded data exactly.
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
    const CookedAsset& asset = assets[a];
    const json& node = root["nodes"][root["scenes"][0]["nodes"][a].get<int>()];
    const std::vector<Ring>& hulls = asset.levels.front().hulls;
    if (hulls.empty()) continue;
    const double half = kGltfHalfThickness * size_of_finest_level(asset);
    ASSERT_EQ(node["children"].size(), hulls.size());
    for (std::size_t h = 0; h < hulls.size(); ++h) {
      const json& child = root["nodes"][node["children"][h].get<int>()];
      const json& primitive = root["meshes"][child["mesh"].get<int>()]["primitives"][0];
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
      EXPECT_EQ(mesh.num_faces(), 4 * hulls[h].size() - 4);

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
      std::vector<Point3> expected = expected_prism(hulls[h], half);
      double extent = 0.0;
      for (int axis = 0; axis < 3; ++axis) {
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
      EXPECT_EQ(points.size(), expected.size());
      for (const Point3& e : expected) {
        EXPECT_TRUE(std::any_of(points.begin(), points.end(), [&](auto& p) { return near(p, e); }));
      }
      for (const Point3& p : points) {
        EXPECT_TRUE(
            std::any_of(expected.begin(), expected.end(), [&](auto& e) { return near(p, e); }));
      }
    }
  }
  EXPECT_GT(compressed, 0u);
}

INSTANTIATE_TEST_SUITE_P(TextAndBinary, GltfFormats, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "glb" : "gltf"; });

TEST(GltfWriter, SameBytesEveryRun) {
  for (bool binary : {false, true}) {
    for (bool draco : {false, true}) {
      std::string first = write_gltf(all_sample_assets(), {.binary = binary, .draco = draco});
      std::string second = write_gltf(all_sample_assets(), {.binary = binary, .draco = draco});
      EXPECT_EQ(first, second) << "binary " << binary << " draco " << draco;
    }
  }
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
      EXPECT_EQ(view["byteOffset"].get<std::size_t>() % 4, 0u);
      EXPECT_LE(view["byteOffset"].get<std::size_t>() + view["byteLength"].get<std::size_t>(),
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
    EXPECT_EQ(parsed.root["nodes"][0]["extras"]["hullcook"]["levels"][0]["hulls"], json::array());
  }
  // No asset at all is still a valid document with one empty scene.
  json root = json::parse(write_gltf({}, {}));
  EXPECT_EQ(root["asset"]["version"], "2.0");
  EXPECT_EQ(root["scenes"], json::array({json::object()}));
}

// Each hull node references its own mesh through both physics drafts; the physics properties
// become a KHR physics material and collision filter; a sensor's hulls become triggers.
TEST(GltfWriter, PhysicsExtensionsReferenceTheHullMeshes) {
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
    const json& node = root["nodes"][root["scenes"][0]["nodes"][a].get<int>()];
    const bool sensor = asset.physics && asset.physics->sensor;
    const char* role = sensor ? "trigger" : "collider";
    for (const json& child_index : node.value("children", json::array())) {
      const json& child = root["nodes"][child_index.get<int>()];
      const int mesh = child["mesh"];
      EXPECT_TRUE(meshes_seen.insert(mesh).second) << "a mesh shared by two hulls";
      const json& collider = child["extensions"]["KHR_physics_rigid_bodies"][role];
      EXPECT_EQ(collider["geometry"]["node"], child_index);
      EXPECT_EQ(collider["geometry"]["convexHull"], true);
      const json& shape = shapes[child["extensions"]["OMI_physics_body"][role]["shape"].get<int>()];
      EXPECT_EQ(shape["type"], "convex");
      EXPECT_EQ(shape["convex"]["mesh"], mesh);
      EXPECT_EQ(root["meshes"][mesh]["primitives"].size(), 1u);

      EXPECT_EQ(collider.contains("physicsMaterial"), asset.physics && !sensor);
      if (collider.contains("physicsMaterial")) {
        const json& material = khr["physicsMaterials"][collider["physicsMaterial"].get<int>()];
        EXPECT_EQ(material["staticFriction"].get<float>(), asset.physics->friction);
        EXPECT_EQ(material["dynamicFriction"].get<float>(), asset.physics->friction);
        EXPECT_EQ(material["restitution"].get<float>(), asset.physics->restitution);
      }
      const bool default_filter = !asset.physics || (asset.physics->category_bits == 1 &&
                                                     asset.physics->mask_bits == 0xFFFF);
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
  }
  EXPECT_EQ(meshes_seen.size(), root["meshes"].size());
}

// Hulls against the contract never crash the writer: one without area gets no mesh (the extras
// keep it), a clockwise one gets a prism that still faces out.
TEST(GltfWriter, DegenerateAndClockwiseHullsAreMirroredSafely) {
  CookedAsset asset = test::base_asset("odd");
  const Ring clockwise = {{0.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {1.0, 0.0}};
  asset.levels.push_back({0.0,
                          {{{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}},
                           {{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}},
                           {{0.0, 0.0}, {1.0, 0.0}},
                           clockwise}});
  for (bool draco : {false, true}) {
    json root = json::parse(write_gltf({asset}, {.draco = draco}));
    ASSERT_EQ(root["nodes"][0]["children"].size(), 1u);
    const json& child = root["nodes"][root["nodes"][0]["children"][0].get<int>()];
    EXPECT_EQ(child["extras"]["hullcook"]["hull"], 3);
    EXPECT_EQ(root["nodes"][0]["extras"]["hullcook"]["levels"][0]["hulls"].size(), 4u);
  }
  tinygltf::Model model = load_with_tinygltf(write_gltf({asset}, {}), false);
  const tinygltf::Primitive& primitive = model.meshes.at(0).primitives.at(0);
  std::vector<Point3> points = read_positions(model, primitive.attributes.at("POSITION"));
  const double half = kGltfHalfThickness * 2.0;
  EXPECT_NEAR(enclosed_volume(points, read_indices(model, primitive.indices)), 2.0 * half, 1e-6);
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

}  // namespace
}  // namespace hullcook
