// `hullcook inspect FILE [--json]`: what a bundle (.hcb) or a glTF written by hullcook holds.
// Bundles are read with the game runtime itself (hullcook::runtime), so inspect shows exactly
// what a game sees; glTF files go to inspect_gltf() (inspect_gltf.cpp).
#include "commands.h"
#include "inspect.h"

#include "hullcook/runtime.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace hullcook::cli {
namespace {

namespace rt = hullcook::runtime;
using json = nlohmann::json;

// A float as the double of its shortest decimal form, so that 0.6f prints as 0.6 and parsing
// the printed text gives the float back.
double shortest_double(float value) {
  std::array<char, 32> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::strtod(std::string(text.data(), result.ptr).c_str(), nullptr);
}

std::string shortest_text(double value) {
  std::array<char, 32> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::string(text.data(), result.ptr);
}

std::string shortest_text(float value) {
  std::array<char, 32> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::string(text.data(), result.ptr);
}

std::string point_text(rt::Vec2 p) {
  return "(" + shortest_text(p.x) + ", " + shortest_text(p.y) + ")";
}

json hull_json(const rt::Hull& hull) {
  json points = json::array();
  for (std::size_t i = 0; i < hull.vertex_count(); ++i) {
    const rt::Vec2 v = hull.vertex(i);
    points.push_back({shortest_double(v.x), shortest_double(v.y)});
  }
  return points;
}

void print_text(const std::filesystem::path& path, const rt::Bundle& bundle) {
  const std::size_t vertices = bundle.vertex_count();
  std::cout << path.string() << ": hullcook bundle " << bundle.version_major() << "."
            << bundle.version_minor() << ", " << bundle.size() << " bytes (64-byte header), "
            << bundle.asset_count() << " assets, " << bundle.level_count() << " levels, "
            << bundle.hull_count() << " hulls, " << vertices << " hull vertices";
  if (vertices > 0) {
    std::cout << ", " << shortest_text(std::round(100.0 * bundle.size() / vertices) / 100.0)
              << " bytes per vertex overall (4 per vertex + 12 per hull + 8 per level + 32 per "
                 "asset + names)";
  }
  std::cout << "\n";
  for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
    const rt::Asset asset = bundle.asset(a);
    std::cout << "asset \"" << asset.name() << "\": image " << asset.image_width() << "x"
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
                << level.hull_count() << " hulls, " << level.vertex_count() << " vertices\n";
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

// The debug JSON of issue 3. A bundle holds hulls only: `regions` is empty and each piece has
// only its `hull` (no `component`, no `concavity`); `source` is the name; `transform` is
// rebuilt from the pixels per unit, pivot and y direction. `levels`, `image_size`,
// `pixels_per_unit`, `pivot`, `quantization_error` and `physics` extend the schema, with the
// same names as the glTF inspector's.
json debug_json(const rt::Bundle& bundle) {
  json assets = json::array();
  for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
    const rt::Asset asset = bundle.asset(a);
    json pieces = json::array(), levels = json::array();
    for (std::size_t l = 0; l < asset.level_count(); ++l) {
      const rt::Level level = asset.level(l);
      json hulls = json::array();
      for (std::size_t h = 0; h < level.hull_count(); ++h) {
        hulls.push_back(hull_json(level.hull(h)));
        if (l == 0) pieces.push_back({{"hull", hulls.back()}});
      }
      levels.push_back({{"tau", shortest_double(level.tau())}, {"hulls", std::move(hulls)}});
    }
    const double ppu = shortest_double(asset.pixels_per_unit());
    const rt::Vec2 pivot = asset.pivot();
    json entry = {
        {"name", std::string(asset.name())},
        {"source", std::string(asset.name())},
        {"transform",
         {{"scale", 1.0 / ppu},
          {"origin",
           {shortest_double(pivot.x) * asset.image_width(),
            shortest_double(pivot.y) * asset.image_height()}},
          {"flip_y", asset.flip_y()}}},
        {"tau", shortest_double(asset.level(0).tau())},
        {"measure", asset.measure()},
        {"regions", json::array()},
        {"pieces", pieces},
        {"levels", std::move(levels)},
        {"image_size", {asset.image_width(), asset.image_height()}},
        {"pixels_per_unit", ppu},
        {"pivot", {shortest_double(pivot.x), shortest_double(pivot.y)}},
        {"quantization_error", shortest_double(asset.quantization_error())},
        {"stats", {{"pieces", pieces.size()}}},
    };
    if (asset.has_physics()) {
      const rt::Physics p = asset.physics();
      entry["physics"] = {{"density", shortest_double(p.density)},
                          {"friction", shortest_double(p.friction)},
                          {"restitution", shortest_double(p.restitution)},
                          {"sensor", p.sensor},
                          {"category_bits", p.category_bits},
                          {"mask_bits", p.mask_bits}};
    }
    assets.push_back(std::move(entry));
  }
  return {{"hullcook", 1}, {"assets", std::move(assets)}};
}

int inspect_bundle(const std::filesystem::path& path, bool json_output) {
  rt::MappedFile file;
  rt::Status status = file.open(path.c_str());
  rt::Bundle bundle;
  if (status == rt::Status::ok) status = bundle.open(file.data(), file.size());
  if (status != rt::Status::ok) {
    std::cerr << "hullcook: error: " << path.string() << ": " << rt::status_string(status) << "\n";
    return 2;
  }
  if (json_output) {
    std::cout << debug_json(bundle).dump(2) << "\n";
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

const CommandRegistration registered{60, add_inspect};

}  // namespace
}  // namespace hullcook::cli
