// `hullcook inspect FILE [--json]`: what a bundle (.hcb) or a glTF written by hullcook holds.
// Bundles are read with the game runtime itself (hullcook::runtime), so inspect shows exactly
// what a game sees; glTF files go to inspect_gltf() (inspect_gltf.cpp).
#include "commands.h"
#include "counted.h"
#include "inspect.h"
#include "printable.h"
#include "shortest.h"

#include "hullcook/cook/debug_json.h"
#include "hullcook/runtime.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace hullcook::cli {
namespace {

namespace rt = hullcook::runtime;

std::string point_text(rt::Vec2 p) {
  return "(" + shortest_text(p.x) + ", " + shortest_text(p.y) + ")";
}

void print_text(const std::filesystem::path& path, const rt::Bundle& bundle) {
  const std::size_t vertices = bundle.vertex_count();
  std::cout << path.string() << ": hullcook bundle " << bundle.version_major() << "."
            << bundle.version_minor() << ", " << bundle.size() << " bytes (64-byte header), "
            << counted(bundle.asset_count(), "asset", "assets") << ", "
            << counted(bundle.level_count(), "level", "levels") << ", "
            << counted(bundle.hull_count(), "hull", "hulls") << ", "
            << counted(vertices, "hull vertex", "hull vertices");
  if (vertices > 0) {
    std::cout << ", " << shortest_text(std::round(100.0 * bundle.size() / vertices) / 100.0)
              << " bytes per vertex overall (4 per vertex + 12 per hull + 8 per level + 32 per "
                 "asset + names)";
  }
  std::cout << "\n";
  for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
    const rt::Asset asset = bundle.asset(a);
    std::cout << "asset \"" << printable(asset.name()) << "\": image " << asset.image_width() << "x"
              << asset.image_height() << " px, " << shortest_text(asset.pixels_per_unit())
              << " px/unit, pivot " << point_text(asset.pivot()) << ", y "
              << (asset.flip_y() ? "up" : "down") << ", measure "
              << (*asset.measure() ? asset.measure() : "unknown")
              << ", quantization error <= " << shortest_text(asset.quantization_error())
              << " units\n";
    if (asset.has_physics()) {
      const rt::Physics p = asset.physics();
      char bits[48];
      std::snprintf(bits, sizeof bits, "0x%04x, mask 0x%04x", p.category_bits, p.mask_bits);
      std::cout << "  physics: density " << shortest_text(p.density) << ", friction "
                << shortest_text(p.friction) << ", restitution " << shortest_text(p.restitution)
                << ", sensor " << (p.sensor ? "yes" : "no") << ", category " << bits << "\n";
    }
    for (std::size_t l = 0; l < asset.level_count(); ++l) {
      const rt::Level level = asset.level(l);
      std::cout << "  level " << l << ": tau " << shortest_text(level.tau()) << ", "
                << counted(level.hull_count(), "hull", "hulls") << ", "
                << counted(level.vertex_count(), "vertex", "vertices") << "\n";
      for (std::size_t h = 0; h < level.hull_count(); ++h) {
        const rt::Hull hull = level.hull(h);
        std::cout << "    hull " << h << " (" << hull.vertex_count() << "):";
        for (std::size_t v = 0; v < hull.vertex_count(); ++v)
          std::cout << " " << point_text(hull.vertex(v));
        std::cout << "\n";
      }
    }
  }
}

// The bundle as cooked assets, for the one debug JSON writer. A bundle holds hulls only: regions
// are empty, each piece is its hull (component and hull alike, concavity 0), the source is the
// name, and the transform is rebuilt from the pixels per unit, pivot and y direction.
std::vector<CookedAsset> cooked_assets(const rt::Bundle& bundle) {
  std::vector<CookedAsset> assets;
  for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
    const rt::Asset asset = bundle.asset(a);
    CookedAsset& cooked = assets.emplace_back();
    cooked.name = cooked.source = std::string(asset.name());
    cooked.image_width = static_cast<int>(asset.image_width());
    cooked.image_height = static_cast<int>(asset.image_height());
    cooked.pixels_per_unit = shortest_double(asset.pixels_per_unit());
    const rt::Vec2 pivot = asset.pivot();
    cooked.pivot = Vec2{shortest_double(pivot.x), shortest_double(pivot.y)};
    cooked.transform =
        Transform{1.0 / cooked.pixels_per_unit,
                  Vec2{cooked.pivot.x * cooked.image_width, cooked.pivot.y * cooked.image_height},
                  asset.flip_y()};
    cooked.measure = asset.measure();
    cooked.quantization_error = shortest_double(asset.quantization_error());
    for (std::size_t l = 0; l < asset.level_count(); ++l) {
      const rt::Level level = asset.level(l);
      CookedLevel& cooked_level = cooked.levels.emplace_back();
      cooked_level.tau = shortest_double(level.tau());
      for (std::size_t h = 0; h < level.hull_count(); ++h) {
        Ring& ring = cooked_level.hulls.emplace_back();
        const rt::Hull hull = level.hull(h);
        for (std::size_t i = 0; i < hull.vertex_count(); ++i) {
          const rt::Vec2 v = hull.vertex(i);
          ring.push_back(Vec2{shortest_double(v.x), shortest_double(v.y)});
        }
        if (l == 0) cooked.pieces.push_back(CookedPiece{Region{ring, {}}, ring, 0.0});
      }
    }
    if (!cooked.levels.empty()) cooked.tau = cooked.levels.front().tau;
    cooked.stats.pieces = cooked.pieces.size();
    if (asset.has_physics()) {
      const rt::Physics p = asset.physics();
      cooked.physics = PhysicsProperties{p.density, p.friction,      p.restitution,
                                         p.sensor,  p.category_bits, p.mask_bits};
    }
  }
  return assets;
}

// For a file that is no bundle: what hullcook's other outputs are, when it is one of them.
std::string what_it_is(const rt::MappedFile& file) {
  const auto* bytes = static_cast<const unsigned char*>(file.data());
  std::size_t first = 0;
  while (first < file.size() && std::isspace(bytes[first])) ++first;
  if (first < file.size() && bytes[first] == '{') {
    return "; it is JSON, as hullcook's debug JSON is (-o X.json, --json): readable as it is";
  }
  if (file.size() >= 4 && std::memcmp(bytes, "HCF\x1a", 4) == 0) {
    return "; it is a hullcook fragment (.hcf): `hullcook link` it into a bundle to inspect it";
  }
  return "";
}

int inspect_bundle(const std::filesystem::path& path, bool json_output) {
  rt::MappedFile file;
  rt::Status status = file.open(path.c_str());
  rt::Bundle bundle;
  if (status == rt::Status::ok) status = bundle.open(file.data(), file.size());
  if (status != rt::Status::ok) {
    std::cerr << "hullcook: error: " << path.string() << ": " << rt::status_string(status)
              << (status == rt::Status::bad_magic || status == rt::Status::truncated
                      ? what_it_is(file)
                      : "")
              << "\n";
    return 2;
  }
  if (json_output) {
    std::cout << debug_json(cooked_assets(bundle));
  } else {
    print_text(path, bundle);
  }
  return 0;
}

bool is_gltf(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".gltf" || extension == ".glb";
}

void add_inspect(CLI::App& root, CommandAction& action) {
  auto* command = root.add_subcommand(
      "inspect",
      "Print what a bundle (.hcb) or a glTF (.gltf, .glb) written by hullcook holds: assets, "
      "levels, hulls, vertices, bytes per vertex. A bad file prints its problem and exits 2.");
  auto file = std::make_shared<std::string>();
  auto json_output = std::make_shared<bool>(false);
  command->add_option("FILE", *file, "the bundle or glTF file")->required();
  command->add_flag("--json", *json_output, "print the debug JSON (schema of `decompose --json`)");
  command->callback([&action, file, json_output] {
    action = [file, json_output] {
      const std::filesystem::path path(*file);
      return is_gltf(path) ? inspect_gltf(path, *json_output) : inspect_bundle(path, *json_output);
    };
  });
}

const CommandRegistration registered{60, "inspect", add_inspect};

}  // namespace
}  // namespace hullcook::cli
