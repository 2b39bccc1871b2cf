#include "stress_runner.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/constrain.h"
#include "hullcook/cook/cook.h"
#include "hullcook/core/poly_io.h"

#include <glm/common.hpp>

#include <chrono>
#include <exception>
#include <fstream>
#include <limits>
#include <sstream>

namespace hullcook::stress {
namespace {

using Clock = std::chrono::steady_clock;

// The assets' hulls moved so that their bounding box's centre, rounded to a multiple of 1024,
// is the origin (an exact subtraction for hulls within a few thousand of it).
std::vector<CookedAsset> moved_to_origin(std::vector<CookedAsset> assets) {
  for (CookedAsset& asset : assets) {
    Vec2 low{std::numeric_limits<double>::infinity()}, high = -low;
    for (const CookedLevel& level : asset.levels) {
      for (const Ring& hull : level.hulls) {
        for (const Vec2& p : hull) low = glm::min(low, p), high = glm::max(high, p);
      }
    }
    if (!(low.x <= high.x)) continue;
    const Vec2 shift = glm::round((low + high) * (0.5 / 1024.0)) * 1024.0;
    for (CookedLevel& level : asset.levels) {
      for (Ring& hull : level.hulls) {
        for (Vec2& p : hull) p -= shift;
      }
    }
  }
  return assets;
}

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream file(path, std::ios::binary);
  file << bytes;
  if (!file) throw std::runtime_error(path.string() + ": cannot write");
}

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string cook_replay(const std::filesystem::path& input, const CookCase& settings) {
  return "hullcook cook " + input.string() + " --tau " + number(settings.tau_px) + " --ppu " +
         number(settings.pixels_per_unit) + " --measure " + measure_name(settings.measure) +
         (settings.weld ? " --weld " + number(*settings.weld) : std::string()) +
         (settings.alpha != 128 ? " --alpha " + number(settings.alpha) : std::string()) +
         (settings.simplify ? " --simplify " + number(*settings.simplify) : std::string()) +
         (settings.merge ? " --merge" : "") +
         (settings.max_verts != 8 ? " --max-verts " + std::to_string(settings.max_verts) : "") +
         " -o cooked.json";
}

std::string cook_label(const std::string& name, const CookCase& settings) {
  return name + ", cook " + measure_name(settings.measure) + ", tau " + number(settings.tau_px) +
         ", ppu " + number(settings.pixels_per_unit) +
         (settings.alpha != 128 ? ", alpha " + number(settings.alpha) : std::string()) +
         (settings.simplify ? ", simplify " + number(*settings.simplify) : std::string()) +
         (settings.merge ? ", merge" : "") +
         (settings.max_verts != 8 ? ", max-verts " + std::to_string(settings.max_verts) : "");
}

CaseOutcome cook_and_check(const std::filesystem::path& input, const CookCase& settings) {
  CaseOutcome outcome;
  Settings cook_settings;
  cook_settings.tau = Tolerance{settings.tau_px, false};
  cook_settings.pixels_per_unit = settings.pixels_per_unit;
  cook_settings.measure = measure_name(settings.measure);
  cook_settings.weld = settings.weld;
  cook_settings.alpha = settings.alpha;
  cook_settings.simplify = settings.simplify;
  cook_settings.merge_pieces = settings.merge;
  cook_settings.max_verts = settings.max_verts;
  cook_settings.threads = 1;
  auto start = Clock::now();
  try {
    const CookResult result = cook({input}, cook_settings);
    outcome.run_ms = milliseconds_since(start);
    start = Clock::now();
    for (const CookedAsset& asset : result.assets) {
      outcome.pieces += asset.pieces.size();
      const CheckReport report = check_cooked_asset(asset, cook_settings.max_verts,
                                                    cook_settings.weld.value_or(kDefaultWeld));
      for (const auto& [rule, count] : report.counts) outcome.report.counts[rule] += count;
      outcome.report.examples.insert(outcome.report.examples.end(), report.examples.begin(),
                                     report.examples.end());
      outcome.report.eps = report.eps;
    }
    outcome.check_ms = milliseconds_since(start);
    // One image alone splits its work over the cook's threads (issue 17): the bundle's bytes, or
    // the writer's refusal (a hull too long for 16-bit deltas, say), must not depend on how many.
    auto bundle_of = [&](const std::vector<CookedAsset>& assets) {
      try {
        return "bytes " + write_bundle(assets);
      } catch (const std::exception& error) {
        return "refused " + std::string(error.what());
      }
    };
    Settings threaded = cook_settings;
    threaded.threads = 3;
    std::string threaded_bundle;
    try {
      threaded_bundle = bundle_of(cook({input}, threaded).assets);
    } catch (const std::exception& error) {
      threaded_bundle = "cook threw " + std::string(error.what());
    }
    const std::string bundle = bundle_of(result.assets);
    // Drawn sprites and polygons within the stress's scales all fit the bundle's grid, except
    // hulls that the runtime's floats would break where they lie (an exact decomposition's
    // specks, 1e5 from the origin, where floats are 0.008 apart): the same hulls moved to the
    // origin must then be stored.
    if (bundle.find("would reach the runtime as a line, a point or a polygon that") !=
            std::string::npos &&
        bundle_of(moved_to_origin(result.assets)).starts_with("bytes")) {
      outcome.stored_only_near_origin = true;
    } else if (bundle.starts_with("refused")) {
      const std::string rule = "the .hcb writer refused the asset";
      ++outcome.report.counts[rule];
      outcome.report.examples.push_back({rule, bundle.substr(0, 300)});
    }
    if (threaded_bundle != bundle) {
      const std::string rule = "3 threads change the output";
      ++outcome.report.counts[rule];
      outcome.report.examples.push_back(
          {rule, "1 thread: " + bundle.substr(0, 200) +
                     "; 3 threads: " + threaded_bundle.substr(0, 200)});
    }
  } catch (const std::exception& error) {
    outcome.error = error.what();
    // The same error with 3 threads (the first region's, whatever the count).
    Settings threaded = cook_settings;
    threaded.threads = 3;
    try {
      cook({input}, threaded);
      outcome.error += " (but 3 threads cooked it)";
    } catch (const std::exception& threaded_error) {
      if (outcome.error != threaded_error.what()) {
        outcome.error += " (3 threads threw another: " + std::string(threaded_error.what()) + ")";
      }
    }
  }
  return outcome;
}

}  // namespace

std::string CaseOutcome::message() const {
  std::ostringstream text;
  text << label << " [" << description << "]: ";
  if (!error.empty()) text << "threw: " << error << "; ";
  text << report.summary();
  if (!saved.empty()) text << "\n  saved: " << saved.string() << "\n  replay: " << replay;
  return text.str();
}

CookCase image_cook(double tau_px, double pixels_per_unit, Measure measure) {
  CookCase cook;
  cook.tau_px = tau_px, cook.pixels_per_unit = pixels_per_unit, cook.measure = measure;
  return cook;
}

std::vector<CookCase> image_cooks(const std::vector<Measure>& measures,
                                  std::optional<ImageFamily> family) {
  std::vector<CookCase> cooks;
  for (Measure measure : measures) {
    for (const auto& [tau_px, pixels_per_unit] : {std::pair{1.0, 1.0}, {4.0, 1.0}, {1.0, 100.0}}) {
      cooks.push_back(image_cook(tau_px, pixels_per_unit, measure));
    }
    // τ 4 px: the most pieces a merge can join, into hulls of 4 vertices (slicing and halving).
    cooks[cooks.size() - 2].merge = true;
    cooks[cooks.size() - 2].max_verts = 4;
    if (family == ImageFamily::soft_edges) {
      CookCase faint = image_cook(0.25, 1.0, measure);
      faint.alpha = 1, faint.simplify = 0.0;
      cooks.push_back(faint);
    }
  }
  return cooks;
}

CookCase polygon_cook(double tau, Measure measure) {
  CookCase cook = image_cook(tau, 1.0, measure);
  if (tau == 0) cook.weld = 0.0;
  cook.merge = tau >= 4;  // as images are at τ 4 px
  // Fewer vertices per hull than the default at some τ, so that slicing and halving are checked.
  if (tau >= 4) cook.max_verts = 4;
  if (tau > 0 && tau < 1) cook.max_verts = 3;
  return cook;
}

bool cooks_polygon_at(Family family, double tau) { return family != Family::dense || tau > 0; }

CaseOutcome run_polygon_case(const GeneratedCase& generated, Measure measure, double tau,
                             const std::filesystem::path& failure_dir) {
  const std::string family = family_name(generated.family);
  CaseOutcome outcome =
      run_polygon_case(family + "-" + std::to_string(generated.seed), generated.regions,
                       generated.description, measure, tau, failure_dir);
  outcome.label = family + " seed " + std::to_string(generated.seed) + ", " +
                  measure_name(measure) + ", tau " + number(tau);
  return outcome;
}

CaseOutcome run_polygon_case(const std::string& name, const std::vector<Region>& regions,
                             const std::string& description, Measure measure, double tau,
                             const std::filesystem::path& failure_dir) {
  CaseOutcome outcome;
  outcome.label = name + ", " + measure_name(measure) + ", tau " + number(tau);
  outcome.description = description;
  std::vector<Piece> pieces;
  auto start = Clock::now();
  try {
    for (const Region& region : regions) {
      std::vector<Piece> part = decompose(region, {tau, measure, 0.1, 1.0}).pieces_at(tau);
      for (Piece& piece : part) pieces.push_back(std::move(piece));
    }
  } catch (const std::exception& error) {
    outcome.error = error.what();
  }
  outcome.run_ms = milliseconds_since(start);
  outcome.pieces = pieces.size();
  if (outcome.error.empty()) {
    start = Clock::now();
    std::vector<CheckedPiece> checked;
    for (const Piece& piece : pieces) checked.push_back({&piece.component, &piece.hull});
    CheckOptions options;
    options.tau = tau;
    outcome.report = check_pieces(regions, checked, options);
    outcome.check_ms = milliseconds_since(start);
  }
  if (!outcome.ok()) {
    outcome.saved = failure_dir / (name + ".poly");
    write_file(outcome.saved, format_poly(regions));
    outcome.replay = "hullcook decompose " + outcome.saved.string() + " --tau " + number(tau) +
                     " --measure " + measure_name(measure);
  }
  return outcome;
}

// Writes input (write may do nothing for a file that is given), cooks and checks it; the input
// is removed again when the case passes, unless it was there before (a failure's, kept).
template <typename Write>
CaseOutcome cook_file(const std::filesystem::path& input, Write write, const std::string& name,
                      const CookCase& settings) {
  const bool existed = std::filesystem::exists(input);
  write();
  CaseOutcome outcome = cook_and_check(input, settings);
  outcome.cooked = true;
  outcome.label = cook_label(name, settings);
  if (outcome.ok()) {
    if (!existed) std::filesystem::remove(input);
  } else {
    outcome.saved = input;
    outcome.replay = cook_replay(input, settings);
  }
  return outcome;
}

CaseOutcome run_polygon_cook_case(const GeneratedCase& generated, const CookCase& settings,
                                  const std::filesystem::path& failure_dir) {
  const std::string name =
      std::string(family_name(generated.family)) + "-" + std::to_string(generated.seed);
  const std::filesystem::path path = failure_dir / (name + ".poly");
  CaseOutcome outcome = cook_file(
      path, [&] { write_file(path, format_poly(generated.regions)); },
      std::string(family_name(generated.family)) + " seed " + std::to_string(generated.seed),
      settings);
  outcome.description = generated.description;
  return outcome;
}

CaseOutcome run_image_case(const DrawnImage& image, const CookCase& settings,
                           const std::filesystem::path& failure_dir) {
  const std::string family = image_family_name(image.family);
  const std::filesystem::path path =
      failure_dir / (family + "-" + std::to_string(image.seed) + ".png");
  CaseOutcome outcome = cook_file(
      path, [&] { write_file(path, encode_png(image)); },
      family + " seed " + std::to_string(image.seed), settings);
  outcome.description = image.description;
  return outcome;
}

CaseOutcome run_sprite_case(const std::filesystem::path& sprite, const CookCase& settings) {
  CaseOutcome outcome = cook_file(
      sprite, [] {}, sprite.filename().string(), settings);
  outcome.description = "given file";
  return outcome;
}

CheckReport check_cooked_asset(const CookedAsset& asset, std::size_t max_verts, double weld) {
  std::vector<CheckedPiece> checked;
  for (const CookedPiece& piece : asset.pieces) checked.push_back({&piece.component, &piece.hull});
  CheckOptions options;
  options.tau = asset.tau;
  options.exact_hulls = false;
  options.engine = EngineRules{max_verts, weld, kCollinearFractionOfWeld};
  return check_pieces(asset.regions, checked, options);
}

}  // namespace hullcook::stress
