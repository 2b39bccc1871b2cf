#include "cook_options.h"

#include "hullcook/core/error.h"

#include <cmath>
#include <cstdlib>
#include <limits>
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

}  // namespace

CLI::Validator number_in(double low, double high, const std::string& what) {
  return CLI::Validator(
      [low, high, what](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size() || !(value >= low) ||
            !(value <= high)) {
          return "'" + text + "' is not " + what;
        }
        return std::string();
      },
      what);
}

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
      ->check(number_in(0, 1e9, "a weight in [0, 1e9]"))
      ->capture_default_str()
      ->group("Decomposition");
  command.add_option("--sd", settings.sd, "Eq. 8 weight of the cut's length")
      ->check(number_in(1e-9, 1e9, "a weight in [1e-9, 1e9]"))
      ->capture_default_str()
      ->group("Decomposition");
  command
      .add_option("--max-pieces", settings.max_pieces,
                  "Shape budget: the finest decomposition with at most K pieces per asset "
                  "(0 = no budget; τ still bounds it from below)")
      ->check(number_in(0, 1e9, "a count of pieces (0 = no budget)"))
      ->group("Decomposition");
  command
      .add_option(
          "--lod", options.lods,
          "Extra levels of detail as other τ values, coarser or finer, e.g. 8,2,0.5 (same units "
          "as --tau)")
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
      ->check(number_in(0, 1e18, "an area in [0, 1e18] px²"))
      ->capture_default_str()
      ->group("Tracing");
  command
      .add_option("--min-hole-area", settings.min_hole_area, "Fill holes smaller than this [px²]")
      ->check(number_in(0, 1e18, "an area in [0, 1e18] px²"))
      ->capture_default_str()
      ->group("Tracing");
  command
      .add_option("--simplify", options.simplify,
                  "Outline simplification error bound [px] (default τ/4, at most 1 px)")
      ->check(number_in(0, 1e9, "a length in [0, 1e9] px"))
      ->group("Tracing");
  command
      .add_option("--max-pixels", settings.max_pixels,
                  "Refuse images with more pixels than this, before decoding")
      ->check(number_in(1, 1e15, "a pixel count in [1, 1e15]"))
      ->capture_default_str()
      ->group("Tracing");

  command
      .add_option("--grid", options.grid,
                  "Cut every image into cells of WxH px (64x64, or 64), each non-empty cell an "
                  "asset named NAME/INDEX (row-major from 0)")
      ->group("Sheets");
  command.add_option("--margin", options.margin, "With --grid: px before the first row and column")
      ->check(CLI::Range(0, 65535))
      ->group("Sheets");
  command.add_option("--spacing", options.spacing, "With --grid: px between cells")
      ->check(CLI::Range(0, 65535))
      ->group("Sheets");
  command
      .add_flag("--tile", options.tile,
                "With --grid: a tileset; each cell's shape stays inside the cell and meets its "
                "border exactly (no seams between solid neighbours)")
      ->group("Sheets");
  command
      .add_option("--snap", options.snap,
                  "With --tile: outline points within this many px of the cell's border lie on it")
      ->check(number_in(0, 16, "a distance in [0, 16] px"))
      ->capture_default_str()
      ->group("Sheets");

  command
      .add_option("--ppu", settings.pixels_per_unit, "Pixels per output unit (e.g. 32 px = 1 m)")
      ->check(number_in(1e-6, 1e6, "a scale in [1e-6, 1e6] pixels per unit"))
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
      ->check(number_in(0, 1e9, "a vertex count (0 = unlimited, else at least 3)"))
      ->capture_default_str()
      ->group("Engine");
  command
      .add_option("--weld", options.weld,
                  "No two hull vertices closer than this [output units]; default 0.005, "
                  "Box2D 2.4's b2_linearSlop at 1 unit = 1 m")
      ->check(number_in(0, 1e9, "a distance in [0, 1e9] output units"))
      ->group("Engine");
  command
      .add_flag("--merge", settings.merge_pieces,
                "Merge neighbouring pieces whose union is one piece within tau and fits one "
                "hull: fewer hulls, same error bound, slower")
      ->group("Engine");

  const CLI::Validator physical = number_in(0, kMaxPhysicsValue, "a finite number >= 0 (an f32)");
  command.add_option("--density", options.physics.density, "Density [kg/unit²]")
      ->check(physical)
      ->group("Physics");
  command.add_option("--friction", options.physics.friction, "Friction coefficient")
      ->check(physical)
      ->group("Physics");
  command.add_option("--restitution", options.physics.restitution, "Restitution (bounciness)")
      ->check(physical)
      ->group("Physics");
  command.add_flag("--sensor", options.physics.sensor, "Mark the bodies' shapes as sensors")
      ->group("Physics");
  const CLI::Validator bits = number_in(0, 65535, "an integer in 0..65535");
  command.add_option("--category", options.physics.category_bits, "Collision category bits")
      ->check(bits)
      ->group("Physics");
  command.add_option("--mask", options.physics.mask_bits, "Collision mask bits")
      ->check(bits)
      ->group("Physics");

  command
      .add_option("--threads", settings.threads,
                  "Worker threads (0 = all cores); the output never depends on it")
      ->check(number_in(0, 4096, "a thread count in 0..4096"))
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
  if (!options.color_key.empty()) {
    try {
      settings.color_key = parse_color(options.color_key);
    } catch (const UsageError& e) {
      throw UsageError(std::string("--color-key: ") + e.what());
    }
  }
  std::vector<std::string> pivot = split(options.pivot, ',');
  if (pivot.size() != 2) throw UsageError("--pivot: expected u,v such as 0.5,0.5");
  settings.pivot_u = parse_number(pivot[0], "--pivot");
  settings.pivot_v = parse_number(pivot[1], "--pivot");
  if (std::abs(settings.pivot_u) > kLargestPivot || std::abs(settings.pivot_v) > kLargestPivot) {
    throw UsageError("--pivot: '" + options.pivot + "' is not within [-1e6, 1e6] image sizes");
  }
  if (settings.max_verts == 1 || settings.max_verts == 2) {
    throw UsageError("--max-verts: " + std::to_string(settings.max_verts) +
                     " is too few for a polygon: use 0 (unlimited) or at least 3");
  }
  if (!options.grid.empty()) {
    Grid grid = Grid::parse(options.grid);
    grid.margin = options.margin;
    grid.spacing = options.spacing;
    if (options.tile) grid.tile_snap = options.snap;
    if (!options.tile && command.count("--snap") > 0) throw UsageError("--snap goes with --tile");
    settings.grid = grid;
  } else if (command.count("--margin") > 0 || command.count("--spacing") > 0 || options.tile) {
    throw UsageError("--margin, --spacing and --tile describe a --grid: give one");
  }
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
