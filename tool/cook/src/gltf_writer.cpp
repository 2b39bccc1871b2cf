// The glTF 2.0 writer. The schema is documented in docs/gltf-extras.md.
//
// Why nlohmann::json and a hand-made GLB container rather than tinygltf's writer: the file must be
// byte-for-byte deterministic, the accessors must sit at offsets in one buffer view per kind of
// data, and the Draco primitives need accessors without bufferViews plus the
// KHR_draco_mesh_compression object built by hand anyway. With nlohmann we control every key
// (sorted, so deterministic), every number and the container (a GLB is a 12-byte header and two
// padded chunks). tinygltf stays the independent reader in the tests (tests/gltf), so a writer bug
// cannot hide behind a reader that shares the writer's code.
//
// Why one flat mesh per asset rather than a prism mesh per hull (as the version 1 layout had):
// the sample sprites' hulls have 5 vertices on average, and a hull of its own costs a node, a
// mesh, an accessor with min/max and two physics objects, about 400 bytes of JSON, or 80 bytes per
// vertex before any geometry; a prism doubles the vertices. The convex pieces stay in the extras,
// which are the canonical data; the mesh is a mirror for 3D-minded importers.
#include "hullcook/cook/gltf_writer.h"

#include "contract_text.h"
#include "gltf_draco.h"
#include "gltf_meshopt.h"
#include "hullcook/core/geometry.h"
#include "utf8_names.h"

#include "hullcook/core/error.h"
#include "hullcook/core/predicates.h"
#include "hullcook/format/bundle_layout.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
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
constexpr int kComponentShort = 5122;
constexpr int kComponentUnsignedByte = 5121;
constexpr int kComponentUnsignedShort = 5123;
constexpr int kComponentUnsignedInt = 5125;
constexpr int kComponentFloat = 5126;

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kGlbVersion = 2;
constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbChunkBin = 0x004E4942;   // "BIN\0"

constexpr const char* kKhrPhysics = "KHR_physics_rigid_bodies";
constexpr const char* kOmiBody = "OMI_physics_body";
constexpr const char* kOmiShape = "OMI_physics_shape";
constexpr const char* kKhrDraco = "KHR_draco_mesh_compression";
constexpr const char* kExtMeshopt = "EXT_meshopt_compression";
constexpr const char* kKhrQuantization = "KHR_mesh_quantization";

double float_area(const Ring& ring) {
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % ring.size()];
    twice += format::nearest_float(a.x) * format::nearest_float(b.y) -
             format::nearest_float(a.y) * format::nearest_float(b.x);
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

// hull as the nearest floats hold it, less the vertices they make repeated, collinear or reflex
// (each such float lies within about a float spacing of the hull without it): the promise of
// docs/gltf-extras.md, convex, counter-clockwise, without repeated or collinear vertex. nullopt
// when every float turns left, as nearly always (the hull is written as cooked); an empty ring
// when fewer than 3 are left, or when the cooked hull itself turns left nowhere.
std::optional<Ring> as_floats_hold_it(const Ring& hull) {
  // Scratch, reused: nearly every hull is written as cooked.
  thread_local Ring floats;
  floats.clear();
  for (const Vec2& v : hull)
    floats.push_back({format::nearest_float(v.x), format::nearest_float(v.y)});
  auto turns_left = [&](std::size_t i) {
    const std::size_t n = floats.size();
    return orientation(floats[(i + n - 1) % n], floats[i], floats[(i + 1) % n]) > 0;
  };
  bool every = floats.size() >= 3;
  for (std::size_t i = 0; every && i < floats.size(); ++i) every = turns_left(i);
  if (every) return std::nullopt;
  if (!turns_left_somewhere(hull)) return std::nullopt;  // against the contract: as it is
  // Dropping a vertex turns its neighbours: passes until one drops none.
  for (bool dropped = true; dropped && floats.size() >= 3;) {
    dropped = false;
    for (std::size_t i = 0; i < floats.size() && floats.size() >= 3;) {
      if (turns_left(i)) {
        ++i;
      } else {
        floats.erase(floats.begin() + static_cast<std::ptrdiff_t>(i));
        dropped = true;
      }
    }
  }
  if (floats.size() < 3) floats.clear();
  return floats;
}

// The asset with its hulls as_floats_hold_it, or nullopt when none changes. Throws OutputError
// for a hull that floats would flatten to a line or a point where it lies (far from the origin,
// or far below a float's precision).
std::optional<CookedAsset> held_by_floats(const CookedAsset& asset) {
  std::optional<CookedAsset> held;
  for (std::size_t l = 0; l < asset.levels.size(); ++l) {
    const std::vector<Ring>& hulls = asset.levels[l].hulls;
    for (std::size_t h = 0; h < hulls.size(); ++h) {
      std::optional<Ring> floats = as_floats_hold_it(hulls[h]);
      if (!floats) continue;
      if (floats->empty()) {
        const Ring& hull = hulls[h];
        // The asset's size: the nearest the origin a pivot can bring its farthest hull is about
        // half of it.
        Vec2 low = hull[0], high = hull[0];
        for (const CookedLevel& level : asset.levels) {
          for (const Ring& ring : level.hulls) {
            for (const Vec2& p : ring) low = glm::min(low, p), high = glm::max(high, p);
          }
        }
        double largest = 0.0;
        for (const Vec2& p : hull) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
        const double thick = convex_thickness(hull), spacing = format::float_spacing(largest);
        // A hull thinner than floats resolve wherever a pivot puts the asset is a sliver of the
        // outline, which a weld removes; a thicker one is too far out.
        const bool sliver = thick <= format::float_spacing(0.5 * glm::length(high - low));
        const std::string figures =
            ", " + detail::number(thick) + " output units thick where 32-bit floats are " +
            detail::number(spacing) + " apart, would reach a reader as a " + "line or a point; ";
        const std::string advice =
            sliver ? "it is a sliver: cook it with a larger tau or a weld (--weld, at least " +
                         detail::number(spacing) +
                         " units, with tau above 0: a piece thinner than the weld is merged into a "
                         "neighbour or given a hull that wide, within tau)"
                   : "move it nearer the origin (for an image, --pivot), where floats are finer";
        throw OutputError("asset " + asset.name + ": hull " + std::to_string(h) + " of level " +
                          std::to_string(l) + ", at " + detail::point(hull[0]) + figures + advice);
      }
      if (!held) held = asset;
      held->levels[l].hulls[h] = std::move(*floats);
    }
  }
  return held;
}

// The asset with each hull as the grid holds it (Quantization::held), or nullopt when rounding
// keeps every hull convex.
std::optional<CookedAsset> held_on_grid(const CookedAsset& asset, const Quantization& grid) {
  std::optional<CookedAsset> held;
  for (std::size_t l = 0; l < asset.levels.size(); ++l) {
    const std::vector<Ring>& hulls = asset.levels[l].hulls;
    for (std::size_t h = 0; h < hulls.size(); ++h) {
      Ring kept = grid.held(hulls[h]);
      if (kept.size() == hulls[h].size()) continue;
      if (!held) held = asset;
      held->levels[l].hulls[h] = std::move(kept);
    }
  }
  return held;
}

json physics_json(const PhysicsProperties& physics) {
  return {
      {"density", float_json(physics.density)},         {"friction", float_json(physics.friction)},
      {"restitution", float_json(physics.restitution)}, {"sensor", physics.sensor},
      {"category_bits", physics.category_bits},         {"mask_bits", physics.mask_bits}};
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

// The kinds of data in the buffer, each in one bufferView (in this order, when not empty).
enum ViewKind : std::size_t { kPositions, kIndices, kPlanar, kCounts, kViewKinds };

// A level's hulls in the buffer's form: vertices per hull, and x, y per vertex, hull after hull.
struct PlanarLevel {
  std::vector<std::uint32_t> counts;
  std::vector<float> xy;
};

PlanarLevel planar_level(const CookedLevel& level) {
  PlanarLevel planar;
  for (const Ring& hull : level.hulls) {
    planar.counts.push_back(static_cast<std::uint32_t>(hull.size()));
    for (const Vec2& v : hull) {
      planar.xy.push_back(static_cast<float>(v.x));
      planar.xy.push_back(static_cast<float>(v.y));
    }
  }
  return planar;
}

// The finest level as one flat mesh: every hull's vertices at z = 0, hull after hull (all of them,
// so that the level's 2D data can be the mesh's positions), and a counter-clockwise triangle fan
// per hull with an area as floats (a clockwise hull, against the contract, is fanned reversed so
// that it still faces +z).
TriangleMesh flat_mesh(const std::vector<Ring>& hulls, const std::string& asset_name) {
  TriangleMesh mesh;
  for (std::size_t h = 0; h < hulls.size(); ++h) {
    const Ring& hull = hulls[h];
    const auto base = static_cast<std::uint32_t>(mesh.positions.size() / 3);
    for (const Vec2& v : hull) {
      mesh.positions.insert(mesh.positions.end(),
                            {static_cast<float>(v.x), static_cast<float>(v.y), 0.0f});
    }
    const double area = float_area(hull);
    if (!std::isfinite(area)) {
      throw OutputError("asset " + asset_name + ": hull " + std::to_string(h) +
                        " has a coordinate that does not fit a 32-bit float");
    }
    if (hull.size() < 3 || area == 0.0) continue;
    const auto n = static_cast<std::uint32_t>(hull.size());
    for (std::uint32_t i = 1; i + 1 < n; ++i) {
      if (area > 0.0) {
        mesh.indices.insert(mesh.indices.end(), {base, base + i, base + i + 1});
      } else {
        mesh.indices.insert(mesh.indices.end(), {base, base + i + 1, base + i});
      }
    }
  }
  return mesh;
}

std::pair<std::array<float, 3>, std::array<float, 3>> bounds(const std::vector<float>& xyz) {
  std::array<float, 3> min{xyz[0], xyz[1], xyz[2]}, max = min;
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    min[i % 3] = std::min(min[i % 3], xyz[i]);
    max[i % 3] = std::max(max[i % 3], xyz[i]);
  }
  return {min, max};
}

// A POSITION accessor without its data; min/max as the exact doubles of the floats (the validator
// compares them bit for bit).
json position_accessor(std::size_t count, const std::array<float, 3>& min,
                       const std::array<float, 3>& max) {
  return {{"componentType", kComponentFloat},
          {"count", count},
          {"type", "VEC3"},
          {"min", {double{min[0]}, double{min[1]}, double{min[2]}}},
          {"max", {double{max[0]}, double{max[1]}, double{max[2]}}}};
}

// The narrowest unsigned component type holding every value up to `largest`.
int unsigned_component(std::uint32_t largest, bool allow_byte) {
  if (allow_byte && largest <= 0xFF) return kComponentUnsignedByte;
  // 65535 is the primitive restart value, never a valid index.
  return largest < 0xFFFF ? kComponentUnsignedShort : kComponentUnsignedInt;
}

// The values as `component`-sized little-endian integers.
std::string pack_unsigned(const std::vector<std::uint32_t>& values, int component) {
  const std::size_t size = component == kComponentUnsignedByte    ? 1
                           : component == kComponentUnsignedShort ? 2
                                                                  : 4;
  std::string bytes(values.size() * size, '\0');
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (std::size_t b = 0; b < size; ++b) {
      bytes[i * size + b] = static_cast<char>((values[i] >> (8 * b)) & 0xFF);
    }
  }
  return bytes;
}

// Builds the document's arrays and its single buffer.
class Document {
 public:
  explicit Document(const GltfOptions& options) : options_(options) {}

  const GltfOptions& options() const { return options_; }

  // The index component type of the whole document with --meshopt (the compressed index view
  // decodes to one width), set before any asset is added.
  void set_index_component(int component) { index_component_ = component; }
  std::optional<int> index_component() const { return index_component_; }

  // Appends the accessor's data to its kind's bufferView, at an offset aligned to its component
  // size (4 for vertex attributes); returns the accessor's index. The bufferView's index is set
  // when the buffer is laid out (finish()).
  int add_accessor(ViewKind kind, std::string_view data, json accessor) {
    std::string& view = views_[kind];
    const int component = accessor["componentType"];
    std::size_t align = component == kComponentUnsignedByte                                    ? 1
                        : component == kComponentShort || component == kComponentUnsignedShort ? 2
                                                                                               : 4;
    if (kind == kPositions) align = 4;
    view.resize((view.size() + align - 1) / align * align, '\0');
    if (!view.empty()) accessor["byteOffset"] = view.size();
    view.append(data);
    accessor_views_.push_back(kind);
    accessors_.push_back(std::move(accessor));
    return static_cast<int>(accessors_.size() - 1);
  }

  // An accessor whose data an extension provides (Draco): no bufferView.
  int add_accessor(json accessor) {
    accessor_views_.push_back(kViewKinds);
    accessors_.push_back(std::move(accessor));
    return static_cast<int>(accessors_.size() - 1);
  }

  // A bufferView of its own (a Draco primitive); they come first in the buffer.
  int add_blob_view(std::string bytes) {
    blobs_.push_back(std::move(bytes));
    return static_cast<int>(blobs_.size() - 1);
  }

  int add_mesh(json primitive) {
    primitive["material"] = 0;
    meshes_.push_back({{"primitives", json::array({std::move(primitive)})}});
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

  // Lays out the buffer (the blobs, then one bufferView per non-empty kind) and returns the glTF
  // JSON; the buffer goes into a data: URI unless it goes into a GLB's BIN chunk.
  json finish(const std::vector<int>& scene_nodes, bool embed_buffer) {
    json buffer_views = json::array();
    auto add_view = [&](std::string_view bytes) {
      buffer_.resize((buffer_.size() + 3) & ~std::size_t{3}, '\0');
      json view = {{"buffer", 0}, {"byteLength", bytes.size()}};
      if (!buffer_.empty()) view["byteOffset"] = buffer_.size();
      buffer_.append(bytes);
      buffer_views.push_back(std::move(view));
      return static_cast<int>(buffer_views.size() - 1);
    };
    for (const std::string& blob : blobs_) add_view(blob);
    std::array<int, kViewKinds> view_index{};
    std::size_t fallback_length = 0;  // the uncompressed size of the compressed views
    for (std::size_t kind = 0; kind < kViewKinds; ++kind) {
      if (views_[kind].empty()) continue;
      const std::size_t stride = kind == kPositions ? (options_.meshopt ? 8 : 12)
                                 : kind == kIndices
                                     ? (index_component_ == kComponentUnsignedInt ? 4 : 2)
                                 : kind == kPlanar ? 4
                                                   : 1;
      if (options_.meshopt && kind != kCounts) {
        // Compressed into buffer 0; the view itself lies in the fallback buffer 1, which has no
        // data: a reader must decode (the extension is required).
        const MeshoptMode mode =
            kind == kIndices ? MeshoptMode::triangles : MeshoptMode::attributes;
        const std::string compressed = meshopt_compress(views_[kind], stride, mode);
        view_index[kind] = add_view(compressed);
        json& view = buffer_views.back();
        json extension = {{"buffer", 0},
                          {"byteLength", compressed.size()},
                          {"byteStride", stride},
                          {"count", views_[kind].size() / stride},
                          {"mode", mode == MeshoptMode::triangles ? "TRIANGLES" : "ATTRIBUTES"}};
        if (view.contains("byteOffset")) extension["byteOffset"] = view["byteOffset"];
        fallback_length = (fallback_length + 3) & ~std::size_t{3};
        view = {{"buffer", 1},
                {"byteLength", views_[kind].size()},
                {"extensions", {{kExtMeshopt, std::move(extension)}}}};
        if (fallback_length > 0) view["byteOffset"] = fallback_length;
        fallback_length += views_[kind].size();
      } else {
        view_index[kind] = add_view(views_[kind]);
      }
      json& view = buffer_views.back();
      if (kind == kPositions) {
        view["target"] = kArrayBuffer;
        view["byteStride"] = stride;  // several POSITION accessors share the view
      }
      if (kind == kIndices) view["target"] = kElementArrayBuffer;
    }
    for (std::size_t a = 0; a < accessors_.size(); ++a) {
      if (accessor_views_[a] != kViewKinds)
        accessors_[a]["bufferView"] = view_index[accessor_views_[a]];
    }

    json root = {{"asset", {{"version", "2.0"}, {"generator", "hullcook"}}}, {"scene", 0}};
    json scene = json::object();
    if (!scene_nodes.empty()) scene["nodes"] = scene_nodes;
    root["scenes"] = json::array({std::move(scene)});
    if (!nodes_.empty()) root["nodes"] = nodes_;
    if (!meshes_.empty()) {
      root["meshes"] = meshes_;
      // Flat meshes: seen from either side.
      root["materials"] = json::array({{{"doubleSided", true}}});
    }
    if (!accessors_.empty()) root["accessors"] = accessors_;
    if (!buffer_views.empty()) root["bufferViews"] = std::move(buffer_views);
    if (!buffer_.empty()) {
      json buffer = {{"byteLength", buffer_.size()}};
      if (embed_buffer) buffer["uri"] = "data:application/octet-stream;base64," + base64(buffer_);
      root["buffers"] = json::array({std::move(buffer)});
      if (fallback_length > 0) {
        root["buffers"].push_back({{"byteLength", fallback_length},
                                   {"extensions", {{kExtMeshopt, {{"fallback", true}}}}}});
      }
    }
    json used = json::array();
    json required = json::array();
    json extensions = json::object();
    if (options_.draco && !meshes_.empty()) {
      // No uncompressed fallback (it would more than undo the compression), so by the
      // extension's specification it is required.
      used.push_back(kKhrDraco);
      required.push_back(kKhrDraco);
    }
    if (fallback_length > 0) {
      used.push_back(kExtMeshopt);
      required.push_back(kExtMeshopt);
    }
    if (options_.meshopt && !meshes_.empty()) {
      // SHORT positions: a reader without the extension would misread them.
      used.push_back(kKhrQuantization);
      required.push_back(kKhrQuantization);
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
  GltfOptions options_;
  std::optional<int> index_component_;
  std::array<std::string, kViewKinds> views_;
  std::vector<std::string> blobs_;
  std::string buffer_;
  std::vector<ViewKind> accessor_views_;  // kViewKinds: no bufferView
  json accessors_ = json::array();
  json meshes_ = json::array();
  json nodes_ = json::array();
  json omi_shapes_ = json::array();
  json physics_materials_ = json::array();
  json collision_filters_ = json::array();
};

// The mesh's primitive, uncompressed: a POSITION accessor (returned in `positions`) and indices.
// The hulls' vertices on the grid, x and y per vertex; as POSITION data (`as_positions`) also
// z = 0 and a pad, so that each vertex takes 8 bytes (vertex attributes are 4-byte aligned).
std::vector<std::int16_t> quantized_vertices(const std::vector<Ring>& hulls,
                                             const Quantization& grid, bool as_positions) {
  std::vector<std::int16_t> values;
  for (const Ring& hull : hulls) {
    for (const Vec2& v : hull) {
      values.push_back(grid.x(v.x));
      values.push_back(grid.y(v.y));
      if (as_positions) values.insert(values.end(), {0, 0});
    }
  }
  return values;
}

template <typename T>
std::string_view bytes_of(const std::vector<T>& values) {
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

// The mesh's primitive, uncompressed or (with a grid) quantized for EXT_meshopt_compression: a
// POSITION accessor (returned in `positions`) and indices.
json plain_primitive(Document& document, const TriangleMesh& mesh, const std::vector<Ring>& hulls,
                     const std::optional<Quantization>& grid, int& positions) {
  const std::size_t vertex_count = mesh.positions.size() / 3;
  if (grid) {
    const std::vector<std::int16_t> values = quantized_vertices(hulls, *grid, true);
    std::array<int, 3> min{}, max{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      min[axis] = max[axis] = values[axis];
      for (std::size_t i = axis; i < values.size(); i += 4) {
        min[axis] = std::min<int>(min[axis], values[i]);
        max[axis] = std::max<int>(max[axis], values[i]);
      }
    }
    positions = document.add_accessor(kPositions, bytes_of(values),
                                      {{"componentType", kComponentShort},
                                       {"count", vertex_count},
                                       {"type", "VEC3"},
                                       {"min", min},
                                       {"max", max}});
  } else {
    auto [min, max] = bounds(mesh.positions);
    positions = document.add_accessor(kPositions, bytes_of(mesh.positions),
                                      position_accessor(vertex_count, min, max));
  }
  const int component = document.index_component().value_or(
      unsigned_component(static_cast<std::uint32_t>(vertex_count - 1), false));
  const int indices = document.add_accessor(
      kIndices, pack_unsigned(mesh.indices, component),
      {{"componentType", component}, {"count", mesh.indices.size()}, {"type", "SCALAR"}});
  return {{"attributes", {{"POSITION", positions}}}, {"indices", indices}};
}

// KHR_draco_mesh_compression without fallback: the accessors have no bufferView and describe the
// decoded data, which draco_encode() measures.
json draco_primitive(Document& document, const TriangleMesh& mesh, const std::string& name) {
  DracoMesh encoded = draco_encode(mesh, kGltfDracoPositionBits, name);
  const int positions =
      document.add_accessor(position_accessor(encoded.decoded_points, encoded.min, encoded.max));
  const int component =
      unsigned_component(static_cast<std::uint32_t>(encoded.decoded_points - 1), false);
  const int indices = document.add_accessor(
      {{"componentType", component}, {"count", 3 * encoded.decoded_faces}, {"type", "SCALAR"}});
  json extension = {{"bufferView", document.add_blob_view(std::move(encoded.bytes))},
                    {"attributes", {{"POSITION", encoded.position_id}}}};
  return {{"attributes", {{"POSITION", positions}}},
          {"indices", indices},
          {"extensions", {{kKhrDraco, std::move(extension)}}}};
}

// A level's entry in the extras: its tau, and accessors for its hulls' vertex counts and their
// vertices (x, y: the first two components), or none for what it does not have.
json level_json(Document& document, const CookedLevel& level, std::optional<int> vertices,
                const std::optional<Quantization>& grid) {
  json entry = {{"tau", level.tau}};
  if (level.hulls.empty()) return entry;
  PlanarLevel planar = planar_level(level);
  const std::uint32_t largest = *std::max_element(planar.counts.begin(), planar.counts.end());
  const int component = unsigned_component(largest, true);
  entry["counts"] = document.add_accessor(
      kCounts, pack_unsigned(planar.counts, component),
      {{"componentType", component}, {"count", planar.counts.size()}, {"type", "SCALAR"}});
  if (vertices) {
    entry["vertices"] = *vertices;
  } else if (!planar.xy.empty() && grid) {
    entry["vertices"] = document.add_accessor(
        kPlanar, bytes_of(quantized_vertices(level.hulls, *grid, false)),
        {{"componentType", kComponentShort}, {"count", planar.xy.size() / 2}, {"type", "VEC2"}});
  } else if (!planar.xy.empty()) {
    entry["vertices"] = document.add_accessor(
        kPlanar,
        {reinterpret_cast<const char*>(planar.xy.data()), planar.xy.size() * sizeof(float)},
        {{"componentType", kComponentFloat}, {"count", planar.xy.size() / 2}, {"type", "VEC2"}});
  }
  return entry;
}

// The asset's metadata for its extras (docs/gltf-extras.md, version 2), levels excluded.
json asset_extras(const CookedAsset& asset) {
  json extras = {
      {"version", kGltfExtrasVersion},
      {"units", "output units (1 unit = 1 m in glTF)"},
      // The name, not the path given: the bytes must not depend on where the cook ran (issue 19).
      {"source", valid_utf8(asset.name)},
      {"image_size", json::array({asset.image_width, asset.image_height})},
      {"pixels_per_unit", asset.pixels_per_unit},
      {"pivot", vec2_json(asset.pivot)},
      {"transform",
       {{"scale", asset.transform.scale},
        {"origin", vec2_json(asset.transform.origin)},
        {"flip_y", asset.transform.flip_y}}},
      {"tau", asset.tau},
      {"measure", asset.measure},
  };
  if (asset.physics) extras["physics"] = physics_json(*asset.physics);
  return extras;
}

// The physics drafts on the asset node, whose mesh is the collider's geometry (a triangle mesh:
// the convex pieces themselves are in the extras).
void add_colliders(Document& document, const CookedAsset& asset, int node_index, int mesh) {
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
  const int shape = document.add_shape({{"type", "trimesh"}, {"trimesh", {{"mesh", mesh}}}});
  // The draft's collider geometry names a node whose mesh is the geometry: this very node.
  json khr_collider = {{"geometry", {{"node", node_index}, {"convexHull", false}}}};
  if (material) khr_collider["physicsMaterial"] = *material;
  if (filter) khr_collider["collisionFilter"] = *filter;
  const char* role = sensor ? "trigger" : "collider";
  document.node(node_index)["extensions"] = {{kKhrPhysics, {{role, std::move(khr_collider)}}},
                                             {kOmiBody, {{role, {{"shape", shape}}}}}};
}

// Adds the asset's node (its extras, and its finest level's mesh when it has triangles); returns
// the node's index.
int add_asset(Document& document, const CookedAsset& cooked) {
  check_finite(cooked);
  const std::optional<CookedAsset> held = held_by_floats(cooked);
  const CookedAsset& asset = held ? *held : cooked;
  const int node_index = document.add_node({{"name", valid_utf8(asset.name)}});
  json extras = asset_extras(asset);
  std::optional<Quantization> grid;
  std::optional<CookedAsset> on_grid;  // the asset's hulls as held on the grid, where they differ
  if (document.options().meshopt) {
    // KHR_mesh_quantization: the node's transform maps the grid to output units, for the mesh
    // and the extras' vertices alike.
    grid = Quantization::of(asset);
    document.node(node_index)["translation"] = {grid->origin.x, grid->origin.y, 0.0};
    document.node(node_index)["scale"] = {grid->step, grid->step, grid->step};
    on_grid = held_on_grid(asset, *grid);
  }
  const CookedAsset& written = on_grid ? *on_grid : asset;
  json levels = json::array();
  for (std::size_t l = 0; l < written.levels.size(); ++l) {
    std::optional<int> vertices;
    if (l == 0) {
      const TriangleMesh mesh = flat_mesh(written.levels[0].hulls, asset.name);
      if (!mesh.indices.empty()) {
        int positions = -1;
        json primitive =
            document.options().draco
                ? draco_primitive(document, mesh, asset.name)
                : plain_primitive(document, mesh, written.levels[0].hulls, grid, positions);
        // Without Draco, the mesh's positions are the finest level's vertices (z = 0).
        if (positions >= 0) vertices = positions;
        const int mesh_index = document.add_mesh(std::move(primitive));
        document.node(node_index)["mesh"] = mesh_index;
        add_colliders(document, asset, node_index, mesh_index);
      }
    }
    levels.push_back(level_json(document, written.levels[l], vertices, grid));
  }
  extras["levels"] = std::move(levels);
  document.node(node_index)["extras"] = {{"hullcook", std::move(extras)}};
  return node_index;
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
  if (options.draco && options.meshopt) {
    throw UsageError("--draco and --meshopt compress the same meshes: give one of them");
  }
  Document document(options);
  if (options.meshopt) {
    std::size_t largest = 0;
    for (const CookedAsset& asset : assets) {
      std::size_t vertices = 0;
      if (!asset.levels.empty()) {
        for (const Ring& hull : asset.levels.front().hulls) vertices += hull.size();
      }
      largest = std::max(largest, vertices);
    }
    document.set_index_component(largest < 0xFFFF ? kComponentUnsignedShort
                                                  : kComponentUnsignedInt);
  }
  std::vector<int> scene_nodes;
  scene_nodes.reserve(assets.size());
  for (const CookedAsset& asset : assets) scene_nodes.push_back(add_asset(document, asset));

  // Names are valid UTF-8 (valid_utf8); any other string is replaced alike.
  std::string text = document.finish(scene_nodes, !options.binary)
                         .dump(-1, ' ', false, json::error_handler_t::replace);
  if (!options.binary) return text;
  return glb_container(text, document.buffer());
}

}  // namespace hullcook
