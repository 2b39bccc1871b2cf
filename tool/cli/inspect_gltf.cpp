// `hullcook inspect FILE.gltf|FILE.glb`: reads the hulls back from the asset nodes' extras
// (docs/gltf-extras.md), the canonical data; the meshes are only a mirror and are not read.
// Version 1 of the extras holds the hulls as JSON numbers, version 2 as accessors into the buffer.
#include "counted.h"
#include "gltf_data.h"
#include "inspect.h"
#include "printable.h"
#include "shortest.h"

#include "hullcook/cook/asset.h"
#include "hullcook/cook/contract.h"
#include "hullcook/cook/debug_json.h"
#include "hullcook/core/decompose.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hullcook::cli {
namespace {

using json = nlohmann::json;

constexpr int kExtrasVersion = 2;  // the newest extras schema this reader knows

std::uint32_t read_u32(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<std::uint8_t>(bytes[offset + i]);
  return value;
}

std::string read_file(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw BadGltf("is a directory");
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    throw BadGltf("not a regular file");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw BadGltf("cannot open the file");
  std::ostringstream content;
  content << file.rdbuf();
  if (file.bad()) throw BadGltf("cannot read the file");
  return std::move(content).str();
}

// The JSON text of a .gltf, or of a .glb's JSON chunk after checking the container; `bin` gets
// the .glb's BIN chunk, if any.
std::string json_text(const std::string& bytes, bool& binary, std::string& bin) {
  binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  if (!binary) return bytes;
  if (bytes.size() < 20) throw BadGltf("truncated GLB: " + std::to_string(bytes.size()) + " bytes");
  if (std::uint32_t version = read_u32(bytes, 4); version != 2) {
    throw BadGltf("GLB container version " + std::to_string(version) + ", expected 2");
  }
  if (std::uint32_t length = read_u32(bytes, 8); length != bytes.size()) {
    throw BadGltf("GLB header gives " + std::to_string(length) + " bytes but the file has " +
                  std::to_string(bytes.size()) + " (truncated or padded)");
  }
  const std::uint32_t chunk_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != 0x4E4F534A) throw BadGltf("the first GLB chunk is not JSON");
  if (chunk_length > bytes.size() - 20) throw BadGltf("the GLB JSON chunk runs past the end");
  const std::size_t bin_start = 20 + std::size_t{chunk_length};
  if (bytes.size() - bin_start >= 8 && read_u32(bytes, bin_start + 4) == 0x004E4942) {
    const std::uint32_t bin_length = read_u32(bytes, bin_start);
    if (bin_length > bytes.size() - bin_start - 8) {
      throw BadGltf("the GLB BIN chunk runs past the end");
    }
    bin = bytes.substr(bin_start + 8, bin_length);
  }
  return bytes.substr(20, chunk_length);
}

// Typed access to the extras, each failure naming the asset and the key.
class Fields {
 public:
  Fields(const json& object, std::string where) : object_(object), where_(std::move(where)) {}

  const json& get(const char* key) const {
    auto it = object_.find(key);
    if (it == object_.end()) throw BadGltf(where_ + ": missing \"" + key + "\"");
    return *it;
  }
  double number(const char* key) const { return number_of(get(key), key); }
  double number_of(const json& value, const std::string& key) const {
    if (!value.is_number()) throw BadGltf(where_ + ": \"" + key + "\" is not a number");
    double number = value.get<double>();
    if (!std::isfinite(number)) throw BadGltf(where_ + ": \"" + key + "\" is not finite");
    return number;
  }
  std::string string(const char* key) const {
    const json& value = get(key);
    if (!value.is_string()) throw BadGltf(where_ + ": \"" + key + "\" is not a string");
    return value.get<std::string>();
  }
  bool boolean(const char* key) const {
    const json& value = get(key);
    if (!value.is_boolean()) throw BadGltf(where_ + ": \"" + key + "\" is not a boolean");
    return value.get<bool>();
  }
  std::int64_t integer(const char* key, std::int64_t min, std::int64_t max) const {
    const json& value = get(key);
    if (!value.is_number_integer() || value.get<std::int64_t>() < min ||
        value.get<std::int64_t>() > max) {
      throw BadGltf(where_ + ": \"" + key + "\" is not an integer in [" + std::to_string(min) +
                    ", " + std::to_string(max) + "]");
    }
    return value.get<std::int64_t>();
  }
  Vec2 pair(const char* key) const {
    const json& value = get(key);
    if (!value.is_array() || value.size() != 2) {
      throw BadGltf(where_ + ": \"" + key + "\" is not a pair of numbers");
    }
    return {number_of(value[0], key), number_of(value[1], key)};
  }
  const json& array(const char* key) const {
    const json& value = get(key);
    if (!value.is_array()) throw BadGltf(where_ + ": \"" + key + "\" is not an array");
    return value;
  }
  const json& object(const char* key) const {
    const json& value = get(key);
    if (!value.is_object()) throw BadGltf(where_ + ": \"" + key + "\" is not an object");
    return value;
  }
  const std::string& where() const { return where_; }

 private:
  const json& object_;
  std::string where_;
};

// Version 1: each hull a flat JSON array [x0, y0, x1, y1, ...].
std::vector<Ring> json_hulls(const Fields& level) {
  std::vector<Ring> hulls;
  const json& flats = level.array("hulls");
  for (std::size_t h = 0; h < flats.size(); ++h) {
    const json& flat = flats[h];
    const std::string key = "hulls[" + std::to_string(h) + "]";
    if (!flat.is_array() || flat.size() % 2 != 0) {
      throw BadGltf(level.where() + ": " + key + " is not a flat array of x, y pairs");
    }
    Ring hull;
    for (std::size_t i = 0; i < flat.size(); i += 2) {
      hull.push_back({level.number_of(flat[i], key), level.number_of(flat[i + 1], key)});
    }
    hulls.push_back(std::move(hull));
  }
  return hulls;
}

// The asset node's translation and scale (x and y), which map quantized vertices (--meshopt) to
// output units; identity when absent. A rotation or matrix is not hullcook's.
struct NodeScaling {
  Vec2 translation{0.0, 0.0};
  Vec2 scale{1.0, 1.0};
};

NodeScaling node_scaling(const json& node, const std::string& where) {
  NodeScaling scaling;
  if (node.contains("rotation") || node.contains("matrix")) {
    throw BadGltf(where + ": an asset node with a rotation or matrix");
  }
  const Fields fields(node, where);
  auto triple = [&](const char* key) {
    const json& value = fields.get(key);
    if (!value.is_array() || value.size() != 3)
      throw BadGltf(where + ": \"" + key + "\" is not 3 numbers");
    return Vec2{fields.number_of(value[0], key), fields.number_of(value[1], key)};
  };
  if (node.contains("translation")) scaling.translation = triple("translation");
  if (node.contains("scale")) scaling.scale = triple("scale");
  return scaling;
}

// Version 2: the vertex count of each hull in the accessor "counts", and the vertices, hull after
// hull, in the accessor "vertices" (x, y are its first two components, mapped by the node's
// translation and scale); both absent for a level without hulls.
std::vector<Ring> buffer_hulls(const json& level, const Fields& fields, const GltfData& data,
                               const NodeScaling& scaling, bool& floats) {
  floats = false;
  std::vector<Ring> hulls;
  if (!level.contains("counts")) {
    if (level.contains("vertices"))
      throw BadGltf(fields.where() + ": \"vertices\" without \"counts\"");
    return hulls;
  }
  const AccessorData counts = data.accessor(level["counts"], fields.where() + ".counts");
  if (counts.components != 1 || counts.component_type == 5126 || counts.component_type == 5120 ||
      counts.component_type == 5122) {
    throw BadGltf(fields.where() + ".counts: not an unsigned integer SCALAR accessor");
  }
  std::size_t total = 0;
  for (double count : counts.values) total += static_cast<std::size_t>(count);
  if (total == 0) {
    if (level.contains("vertices")) throw BadGltf(fields.where() + ": \"vertices\" for no vertex");
    hulls.resize(counts.values.size());
    return hulls;
  }
  const AccessorData vertices = data.accessor(fields.get("vertices"), fields.where() + ".vertices");
  if ((vertices.component_type != 5126 && vertices.component_type != 5122) ||
      vertices.components < 2) {
    throw BadGltf(fields.where() +
                  ".vertices: not a FLOAT or SHORT accessor of at least two components");
  }
  floats = vertices.component_type == 5126;
  const std::size_t stored = vertices.values.size() / vertices.components;
  if (stored != total) {
    throw BadGltf(fields.where() + ": the counts add up to " + std::to_string(total) +
                  " vertices but \"vertices\" has " + std::to_string(stored));
  }
  std::size_t next = 0;
  for (double count : counts.values) {
    Ring& hull = hulls.emplace_back();
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i, ++next) {
      const double x = vertices.values[next * vertices.components];
      const double y = vertices.values[next * vertices.components + 1];
      // Exact for the identity: 0 + 1 * x == x.
      hull.push_back({scaling.translation.x + scaling.scale.x * x,
                      scaling.translation.y + scaling.scale.y * y});
    }
  }
  return hulls;
}

// What the writer promises of every asset (docs/gltf-extras.md), checked as the bundle reader
// checks a bundle's: a file corrupted or changed by another tool is refused instead of printed.
// A helper's hunt (stop 60) had bit flips in meshopt data make hulls non-convex, a node scale of
// 0 make them points, and levels out of order, each printed with exit 0.
void check_asset(const CookedAsset& asset, const std::string& where) {
  if (asset.name.empty()) throw BadGltf(where + ": an asset node without a name");
  if (!stores_as_positive_float(asset.pixels_per_unit)) {
    throw BadGltf(where + ": \"pixels_per_unit\" is not a positive 32-bit float");
  }
  if (!(asset.tau >= 0)) throw BadGltf(where + ": a negative \"tau\"");
  if (!parse_measure(asset.measure)) {
    throw BadGltf(where + ": \"measure\" '" + printable(asset.measure) +
                  "' is not one of sl, sp, h1, h2");
  }
  double finer = 0.0;
  for (std::size_t l = 0; l < asset.levels.size(); ++l) {
    const CookedLevel& level = asset.levels[l];
    const std::string at = where + ".levels[" + std::to_string(l) + "]";
    if (!(level.tau >= finer)) {
      throw BadGltf(at + ": \"tau\" " + shortest_text(level.tau) +
                    (level.tau < 0 ? " is negative"
                                   : " is finer than the previous level's (finest go first)"));
    }
    finer = level.tau;
    for (std::size_t h = 0; h < level.hulls.size(); ++h) {
      for (const Vec2& v : level.hulls[h]) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) {
          throw BadGltf(at + ", hull " + std::to_string(h) + ": a vertex is not finite");
        }
      }
      if (std::optional<std::string> defect = hull_shape_defect(level.hulls[h])) {
        throw BadGltf(at + ", hull " + std::to_string(h) + ": " + *defect);
      }
    }
  }
}

CookedAsset read_asset(const json& node, const json& extras, std::size_t node_index,
                       const GltfData& data) {
  CookedAsset asset;
  asset.name = node.contains("name") && node["name"].is_string() ? node["name"].get<std::string>()
                                                                 : std::string();
  const Fields fields(
      extras, "node " + std::to_string(node_index) + " (\"" + asset.name + "\") extras.hullcook");
  const std::int64_t version = fields.integer("version", 1, INT32_MAX);
  if (version > kExtrasVersion) {
    throw BadGltf(fields.where() + ": version " + std::to_string(version) +
                  " is newer than this hullcook reads (" + std::to_string(kExtrasVersion) + ")");
  }
  asset.source = fields.string("source");
  const json& size = fields.array("image_size");
  if (size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer() ||
      size[0].get<std::int64_t>() < 0 || size[1].get<std::int64_t>() < 0 ||
      size[0].get<std::int64_t>() > INT32_MAX || size[1].get<std::int64_t>() > INT32_MAX) {
    throw BadGltf(fields.where() + ": \"image_size\" is not two non-negative integers");
  }
  asset.image_width = size[0].get<int>();
  asset.image_height = size[1].get<int>();
  asset.pixels_per_unit = fields.number("pixels_per_unit");
  asset.pivot = fields.pair("pivot");
  const Fields transform(fields.object("transform"), fields.where() + ".transform");
  asset.transform.scale = transform.number("scale");
  asset.transform.origin = transform.pair("origin");
  asset.transform.flip_y = transform.boolean("flip_y");
  asset.tau = fields.number("tau");
  asset.measure = fields.string("measure");

  const NodeScaling scaling =
      node_scaling(node, "node " + std::to_string(node_index) + " (\"" + asset.name + "\")");
  // --meshopt's grid (KHR_mesh_quantization): rounding to it moves a vertex by at most half a
  // step per coordinate, the bound that inspect of a bundle prints too (docs/gltf-extras.md).
  if (node.contains("scale") && scaling.scale.x == scaling.scale.y && scaling.scale.x > 0) {
    asset.quantization_error = scaling.scale.x / std::sqrt(2.0);
  }
  const json& levels = fields.array("levels");
  std::vector<char> of_floats(levels.size(), 0);
  for (std::size_t l = 0; l < levels.size(); ++l) {
    if (!levels[l].is_object()) throw BadGltf(fields.where() + ": a level is not an object");
    const Fields level_fields(levels[l], fields.where() + ".levels[" + std::to_string(l) + "]");
    CookedLevel level;
    level.tau = level_fields.number("tau");
    bool floats = false;
    level.hulls = version == 1 ? json_hulls(level_fields)
                               : buffer_hulls(levels[l], level_fields, data, scaling, floats);
    of_floats[l] = floats && !node.contains("translation") && !node.contains("scale");
    asset.levels.push_back(std::move(level));
  }
  // The writer promises convex hulls of the floats as stored (a reader computes with them), so
  // they are checked as they are; a float is then shown by its shortest decimal, which may turn
  // a nearly straight run of three the other way (a helper's review: --ppu 7.3 --weld 0).
  check_asset(asset, "node " + std::to_string(node_index) + " (\"" + printable(asset.name) +
                         "\") extras.hullcook");
  for (std::size_t l = 0; l < asset.levels.size(); ++l) {
    if (!of_floats[l]) continue;
    for (Ring& hull : asset.levels[l].hulls) {
      for (Vec2& v : hull) {
        v = {shortest_double(static_cast<float>(v.x)), shortest_double(static_cast<float>(v.y))};
      }
    }
  }

  if (extras.contains("physics")) {
    const Fields physics(fields.object("physics"), fields.where() + ".physics");
    PhysicsProperties properties;
    properties.density = static_cast<float>(physics.number("density"));
    properties.friction = static_cast<float>(physics.number("friction"));
    properties.restitution = static_cast<float>(physics.number("restitution"));
    properties.sensor = physics.boolean("sensor");
    properties.category_bits =
        static_cast<std::uint16_t>(physics.integer("category_bits", 0, 0xFFFF));
    properties.mask_bits = static_cast<std::uint16_t>(physics.integer("mask_bits", 0, 0xFFFF));
    asset.physics = properties;
  }
  return asset;
}

struct GltfContents {
  bool binary = false;
  bool draco = false;
  bool meshopt = false;
  std::size_t bytes = 0;
  std::vector<CookedAsset> assets;
};

GltfContents read_gltf(const std::filesystem::path& path) {
  GltfContents contents;
  const std::string bytes = read_file(path);
  contents.bytes = bytes.size();
  std::string bin;
  json root = json::parse(json_text(bytes, contents.binary, bin), nullptr, false);
  if (root.is_discarded()) {
    throw BadGltf(contents.binary ? "the GLB JSON chunk is not valid JSON"
                                  : "neither a GLB nor valid glTF JSON");
  }
  if (!root.is_object() || !root.contains("asset") || !root["asset"].is_object() ||
      !root["asset"].contains("version") || !root["asset"]["version"].is_string()) {
    throw BadGltf("not a glTF document (no asset.version)");
  }
  const std::string version = root["asset"]["version"];
  if (version.rfind("2.", 0) != 0) throw BadGltf("glTF version " + version + ", expected 2.x");
  if (root.contains("extensionsUsed") && root["extensionsUsed"].is_array()) {
    for (const json& name : root["extensionsUsed"]) {
      if (name == "KHR_draco_mesh_compression") contents.draco = true;
      if (name == "EXT_meshopt_compression") contents.meshopt = true;
    }
  }
  const GltfData data(root, std::move(bin));
  const bool ours = root["asset"].contains("generator") && root["asset"]["generator"] == "hullcook";
  if (ours && root.contains("nodes") && !root["nodes"].is_array()) {
    throw BadGltf("\"nodes\" is not an array");
  }
  if (root.contains("nodes") && root["nodes"].is_array()) {
    const json& nodes = root["nodes"];
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const json& node = nodes[i];
      const bool with_extras = node.is_object() && node.contains("extras") &&
                               node["extras"].is_object() && node["extras"].contains("hullcook") &&
                               node["extras"]["hullcook"].is_object();
      // Every node hullcook writes holds extras.hullcook (an asset node's, or in version 1 a hull
      // node's): one without it lost it (other tools' exports drop extras), and printing "0
      // assets" would hide that.
      if (!with_extras && ours) {
        throw BadGltf("node " + std::to_string(i) +
                      " has no extras.hullcook, which every node hullcook writes holds (the "
                      "hulls' data; did another tool drop the extras?)");
      }
      if (!with_extras) continue;
      const json& extras = node["extras"];
      if (!extras["hullcook"].contains("version")) continue;  // a hull node, not an asset node
      contents.assets.push_back(read_asset(node, extras["hullcook"], i, data));
    }
  }
  // hullcook writes a valid document for zero assets; any other glTF without our extras is not
  // ours.
  if (contents.assets.empty() && !ours) {
    throw BadGltf("glTF without hullcook data (no node has extras.hullcook with a version)");
  }
  // Names are the assets' keys, as in a bundle.
  std::vector<const std::string*> names;
  for (const CookedAsset& asset : contents.assets) names.push_back(&asset.name);
  std::sort(names.begin(), names.end(),
            [](const std::string* a, const std::string* b) { return *a < *b; });
  for (std::size_t i = 1; i < names.size(); ++i) {
    if (*names[i] == *names[i - 1]) {
      throw BadGltf("two asset nodes are named \"" + printable(*names[i]) + "\"");
    }
  }
  return contents;
}

std::string point_text(Vec2 p) {
  return "(" + shortest_text(p.x) + ", " + shortest_text(p.y) + ")";
}

void print_text(const std::filesystem::path& path, const GltfContents& contents) {
  std::size_t hulls = 0, vertices = 0;
  for (const CookedAsset& asset : contents.assets) {
    for (const CookedLevel& level : asset.levels) {
      hulls += level.hulls.size();
      for (const Ring& hull : level.hulls) vertices += hull.size();
    }
  }
  std::cout << path.string() << ": glTF 2.0 "
            << (contents.binary ? "binary (.glb)" : "text (.gltf)")
            << (contents.draco ? " with Draco meshes" : "")
            << (contents.meshopt ? " with meshopt compression" : "") << ", " << contents.bytes
            << " bytes, " << counted(contents.assets.size(), "asset", "assets") << ", "
            << counted(hulls, "hull", "hulls") << ", "
            << counted(vertices, "hull vertex", "hull vertices") << " over all levels";
  if (vertices > 0) {
    std::cout << ", " << shortest_text(std::round(10.0 * contents.bytes / vertices) / 10.0)
              << " bytes per vertex";
  }
  std::cout << "\n";
  for (const CookedAsset& asset : contents.assets) {
    std::cout << "asset \"" << printable(asset.name) << "\": source " << printable(asset.source)
              << ", image " << asset.image_width << "x" << asset.image_height << " px, "
              << shortest_text(asset.pixels_per_unit) << " px/unit, pivot "
              << point_text(asset.pivot) << ", measure " << asset.measure << ", tau "
              << shortest_text(asset.tau);
    if (asset.quantization_error) {
      std::cout << ", quantization error <= " << shortest_text(*asset.quantization_error)
                << " units";
    }
    std::cout << "\n";
    if (asset.physics) {
      const PhysicsProperties& p = *asset.physics;
      char bits[32];
      std::snprintf(bits, sizeof bits, "0x%04x, mask 0x%04x", p.category_bits, p.mask_bits);
      std::cout << "  physics: density " << shortest_text(p.density) << ", friction "
                << shortest_text(p.friction) << ", restitution " << shortest_text(p.restitution)
                << ", sensor " << (p.sensor ? "yes" : "no") << ", category " << bits << "\n";
    }
    for (std::size_t l = 0; l < asset.levels.size(); ++l) {
      const CookedLevel& level = asset.levels[l];
      std::size_t level_vertices = 0;
      for (const Ring& hull : level.hulls) level_vertices += hull.size();
      std::cout << "  level " << l << ": tau " << shortest_text(level.tau) << ", "
                << counted(level.hulls.size(), "hull", "hulls") << ", "
                << counted(level_vertices, "vertex", "vertices") << "\n";
      for (std::size_t h = 0; h < level.hulls.size(); ++h) {
        std::cout << "    hull " << h << " (" << level.hulls[h].size() << "):";
        for (const Vec2& v : level.hulls[h]) std::cout << " " << point_text(v);
        std::cout << "\n";
      }
    }
  }
}

// A glTF holds hulls only: each piece of the debug JSON gets its hull as its component too
// (regions and concavities are not stored), and the levels carry every level's hulls.
std::vector<CookedAsset> with_hull_pieces(std::vector<CookedAsset> assets) {
  for (CookedAsset& asset : assets) {
    asset.pieces.clear();
    if (asset.levels.empty()) continue;
    for (const Ring& hull : asset.levels.front().hulls) {
      asset.pieces.push_back(CookedPiece{Region{hull, {}}, hull, 0.0});
    }
    asset.stats.pieces = asset.pieces.size();
  }
  return assets;
}

}  // namespace

int inspect_gltf(const std::filesystem::path& path, bool json_output) {
  GltfContents contents;
  try {
    contents = read_gltf(path);
  } catch (const BadGltf& error) {
    std::cerr << "hullcook: error: " << path.string() << ": " << error.what() << "\n";
    return 2;
  } catch (const json::exception& error) {
    std::cerr << "hullcook: error: " << path.string() << ": malformed glTF: " << error.what()
              << "\n";
    return 2;
  }
  if (json_output) {
    std::cout << debug_json(with_hull_pieces(std::move(contents.assets)));
  } else {
    print_text(path, contents);
  }
  return 0;
}

}  // namespace hullcook::cli
