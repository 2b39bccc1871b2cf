// The glTF 2.0 writer. The schema is documented in docs/gltf-extras.md.
//
// Why nlohmann::json and a hand-made GLB container rather than tinygltf's writer: the file must be
// byte-for-byte deterministic, the hulls in the extras must print as round-tripping doubles, and
// the Draco primitives need accessors without bufferViews plus the KHR_draco_mesh_compression
// object built by hand anyway. With nlohmann we control every key (sorted, so deterministic), every
// number and the container (a GLB is a 12-byte header and two padded chunks). tinygltf stays the
// independent reader in the tests (tests/gltf), so a writer bug cannot hide behind a reader that
// shares the writer's code.
#include "hullcook/cook/gltf_writer.h"

#include "hullcook/core/error.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>

namespace hullcook {
namespace {

using json = nlohmann::json;

// glTF enumerations (glTF 2.0 specification, §5).
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kComponentFloat = 5126;
constexpr int kComponentUnsignedShort = 5123;
constexpr int kComponentUnsignedInt = 5125;
constexpr int kModeTriangles = 4;

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kGlbVersion = 2;
constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbChunkBin = 0x004E4942;   // "BIN\0"

constexpr const char* kKhrPhysics = "KHR_physics_rigid_bodies";
constexpr const char* kOmiBody = "OMI_physics_body";
constexpr const char* kOmiShape = "OMI_physics_shape";
constexpr const char* kKhrDraco = "KHR_draco_mesh_compression";

// A convex ring extruded along z: the vertices of the ring at z = +h (0..n-1), then at z = -h
// (n..2n-1); outward-facing counter-clockwise triangles.
struct Prism {
  std::vector<float> positions;  // [output units] x, y, z per vertex
  std::vector<std::uint32_t> indices;
};

Prism extrude(const Ring& hull, double half_thickness, const std::string& asset_name) {
  const std::uint32_t n = static_cast<std::uint32_t>(hull.size());
  Prism prism;
  prism.positions.reserve(6 * n);
  for (double z : {half_thickness, -half_thickness}) {
    for (const Vec2& vertex : hull) {
      for (double coordinate : {vertex.x, vertex.y, z}) {
        float value = static_cast<float>(coordinate);
        if (!std::isfinite(value)) {
          throw OutputError("asset " + asset_name + ": hull coordinate " +
                            std::to_string(coordinate) + " does not fit a 32-bit float");
        }
        prism.positions.push_back(value);
      }
    }
  }
  prism.indices.reserve(3 * (4 * n - 4));
  for (std::uint32_t i = 1; i + 1 < n; ++i) {
    prism.indices.insert(prism.indices.end(), {0, i, i + 1});          // top, facing +z
    prism.indices.insert(prism.indices.end(), {n, n + i + 1, n + i});  // bottom, facing -z
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    // The ring is counter-clockwise, so the outside of edge i -> j is on its right.
    std::uint32_t j = (i + 1) % n;
    prism.indices.insert(prism.indices.end(), {n + i, n + j, j});
    prism.indices.insert(prism.indices.end(), {n + i, j, i});
  }
  return prism;
}

// Twice the signed area of the ring once its vertices are rounded to floats, as in the mesh.
double float_area(const Ring& ring) {
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % ring.size()];
    twice += double{static_cast<float>(a.x)} * double{static_cast<float>(b.y)} -
             double{static_cast<float>(a.y)} * double{static_cast<float>(b.x)};
  }
  return twice;
}

// A float as JSON through its shortest decimal form, so that 0.2f prints as 0.2 and reads back as
// the same float. Not for accessor min/max, which must equal the stored floats exactly as doubles.
json float_json(float value) {
  std::array<char, 32> text{};
  auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::strtod(std::string(text.data(), result.ptr).c_str(), nullptr);
}

json vec2_json(Vec2 v) { return json::array({v.x, v.y}); }

void require_finite(double value, const std::string& asset_name, const char* what) {
  if (!std::isfinite(value)) {
    throw OutputError("asset " + asset_name + ": " + what + " is not a finite number");
  }
}

void check_finite(const CookedAsset& asset) {
  require_finite(asset.pixels_per_unit, asset.name, "pixels_per_unit");
  require_finite(asset.pivot.x, asset.name, "pivot");
  require_finite(asset.pivot.y, asset.name, "pivot");
  require_finite(asset.transform.scale, asset.name, "transform scale");
  require_finite(asset.transform.origin.x, asset.name, "transform origin");
  require_finite(asset.transform.origin.y, asset.name, "transform origin");
  require_finite(asset.tau, asset.name, "tau");
  for (const CookedLevel& level : asset.levels) {
    require_finite(level.tau, asset.name, "a level's tau");
    for (const Ring& hull : level.hulls) {
      for (const Vec2& vertex : hull) {
        require_finite(vertex.x, asset.name, "a hull vertex");
        require_finite(vertex.y, asset.name, "a hull vertex");
        // Converting a double beyond the float range is undefined behaviour: refuse it first.
        constexpr double kFloatMax = std::numeric_limits<float>::max();
        if (std::abs(vertex.x) > kFloatMax || std::abs(vertex.y) > kFloatMax) {
          throw OutputError("asset " + asset.name + ": hull coordinate " +
                            std::to_string(std::max(std::abs(vertex.x), std::abs(vertex.y))) +
                            " does not fit a 32-bit float");
        }
      }
    }
  }
  if (asset.physics) {
    require_finite(asset.physics->density, asset.name, "density");
    require_finite(asset.physics->friction, asset.name, "friction");
    require_finite(asset.physics->restitution, asset.name, "restitution");
  }
}

json physics_json(const PhysicsProperties& physics) {
  return {
      {"density", float_json(physics.density)},         {"friction", float_json(physics.friction)},
      {"restitution", float_json(physics.restitution)}, {"sensor", physics.sensor},
      {"category_bits", physics.category_bits},         {"mask_bits", physics.mask_bits}};
}

// The canonical 2D data, the node's extras (docs/gltf-extras.md, version 1).
json asset_extras(const CookedAsset& asset, double half_thickness) {
  json levels = json::array();
  for (const CookedLevel& level : asset.levels) {
    json hulls = json::array();
    for (const Ring& hull : level.hulls) {
      json flat = json::array();
      for (const Vec2& vertex : hull) {
        flat.push_back(vertex.x);
        flat.push_back(vertex.y);
      }
      hulls.push_back(std::move(flat));
    }
    levels.push_back({{"tau", level.tau}, {"hulls", std::move(hulls)}});
  }
  json extras = {
      {"version", 1},
      {"units", "output units (1 unit = 1 m in glTF)"},
      // The name, not the path given: the bytes must not depend on where the cook ran (issue 19).
      {"source", asset.name},
      {"image_size", json::array({asset.image_width, asset.image_height})},
      {"pixels_per_unit", asset.pixels_per_unit},
      {"pivot", vec2_json(asset.pivot)},
      {"transform",
       {{"scale", asset.transform.scale},
        {"origin", vec2_json(asset.transform.origin)},
        {"flip_y", asset.transform.flip_y}}},
      {"tau", asset.tau},
      {"measure", asset.measure},
      {"levels", std::move(levels)},
      {"mesh_half_thickness", half_thickness},
  };
  if (asset.physics) extras["physics"] = physics_json(*asset.physics);
  return {{"hullcook", std::move(extras)}};
}

// The collision systems of the KHR collision filter: one name per bit of Box2D's 16-bit filter.
json bit_names(std::uint16_t bits) {
  json names = json::array();
  for (int bit = 0; bit < 16; ++bit) {
    if (bits & (1u << bit)) names.push_back("bit" + std::to_string(bit));
  }
  return names;
}

// Box2D's category/mask bits as a KHR_physics_rigid_bodies collision filter, or nothing when
// they are Box2D's defaults (collide with everything).
std::optional<json> collision_filter(const PhysicsProperties& physics) {
  if (physics.category_bits == 0x0001 && physics.mask_bits == 0xFFFF) return std::nullopt;
  json filter = json::object();
  if (physics.category_bits != 0) filter["collisionSystems"] = bit_names(physics.category_bits);
  if (physics.mask_bits == 0) {
    filter["notCollideWithSystems"] = bit_names(0xFFFF);
  } else if (physics.mask_bits != 0xFFFF) {
    filter["collideWithSystems"] = bit_names(physics.mask_bits);
  }
  return filter;
}

// The asset's size, for the thickness of its prisms: the larger side of the bounding box of the
// finest level's hulls; 1 when that box is empty or a point.
double asset_size(const CookedAsset& asset) {
  if (asset.levels.empty()) return 1.0;
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (const Ring& hull : asset.levels.front().hulls) {
    for (const Vec2& v : hull) {
      min_x = std::min(min_x, v.x), max_x = std::max(max_x, v.x);
      min_y = std::min(min_y, v.y), max_y = std::max(max_y, v.y);
    }
  }
  double size = std::max(max_x - min_x, max_y - min_y);
  return std::isfinite(size) && size > 0.0 ? size : 1.0;
}

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t group = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) group |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) group |= static_cast<std::uint8_t>(bytes[i + 2]);
    text += kAlphabet[(group >> 18) & 63];
    text += kAlphabet[(group >> 12) & 63];
    text += i + 1 < bytes.size() ? kAlphabet[(group >> 6) & 63] : '=';
    text += i + 2 < bytes.size() ? kAlphabet[group & 63] : '=';
  }
  return text;
}

void append_u32(std::string& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) out += static_cast<char>((value >> shift) & 0xFF);
}

// Builds the document's arrays and its single buffer.
class Document {
 public:
  explicit Document(bool draco) : draco_(draco) {}

  // Appends bytes to the buffer at a 4-byte aligned offset; returns the bufferView's index.
  int add_buffer_view(const void* data, std::size_t size, std::optional<int> target) {
    buffer_.resize((buffer_.size() + 3) & ~std::size_t{3}, '\0');
    json view = {{"buffer", 0}, {"byteOffset", buffer_.size()}, {"byteLength", size}};
    if (target) view["target"] = *target;
    buffer_.append(static_cast<const char*>(data), size);
    buffer_views_.push_back(std::move(view));
    return static_cast<int>(buffer_views_.size() - 1);
  }

  int add_accessor(json accessor) {
    accessors_.push_back(std::move(accessor));
    return static_cast<int>(accessors_.size() - 1);
  }

  // Adds a mesh with one triangle primitive; returns its index.
  int add_mesh(const Prism& prism, const std::string& name) {
    json primitive = draco_ ? draco_primitive(prism, name) : plain_primitive(prism);
    primitive["mode"] = kModeTriangles;
    meshes_.push_back({{"name", name}, {"primitives", json::array({std::move(primitive)})}});
    return static_cast<int>(meshes_.size() - 1);
  }

  int add_node(json node) {
    nodes_.push_back(std::move(node));
    return static_cast<int>(nodes_.size() - 1);
  }
  json& node(int index) { return nodes_[static_cast<std::size_t>(index)]; }

  int add_shape(json shape) {
    omi_shapes_.push_back(std::move(shape));
    return static_cast<int>(omi_shapes_.size() - 1);
  }
  int add_physics_material(json material) {
    physics_materials_.push_back(std::move(material));
    return static_cast<int>(physics_materials_.size() - 1);
  }
  int add_collision_filter(json filter) {
    collision_filters_.push_back(std::move(filter));
    return static_cast<int>(collision_filters_.size() - 1);
  }

  // The glTF JSON; the buffer as a data: URI unless it goes into a GLB's BIN chunk.
  json to_json(const std::vector<int>& scene_nodes, bool embed_buffer) const {
    json root = {{"asset", {{"version", "2.0"}, {"generator", "hullcook"}}}, {"scene", 0}};
    json scene = json::object();
    if (!scene_nodes.empty()) scene["nodes"] = scene_nodes;
    root["scenes"] = json::array({std::move(scene)});
    if (!nodes_.empty()) root["nodes"] = nodes_;
    if (!meshes_.empty()) root["meshes"] = meshes_;
    if (!accessors_.empty()) root["accessors"] = accessors_;
    if (!buffer_views_.empty()) root["bufferViews"] = buffer_views_;
    if (!buffer_.empty()) {
      json buffer = {{"byteLength", buffer_.size()}};
      if (embed_buffer) buffer["uri"] = "data:application/octet-stream;base64," + base64(buffer_);
      root["buffers"] = json::array({std::move(buffer)});
    }
    json used = json::array();
    json required = json::array();
    json extensions = json::object();
    if (draco_ && !meshes_.empty()) {
      // No uncompressed fallback (it would more than undo the compression), so by the
      // extension's specification it is required.
      used.push_back(kKhrDraco);
      required.push_back(kKhrDraco);
    }
    if (!omi_shapes_.empty()) {
      used.push_back(kKhrPhysics);
      used.push_back(kOmiBody);
      used.push_back(kOmiShape);
      extensions[kOmiShape] = {{"shapes", omi_shapes_}};
    }
    json khr = json::object();
    if (!physics_materials_.empty()) khr["physicsMaterials"] = physics_materials_;
    if (!collision_filters_.empty()) khr["collisionFilters"] = collision_filters_;
    if (!khr.empty()) extensions[kKhrPhysics] = std::move(khr);
    if (!used.empty()) root["extensionsUsed"] = std::move(used);
    if (!required.empty()) root["extensionsRequired"] = std::move(required);
    if (!extensions.empty()) root["extensions"] = std::move(extensions);
    return root;
  }

  const std::string& buffer() const { return buffer_; }

 private:
  static json position_accessor(std::size_t count, const std::array<float, 3>& min,
                                const std::array<float, 3>& max) {
    // min/max as the exact doubles of the stored floats: the validator compares them bit for bit.
    return {{"componentType", kComponentFloat},
            {"count", count},
            {"type", "VEC3"},
            {"min", {double{min[0]}, double{min[1]}, double{min[2]}}},
            {"max", {double{max[0]}, double{max[1]}, double{max[2]}}}};
  }

  static std::pair<std::array<float, 3>, std::array<float, 3>> bounds(
      const std::vector<float>& positions) {
    std::array<float, 3> min{}, max{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      min[axis] = max[axis] = positions[axis];
    }
    for (std::size_t i = 0; i < positions.size(); ++i) {
      min[i % 3] = std::min(min[i % 3], positions[i]);
      max[i % 3] = std::max(max[i % 3], positions[i]);
    }
    return {min, max};
  }

  json plain_primitive(const Prism& prism) {
    auto [min, max] = bounds(prism.positions);
    json positions = position_accessor(prism.positions.size() / 3, min, max);
    positions["bufferView"] = add_buffer_view(prism.positions.data(),
                                              prism.positions.size() * sizeof(float), kArrayBuffer);
    int position_accessor_index = add_accessor(std::move(positions));

    std::size_t vertex_count = prism.positions.size() / 3;
    json indices = {{"count", prism.indices.size()}, {"type", "SCALAR"}};
    if (vertex_count <= 0xFFFF) {
      std::vector<std::uint16_t> narrow(prism.indices.begin(), prism.indices.end());
      indices["componentType"] = kComponentUnsignedShort;
      indices["bufferView"] = add_buffer_view(narrow.data(), narrow.size() * sizeof(std::uint16_t),
                                              kElementArrayBuffer);
    } else {
      indices["componentType"] = kComponentUnsignedInt;
      indices["bufferView"] = add_buffer_view(
          prism.indices.data(), prism.indices.size() * sizeof(std::uint32_t), kElementArrayBuffer);
    }
    return {{"attributes", {{"POSITION", position_accessor_index}}},
            {"indices", add_accessor(std::move(indices))}};
  }

  // KHR_draco_mesh_compression without fallback: the accessors have no bufferView and describe
  // the decoded data. To get their count/min/max right whatever Draco does (it deduplicates and
  // reorders points, and quantizes), the encoded bytes are decoded here and measured.
  json draco_primitive(const Prism& prism, const std::string& name) {
    const int face_count = static_cast<int>(prism.indices.size() / 3);
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(face_count);
    const int position_attribute =
        builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    for (int face = 0; face < face_count; ++face) {
      const std::uint32_t* corner = &prism.indices[3 * static_cast<std::size_t>(face)];
      builder.SetAttributeValuesForFace(
          position_attribute, draco::FaceIndex(face), &prism.positions[3 * corner[0]],
          &prism.positions[3 * corner[1]], &prism.positions[3 * corner[2]]);
    }
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    if (!mesh) throw OutputError("mesh " + name + ": Draco could not build the mesh");

    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, kGltfDracoPositionBits);
    draco::EncoderBuffer encoded;
    draco::Status status = encoder.EncodeMeshToBuffer(*mesh, &encoded);
    if (!status.ok()) {
      throw OutputError("mesh " + name + ": Draco encoding failed: " + status.error_msg_string());
    }

    draco::DecoderBuffer input;
    input.Init(encoded.data(), encoded.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&input);
    if (!decoded.ok() || !decoded.value()) {
      throw OutputError("mesh " + name + ": the Draco encoding does not decode");
    }
    const draco::Mesh& result = *decoded.value();
    const draco::PointAttribute* decoded_positions =
        result.GetNamedAttribute(draco::GeometryAttribute::POSITION);
    if (!decoded_positions || result.num_points() == 0) {
      throw OutputError("mesh " + name + ": the Draco encoding lost its positions");
    }
    std::vector<float> points(3 * static_cast<std::size_t>(result.num_points()));
    for (draco::PointIndex point(0); point < result.num_points(); ++point) {
      decoded_positions->GetMappedValue(point, &points[3 * point.value()]);
    }
    auto [min, max] = bounds(points);
    int position_accessor_index = add_accessor(position_accessor(result.num_points(), min, max));
    int index_accessor =
        add_accessor({{"componentType", result.num_points() <= 0xFFFF ? kComponentUnsignedShort
                                                                      : kComponentUnsignedInt},
                      {"count", 3 * static_cast<std::size_t>(result.num_faces())},
                      {"type", "SCALAR"}});

    int view = add_buffer_view(encoded.data(), encoded.size(), std::nullopt);
    json extension = {{"bufferView", view},
                      {"attributes", {{"POSITION", decoded_positions->unique_id()}}}};
    return {{"attributes", {{"POSITION", position_accessor_index}}},
            {"indices", index_accessor},
            {"extensions", {{kKhrDraco, std::move(extension)}}}};
  }

  bool draco_;
  std::string buffer_;
  json buffer_views_ = json::array();
  json accessors_ = json::array();
  json meshes_ = json::array();
  json nodes_ = json::array();
  json omi_shapes_ = json::array();
  json physics_materials_ = json::array();
  json collision_filters_ = json::array();
};

// Adds the asset's root node and one child per hull of its finest level; returns the root's index.
int add_asset(Document& document, const CookedAsset& asset) {
  check_finite(asset);
  const double half_thickness = kGltfHalfThickness * asset_size(asset);
  const int asset_node =
      document.add_node({{"name", asset.name}, {"extras", asset_extras(asset, half_thickness)}});

  std::optional<int> material, filter;
  const bool sensor = asset.physics && asset.physics->sensor;
  if (asset.physics) {
    if (!sensor) {
      material =
          document.add_physics_material({{"staticFriction", float_json(asset.physics->friction)},
                                         {"dynamicFriction", float_json(asset.physics->friction)},
                                         {"restitution", float_json(asset.physics->restitution)}});
    }
    if (auto description = collision_filter(*asset.physics)) {
      filter = document.add_collision_filter(std::move(*description));
    }
  }

  json children = json::array();
  const std::vector<Ring> no_hulls;
  const std::vector<Ring>& hulls = asset.levels.empty() ? no_hulls : asset.levels.front().hulls;
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    // A hull without area as floats has no prism to mirror it with; the extras keep it. A
    // clockwise one (against the contract) is mirrored reversed, so its prism still faces out.
    const double area = float_area(hulls[i]);
    if (!std::isfinite(area)) {
      throw OutputError("asset " + asset.name + ": hull " + std::to_string(i) +
                        " has a coordinate that does not fit a 32-bit float");
    }
    if (hulls[i].size() < 3 || area == 0.0) continue;
    Ring ring = hulls[i];
    if (area < 0.0) std::reverse(ring.begin(), ring.end());
    const std::string name = asset.name + "/hull" + std::to_string(i);
    const int mesh = document.add_mesh(extrude(ring, half_thickness, asset.name), name);
    const int shape = document.add_shape({{"type", "convex"}, {"convex", {{"mesh", mesh}}}});
    const int node_index = static_cast<int>(asset_node + 1 + children.size());

    // The draft's collider geometry names a node whose mesh is the geometry: this very node.
    json khr_collider = {{"geometry", {{"node", node_index}, {"convexHull", true}}}};
    if (material) khr_collider["physicsMaterial"] = *material;
    if (filter) khr_collider["collisionFilter"] = *filter;
    const char* role = sensor ? "trigger" : "collider";
    json node = {{"name", name},
                 {"mesh", mesh},
                 {"extras", {{"hullcook", {{"hull", i}}}}},
                 {"extensions",
                  {{kKhrPhysics, {{role, std::move(khr_collider)}}},
                   {kOmiBody, {{role, {{"shape", shape}}}}}}}};
    if (document.add_node(std::move(node)) != node_index) {
      throw OutputError("asset " + asset.name + ": internal error: glTF node numbering");
    }
    children.push_back(node_index);
  }
  if (!children.empty()) document.node(asset_node)["children"] = std::move(children);
  return asset_node;
}

std::string glb_container(const std::string& json_text, const std::string& bin) {
  std::string json_chunk = json_text;
  json_chunk.resize((json_chunk.size() + 3) & ~std::size_t{3}, ' ');
  std::string bin_chunk = bin;
  bin_chunk.resize((bin_chunk.size() + 3) & ~std::size_t{3}, '\0');
  std::size_t total = 12 + 8 + json_chunk.size() + (bin.empty() ? 0 : 8 + bin_chunk.size());
  if (total > std::numeric_limits<std::uint32_t>::max()) {
    throw OutputError("the glTF binary would exceed 4 GiB");
  }
  std::string out;
  out.reserve(total);
  append_u32(out, kGlbMagic);
  append_u32(out, kGlbVersion);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_u32(out, static_cast<std::uint32_t>(json_chunk.size()));
  append_u32(out, kGlbChunkJson);
  out += json_chunk;
  if (!bin.empty()) {
    append_u32(out, static_cast<std::uint32_t>(bin_chunk.size()));
    append_u32(out, kGlbChunkBin);
    out += bin_chunk;
  }
  return out;
}

}  // namespace

std::string write_gltf(const std::vector<CookedAsset>& assets, const GltfOptions& options) {
  Document document(options.draco);
  std::vector<int> scene_nodes;
  scene_nodes.reserve(assets.size());
  for (const CookedAsset& asset : assets) scene_nodes.push_back(add_asset(document, asset));

  // Invalid UTF-8 in a name is replaced (U+FFFD) rather than refused: the name is a label.
  std::string text = document.to_json(scene_nodes, !options.binary)
                         .dump(-1, ' ', false, json::error_handler_t::replace);
  if (!options.binary) return text;
  return glb_container(text, document.buffer());
}

}  // namespace hullcook
