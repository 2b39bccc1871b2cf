#include "cook_options.h"

#include "hullcook/core/error.h"

#include <cstdlib>
#include <sstream>

namespace hullcook::cli {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  return parts;
}

double parse_number(const std::string& text, const char* option) {
  char* end = nullptr;
  double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    throw UsageError(std::string(option) + ": '" + text + "' is not a number");
  }
  return value;
}

std::array<std::uint8_t, 3> parse_color(const std::string& text) {
  std::string hex = text;
  if (!hex.empty() && hex[0] == '#') hex.erase(0, 1);
  bool ok = hex.size() == 6 && hex.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos;
  if (!ok) throw UsageError("--color-key: '" + text + "' is not a colour like #ff00ff");
  unsigned long rgb = std::strtoul(hex.c_str(), nullptr, 16);
  return {static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8),
          static_cast<std::uint8_t>(rgb)};
}

}  // namespace

void add_cook_options(CLI::App& command, Settings& settings, CookOptions& options) {
  command
      .add_option("--tau", options.tau,
                  "Concavity tolerance τ: input units (px for images, e.g. 2) or a percentage "
                  "of the enclosing-circle radius R (e.g. 1%); 0 = exact convex pieces")
      ->capture_default_str()
      ->group("Decomposition");
  command.add_option("--measure", settings.measure, "Concavity measure: sl, sp, h1 or h2")
      ->check(CLI::IsMember({"sl", "sp", "h1", "h2"}))
      ->capture_default_str()
      ->group("Decomposition");
  command.add_option("--sc", settings.sc, "Eq. 8 weight of the concavity at the cut's far end")
      ->capture_default_str()
      ->group("Decomposition");
  command.add_option("--sd", settings.sd, "Eq. 8 weight of the cut's length")
      ->capture_default_str()
      ->group("Decomposition");
  command
      .add_option("--max-pieces", settings.max_pieces,
                  "Shape budget: the finest decomposition with at most K pieces per asset "
                  "(0 = no budget; τ still bounds it from below)")
      ->group("Decomposition");
  command
      .add_option("--lod", options.lods,
                  "Extra levels of detail as coarser τ values, e.g. 8,2,0.5 (same units as --tau)")
      ->group("Decomposition");

  command.add_option("--alpha", settings.alpha, "Opaque where alpha >= this (0-255)")
      ->check(CLI::Range(0, 255))
      ->capture_default_str()
      ->group("Tracing");
  command
      .add_option("--color-key", options.color_key,
                  "Trace images without alpha: this RGB colour is transparent (#ff00ff)")
      ->group("Tracing");
  command
      .add_option("--min-blob-area", settings.min_blob_area, "Drop blobs smaller than this [px²]")
      ->capture_default_str()
      ->group("Tracing");
  command
      .add_option("--min-hole-area", settings.min_hole_area, "Fill holes smaller than this [px²]")
      ->capture_default_str()
      ->group("Tracing");
  command
      .add_option("--simplify", options.simplify,
                  "Outline simplification error bound [px] (default τ/4, at most 1 px)")
      ->group("Tracing");
  command
      .add_option("--max-pixels", settings.max_pixels,
                  "Refuse images with more pixels than this, before decoding")
      ->capture_default_str()
      ->group("Tracing");

  command
      .add_option("--ppu", settings.pixels_per_unit, "Pixels per output unit (e.g. 32 px = 1 m)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str()
      ->group("World");
  command
      .add_option("--pivot", options.pivot,
                  "Output origin in normalised image coordinates u,v (0,0 = top left)")
      ->capture_default_str()
      ->group("World");
  command.add_flag("--y-down", settings.y_down, "Keep the image's y-down orientation")
      ->group("World");

  command
      .add_option("--max-verts", settings.max_verts,
                  "Most vertices per hull (Box2D 2.4: 8; 0 = unlimited, e.g. for Chipmunk)")
      ->capture_default_str()
      ->group("Engine");
  command
      .add_option("--weld", options.weld,
                  "No two hull vertices closer than this [output units]; default 0.005, "
                  "Box2D 2.4's b2_linearSlop at 1 unit = 1 m")
      ->group("Engine");

  command.add_option("--density", options.physics.density, "Density [kg/unit²]")->group("Physics");
  command.add_option("--friction", options.physics.friction, "Friction coefficient")
      ->group("Physics");
  command.add_option("--restitution", options.physics.restitution, "Restitution (bounciness)")
      ->group("Physics");
  command.add_flag("--sensor", options.physics.sensor, "Mark the bodies' shapes as sensors")
      ->group("Physics");
  command.add_option("--category", options.physics.category_bits, "Collision category bits")
      ->group("Physics");
  command.add_option("--mask", options.physics.mask_bits, "Collision mask bits")->group("Physics");

  command
      .add_option("--threads", settings.threads,
                  "Worker threads (0 = all cores); the output never depends on it")
      ->group("Output");
}

void finish_cook_options(const CLI::App& command, Settings& settings, const CookOptions& options) {
  settings.tau = Tolerance::parse(options.tau);
  settings.lods.clear();
  if (!options.lods.empty()) {
    for (const std::string& lod : split(options.lods, ',')) {
      Tolerance tolerance = Tolerance::parse(lod);
      if (tolerance.relative != settings.tau.relative) {
        throw UsageError("--lod: '" + lod + "' must use the same kind of units as --tau");
      }
      settings.lods.push_back(tolerance);
    }
  }
  if (!options.color_key.empty()) settings.color_key = parse_color(options.color_key);
  std::vector<std::string> pivot = split(options.pivot, ',');
  if (pivot.size() != 2) throw UsageError("--pivot: expected u,v such as 0.5,0.5");
  settings.pivot_u = parse_number(pivot[0], "--pivot");
  settings.pivot_v = parse_number(pivot[1], "--pivot");
  if (options.weld >= 0) settings.weld = options.weld;
  if (options.simplify >= 0) settings.simplify = options.simplify;
  bool any_physics = false;
  for (const char* name :
       {"--density", "--friction", "--restitution", "--sensor", "--category", "--mask"}) {
    any_physics = any_physics || command.count(name) > 0;
  }
  if (any_physics) settings.physics = options.physics;
}

}  // namespace hullcook::cli
