// cook(): inputs → traced or read polygons → decomposition tree → levels →
// engine limits.
#include "hullcook/cook/cook.h"

#include "asset_settings.h"
#include "contract_text.h"
#include "cook_inputs.h"
#include "grid.h"
#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/constrain.h"
#include "hullcook/cook/contract.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/parallel_for.h"
#include "hullcook/core/poly_io.h"
#include "hullcook/format/bundle_layout.h"
#include "hullcook/trace/trace.h"
#include "listed_files.h"
#include "sheet.h"
#include "tile_snap.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include "hullcook/cook/process_heap.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <iomanip>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace hullcook {
namespace {

void transform_in_place(Region& region, const Transform& transform) {
  for (Vec2& v : region.outer) v = transform.apply(v);
  for (Ring& hole : region.holes) {
    for (Vec2& v : hole) v = transform.apply(v);
  }
}

std::size_t vertex_count(const std::vector<Region>& regions) {
  std::size_t count = 0;
  for (const Region& region : regions) {
    count += region.outer.size();
    for (const Ring& hole : region.holes) count += hole.size();
  }
  return count;
}

// region_of: each piece's region (see CookedPiece::region), if not all the first's.
std::vector<CookedPiece> to_cooked(std::vector<Piece> pieces,
                                   const std::vector<std::uint32_t>* region_of = nullptr) {
  std::vector<CookedPiece> cooked;
  cooked.reserve(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    Piece& piece = pieces[k];
    cooked.push_back({std::move(piece.component), std::move(piece.hull), piece.concavity,
                      region_of ? (*region_of)[k] : 0u});
  }
  return cooked;
}

// The decomposition of every region of one asset, and the levels read off its
// trees.
class AssetDecomposer {
 public:
  AssetDecomposer(const std::vector<Region>& regions, const DecomposeSettings& settings,
                  unsigned threads)
      : settings_(settings), threads_(threads) {
    trees_.resize(regions.size());
    parallel_for(regions.size(), threads,
                 [&](std::size_t r, unsigned) { trees_[r] = decompose(regions[r], settings); });
  }

  // The pieces at tau, region after region; region_of gets the region of each.
  std::vector<Piece> pieces_at(double tau, std::vector<std::uint32_t>& region_of) const {
    return joined([&](std::size_t r) { return trees_[r].pieces_at(tau); }, region_of,
                  piece_count_at(tau));
  }

  // The same, for the last level read: the pieces' components are moved out of the trees.
  std::vector<Piece> take_pieces_at(double tau, std::vector<std::uint32_t>& region_of) {
    // Each tree is freed on the thread that read it, not all of them on the caller after.
    std::vector<Piece> pieces = joined(
        [&](std::size_t r) {
          DecompositionTree tree = std::move(trees_[r]);
          return std::move(tree).pieces_at(tau);
        },
        region_of, piece_count_at(tau));
    trees_.clear();
    return pieces;
  }

  std::size_t piece_count_at(double tau) const {
    std::size_t count = 0;
    for (const DecompositionTree& tree : trees_) count += tree.piece_count_at(tau);
    return count;
  }

  // The smallest tolerance >= tau whose decomposition has at most max_pieces pieces over all
  // regions: the decomposition only changes at the trees' node concavities, so those are the
  // candidates. Falls back to the coarsest level (one piece per region) when none fits.
  double tau_for_budget(double tau, std::size_t max_pieces) const {
    std::vector<double> candidates{tau};
    for (const DecompositionTree& tree : trees_) {
      for (double level : tree.level_taus()) {
        if (level > tau) candidates.push_back(level);
      }
    }
    std::sort(candidates.begin(), candidates.end());
    // The count does not grow with the tolerance: a binary search (a scan took minutes on an
    // image of thousands of blobs at tau 0, where every one of its nodes is a candidate).
    const auto fitting = std::partition_point(
        candidates.begin(), candidates.end(),
        [&](double candidate) { return piece_count_at(candidate) > max_pieces; });
    return fitting == candidates.end() ? candidates.back() : *fitting;
  }

 private:
  // The pieces read off each tree (on the threads), in the trees' order, and their regions;
  // `expected` of them.
  template <typename Read>
  std::vector<Piece> joined(const Read& read, std::vector<std::uint32_t>& region_of,
                            std::size_t expected) const {
    std::vector<std::size_t> counts(trees_.size());
    std::vector<Piece> joined = parallel_join<Piece>(
        trees_.size(), threads_,
        [&](std::size_t r, unsigned, std::vector<Piece>& out) {
          std::vector<Piece> pieces = read(r);
          counts[r] = pieces.size();
          std::move(pieces.begin(), pieces.end(), std::back_inserter(out));
        },
        kItemsWorthAThread, expected);
    region_of.clear();
    region_of.reserve(joined.size());
    for (std::size_t r = 0; r < counts.size(); ++r) {
      region_of.insert(region_of.end(), counts[r], static_cast<std::uint32_t>(r));
    }
    return joined;
  }

  DecomposeSettings settings_;
  unsigned threads_;
  std::vector<DecompositionTree> trees_;
};

struct PreparedInput {
  std::vector<Region> regions;  // [input units], as read or traced
  Transform transform;
  int width = 0, height = 0;
  std::size_t traced_vertices = 0;
  double enclosing_radius = 0;  // [input units]
  std::vector<std::string> warnings;
  double decode_ms = 0;
  double trace_ms = 0;
};

// The simplification bound: a quarter of τ (the rest of the budget is the
// decomposition's), and never more than a pixel, so that outlines stay
// recognisable at large τ.
double default_simplify(double tau_px) { return std::clamp(tau_px / 4, 0.05, 1.0); }

// Normalised image coordinates of the output origin: a sheet's frame's own, else --pivot.
Vec2 pivot_of(const InputFile& file, const Settings& settings) {
  if (file.frames && file.frames->frames[file.frame].pivot) {
    return *file.frames->frames[file.frame].pivot;
  }
  return Vec2{settings.pivot_u, settings.pivot_v};
}

// threads: how many may trace this one image.
PreparedInput prepare_image(const InputFile& file, const Settings& settings, unsigned threads) {
  auto start = Clock::now();
  PreparedInput prepared;
  AlphaImage image = file.frames  ? frame_image(*file.sheet, file.frames->frames[file.frame])
                     : file.sheet ? crop(*file.sheet, file.cell)
                                  : load_alpha(file.path, trace_settings(settings, 0));
  prepared.decode_ms = file.sheet ? file.decode_ms : milliseconds_since(start);
  start = Clock::now();
  prepared.width = image.width;
  prepared.height = image.height;
  if (settings.bundle_output) {
    check_bundle_image_size(file.name, std::filesystem::path(file.path).generic_string(),
                            image.width, image.height);
  }
  double simplify = settings.simplify.value_or(0);
  if (!settings.simplify) {
    if (settings.tau.relative) {
      // τ depends on the outline's radius: measure it on a finely simplified
      // trace first.
      TraceSettings fine_settings = trace_settings(settings, 0.05);
      fine_settings.threads = threads;
      TraceResult fine = trace_alpha(image, fine_settings);
      double radius = fine.regions.empty() ? 0 : enclosing_radius(fine.regions);
      simplify = default_simplify(settings.tau.resolve(radius));
    } else {
      simplify = default_simplify(settings.tau.value);
    }
  }
  // A tile's outline is put onto its cell's border before it is simplified: simplified first,
  // a corner that the tracing cut by half a pixel kept the cut's point on the border and lost the
  // one beside it, which snapping would have moved there, so that a half tile's top met the
  // border 0.5 px lower on one side than on the other (a step at the seam with its neighbour).
  const bool grid_cell = file.sheet && !file.frames;
  const bool tile = grid_cell && settings.grid && settings.grid->tile_snap;
  TraceSettings tracing = trace_settings(settings, tile ? 0.0 : simplify);
  // As traced, collinear points too: a corner's half-pixel cut on a 2:1 slope's line was dropped
  // with them, and the slope met its cell's border half a pixel above its neighbour's.
  tracing.keep_collinear = tile;
  tracing.threads = threads;
  TraceResult traced = trace_alpha(image, tracing);
  prepared.regions = std::move(traced.regions);
  prepared.traced_vertices = traced.traced_vertices;
  prepared.warnings = std::move(traced.warnings);
  if (tile) {
    // Points on the border stay: simplified away, a corner where the outline leaves the border
    // at a shallow angle (a 45° slope's foot) left the border uncovered there.
    const double width = image.width, height = image.height;
    const std::function<bool(Vec2)> on_border = [width, height](Vec2 p) {
      return p.x == 0 || p.x == width || p.y == 0 || p.y == height;
    };
    prepared.regions =
        simplify_regions(snap_to_cell(prepared.regions, image.width, image.height,
                                      *settings.grid->tile_snap, file.name, prepared.warnings),
                         simplify, threads, on_border);
  }
  double scale = 1.0 / settings.pixels_per_unit;
  const Vec2 pivot = pivot_of(file, settings);
  prepared.transform =
      Transform{scale, Vec2{pivot.x * image.width, pivot.y * image.height}, !settings.y_down};
  prepared.trace_ms = milliseconds_since(start);
  return prepared;
}

SpriteCutout cutout_of(const InputFile& file, int width, int height, const Settings& settings) {
  if (is_poly_file(file.path)) return {};
  if (file.frames) {
    const SheetFrame& frame = file.frames->frames[file.frame];
    return {file.frames->image.generic_string(),
            frame.atlas.x,
            frame.atlas.y,
            frame.trimmed_width,
            frame.trimmed_height,
            frame.rotated,
            frame.offset_x,
            frame.offset_y,
            settings.color_key};
  }
  if (file.sheet) {
    return {file.path, file.cell.x, file.cell.y, width, height, false, 0, 0, settings.color_key};
  }
  return {file.path, 0, 0, width, height, false, 0, 0, settings.color_key};
}

PreparedInput prepare_polygons(const InputFile& file, const Settings& settings) {
  PreparedInput prepared;
  prepared.regions = read_poly_file(file.path);
  prepared.traced_vertices = vertex_count(prepared.regions);
  prepared.transform = Transform{1.0 / settings.pixels_per_unit, Vec2{0, 0}, false};
  return prepared;
}

// Physics properties for one asset: the command line's, overridden field by field by a sidecar
// file NAME.physics.json beside the input, e.g. {"density": 2, "sensor": true}.
std::optional<PhysicsProperties> physics_for(const std::filesystem::path& input,
                                             const Settings& settings,
                                             const AssetSettings& asset_settings) {
  const std::filesystem::path sidecar = physics_sidecar(input);
  if (!asset_settings.exists(sidecar)) return settings.physics;
  PhysicsProperties physics = settings.physics.value_or(PhysicsProperties{});
  const nlohmann::json json = read_json_object(sidecar, "physics properties");
  apply_physics_json(physics, json, sidecar.string());
  return physics;
}

// Areas and squared lengths of coordinates beyond this overflow or lose all precision (a 1e300
// polygon cooked to a NaN area and no hull), and no output format stores them.
constexpr double kLargestOutputCoordinate = 1e15;

void refuse_huge_coordinates(const std::vector<Region>& regions, const std::string& source) {
  double largest = 0.0;
  for (const Region& region : regions) {
    auto visit = [&](const Ring& ring) {
      for (Vec2 p : ring) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    };
    visit(region.outer);
    for (const Ring& hole : region.holes) visit(hole);
  }
  if (largest > kLargestOutputCoordinate) {
    std::ostringstream message;
    // All its digits: at 6, 1e15 + 1e7 read "1e+15 ... at most 1e15" (stop 55's sweep).
    message << source << ": a coordinate of " << std::setprecision(17) << largest
            << " output units is too large (at most 1e15; scale the input or raise --ppu)";
    throw InputError(message.str());
  }
}

// What the writers' rounding may take from a distance between two hull vertices or from a turn's
// height (EngineLimits::rounding, formats/SPEC.md §9) [output units], for a weld [output units]
// (0: none), the regions in output units and the levels' τ, finest first; and how it depends on
// the weld (EngineLimits::rounding_steps).
// - Where the bundle's grid is finer than the weld (its step at the least error bound the writer
//   may choose, 1 % of τ or 1/64 px), twice its error bound E, for the largest hull the asset may
//   have (its largest region's box grown by the coarsest τ: the writer's E is the largest hull's;
//   for --meshopt, whose grid spans the whole asset, the box of all its regions grown so); a grid
//   as coarse as the weld keeps distinct vertices a weld apart.
// - Where floats at the asset's farthest coordinate are finer than the weld, twice their spacing;
//   floats as coarse as the weld keep distinct vertices apart as the grid does (a margin of their
//   size refused thin stress polygons 1e5 from the origin).
struct WritersRounding {
  double rounding = 0.0;
  EngineLimits::RoundingSteps steps;
};
WritersRounding writers_rounding(const std::vector<Region>& regions,
                                 const std::vector<double>& level_taus, double pixels_per_unit,
                                 double weld, bool meshopt) {
  if (!(weld > 0) || regions.empty()) return {};
  double largest_extent = 0.0, farthest = 0.0;
  Vec2 all_low{std::numeric_limits<double>::infinity()}, all_high = -all_low;
  for (const Region& region : regions) {
    Vec2 low{std::numeric_limits<double>::infinity()}, high = -low;
    for (const Vec2& p : region.outer) low = glm::min(low, p), high = glm::max(high, p);
    if (!(low.x <= high.x)) continue;
    largest_extent = std::max({largest_extent, high.x - low.x, high.y - low.y});
    farthest =
        std::max({farthest, std::abs(low.x), std::abs(low.y), std::abs(high.x), std::abs(high.y)});
    all_low = glm::min(all_low, low), all_high = glm::max(all_high, high);
  }
  // Stop 55's sweep: at --ppu 100 a --meshopt hull's vertex read back 0.000447 from its
  // neighbours' line, under weld/10, where the margin was the largest region's.
  if (meshopt && all_low.x <= all_high.x) {
    largest_extent = std::max(all_high.x - all_low.x, all_high.y - all_low.y);
  }
  const double grown = level_taus.back();
  const double least_bound = format::quantization_error_bound(level_taus.front(), pixels_per_unit);
  const double bound = format::quantization_error_bound(level_taus.front(), pixels_per_unit,
                                                        largest_extent + 2 * grown);
  const double spacing = format::float_spacing(farthest + grown);
  const EngineLimits::RoundingSteps steps{std::sqrt(2.0) * least_bound, 2 * bound, spacing,
                                          2 * spacing};
  return {steps.at(weld), steps};
}

// threads: how many may work on this one asset (its regions), when there are fewer
// assets than threads.
CookedAsset cook_one(const InputFile& file, const Settings& given, AssetSettings& asset_settings,
                     unsigned threads) {
  auto start = Clock::now();
  // A project file's rules and the image's sidecar may change its settings (asset_settings.h).
  const std::shared_ptr<const Settings> own =
      file.own_resolved ? file.own : asset_settings.for_input(file.path);
  const Settings& settings = own ? *own : given;
  PreparedInput input = is_poly_file(file.path) ? prepare_polygons(file, settings)
                                                : prepare_image(file, settings, threads);
  CookedAsset asset;
  asset.name = file.name;
  asset.source = std::filesystem::path(file.path).generic_string();
  asset.image_width = input.width;
  asset.image_height = input.height;
  asset.cutout = cutout_of(file, input.width, input.height, settings);
  asset.pixels_per_unit = settings.pixels_per_unit;
  asset.pivot = pivot_of(file, settings);
  asset.transform = input.transform;
  asset.measure = settings.measure;
  asset.physics = physics_for(file.path, settings, asset_settings);
  asset.tile = file.sheet && !file.frames && settings.grid && settings.grid->tile_snap;
  asset.part_of_source = file.sheet != nullptr;
  const std::string where = described(asset);
  asset.warnings = std::move(input.warnings);
  asset.stats.traced_vertices = input.traced_vertices;
  asset.stats.decode_ms = input.decode_ms;
  asset.stats.trace_ms = input.trace_ms;

  std::vector<Region> prepared = std::move(input.regions);
  for (Region& region : prepared) transform_in_place(region, input.transform);
  // A fully transparent image is a warning (from the tracer) and an empty asset, not an error.
  if (!prepared.empty()) {
    refuse_tiny_rings(prepared, where);
    prepared = clean_and_validate(std::move(prepared), where, threads);
  }
  refuse_huge_coordinates(prepared, where);
  refuse_sliver_regions(prepared, where, 1, threads);
  refuse_too_many_holes(prepared, where,
                        asset.image_width == 0 ? TracedFrom::polygons
                        : settings.color_key   ? TracedFrom::color_key
                                               : TracedFrom::alpha);
  // The asset keeps the outline; the cook reads it there (one copy of it, not two).
  asset.regions = std::move(prepared);
  const std::vector<Region>& regions = asset.regions;

  // Tolerances are given in input units (or relative to R); the output is in
  // output units.
  // The enclosing circle (a hull of every vertex) only when a tolerance is relative to it: it
  // was a fiftieth of a cook.
  std::optional<double> radius;
  double scale = input.transform.scale;
  auto resolve = [&](const Tolerance& tolerance) {
    if (!tolerance.relative) return tolerance.value * scale;
    if (!radius) radius = regions.empty() ? 0 : enclosing_radius(regions);
    return tolerance.value * *radius;
  };
  std::vector<double> level_taus{resolve(settings.tau)};
  for (const Tolerance& lod : settings.lods) level_taus.push_back(resolve(lod));
  std::sort(level_taus.begin(), level_taus.end());
  level_taus.erase(std::unique(level_taus.begin(), level_taus.end()), level_taus.end());

  DecomposeSettings decompose_settings;
  decompose_settings.tau = level_taus.front();
  decompose_settings.measure = *parse_measure(settings.measure);
  decompose_settings.sc = settings.sc;
  decompose_settings.sd = settings.sd;
  // The trees keep the outlines of the levels read, not of every node they split (see
  // DecomposeSettings::keep_coarser_levels).
  decompose_settings.keep_coarser_levels = false;
  decompose_settings.kept_levels.assign(level_taus.begin() + 1, level_taus.end());
  auto decompose_start = Clock::now();
  std::optional<AssetDecomposer> decomposer(std::in_place, regions, decompose_settings, threads);
  if (settings.max_pieces > 0) {
    double budget_tau = decomposer->tau_for_budget(level_taus.front(), settings.max_pieces);
    // Each region is one piece at least: a budget below their count cannot be kept, which the
    // user learns here rather than from the bundle.
    const std::size_t budget_pieces = decomposer->piece_count_at(budget_tau);
    if (budget_pieces > settings.max_pieces) {
      // A region can be more concave than it is large (a spiral's paths wind through its
      // pockets; Eq. 5 adds the depths of holes reached through others): said, or the figure
      // reads as a mistake. Above every region's size, it is so of the region that set it.
      double largest_diagonal = 0.0;
      for (const Region& region : regions) {
        Vec2 low = region.outer.front(), high = low;
        for (const Vec2& p : region.outer) low = glm::min(low, p), high = glm::max(high, p);
        largest_diagonal = std::max(largest_diagonal, glm::length(high - low));
      }
      asset.warnings.push_back(
          "--max-pieces " + std::to_string(settings.max_pieces) + " cannot be kept: its " +
          std::to_string(regions.size()) + " regions are one piece each at least, so it keeps " +
          std::to_string(budget_pieces) + " pieces (τ " + detail::number(budget_tau) +
          " output units, the coarsest level" +
          (budget_tau > largest_diagonal
               ? ": more than a region's size, as concavity is measured along paths that wind "
                 "through a region's pockets, and a hole's (the paper's Eq. 5) adds the depths "
                 "of holes reached through other holes"
               : "") +
          ")");
    }
    if (budget_tau > level_taus.front()) {
      // Said once for the cook (print_warnings): with --lod, most assets of a folder may drop
      // some.
      asset.lods_left_out = static_cast<std::size_t>(std::count_if(
          level_taus.begin() + 1, level_taus.end(), [&](double t) { return t < budget_tau; }));
      std::erase_if(level_taus, [&](double t) { return t < budget_tau; });
      if (level_taus.empty() || level_taus.front() != budget_tau) {
        level_taus.insert(level_taus.begin(), budget_tau);
      }
      // The budget's level is known only from the trees: they are built again (the same cuts)
      // keeping it, which costs a second decomposition where keeping every level cost memory
      // quadratic in the outline (a comb) or in the holes.
      decompose_settings.kept_levels = level_taus;
      decomposer.emplace(regions, decompose_settings, threads);
    }
  }
  asset.tau = level_taus.front();

  EngineLimits limits{settings.max_verts, settings.weld.value_or(kDefaultWeld)};
  const WritersRounding rounding =
      writers_rounding(regions, level_taus, asset.pixels_per_unit, limits.weld, settings.meshopt);
  limits.rounding = rounding.rounding;
  limits.rounding_steps = rounding.steps;
  if (asset.tile) {
    const Vec2 a = asset.transform.apply({0.0, 0.0});
    const Vec2 b = asset.transform.apply({double(input.width), double(input.height)});
    limits.keep_inside = EngineLimits::Box{{std::min(a.x, b.x), std::min(a.y, b.y)},
                                           {std::max(a.x, b.x), std::max(a.y, b.y)}};
  }
  // A hull thinner than the bundle's quantization bound rounds to a segment on its grid (and is
  // no shape an engine can use): it is merged into a neighbour where one can take it.
  const double merge_width =
      format::quantization_error_bound(level_taus.front(), asset.pixels_per_unit);
  auto split = [&](const Region& component, double tau) {
    DecomposeSettings finer = decompose_settings;
    finer.tau = tau;
    finer.kept_levels.clear();
    return to_cooked(decompose(component, finer).pieces_at(tau));
  };
  // Every level is checked before the asset is returned, so that a broken one stops the cook
  // before anything is written.
  // Every level's pieces are read off the trees, which are then freed: the engine limits and the
  // contract check, where a cook's memory peaks, never need them (a third of that peak on a sheet
  // of thousands of blobs).
  std::vector<std::vector<Piece>> level_pieces;
  std::vector<std::vector<std::uint32_t>> level_regions(level_taus.size());
  level_pieces.reserve(level_taus.size());
  for (std::size_t l = 0; l < level_taus.size(); ++l) {
    level_pieces.push_back(l + 1 < level_taus.size()
                               ? decomposer->pieces_at(level_taus[l], level_regions[l])
                               : decomposer->take_pieces_at(level_taus[l], level_regions[l]));
  }
  decomposer.reset();
  asset.stats.decompose_ms = milliseconds_since(decompose_start);
  std::vector<std::string> violations;
  for (std::size_t l = 0; l < level_taus.size(); ++l) {
    const double tau = level_taus[l];
    std::vector<Piece> pieces = std::move(level_pieces[l]);
    CookedLevel level{tau, {}};
    if (asset.levels.empty()) {
      asset.stats.pieces = pieces.size();
      asset.stats.convexity = convexity(pieces);
      for (const Piece& piece : pieces) {
        asset.stats.max_concavity = std::max(asset.stats.max_concavity, piece.concavity);
      }
    }
    auto limits_start = Clock::now();
    std::vector<CookedPiece> constrained =
        apply_engine_limits(to_cooked(std::move(pieces), &level_regions[l]), tau, limits, split,
                            where, threads, merge_width, true, settings.merge_pieces);
    asset.stats.limits_ms += milliseconds_since(limits_start);
    auto contract_start = Clock::now();
    const ContractTerms terms{tau, decompose_settings.measure, limits};
    for (std::string& violation : find_contract_violations(constrained, regions, terms, threads)) {
      if (level_taus.size() == 1) {
        violations.push_back(std::move(violation));
      } else {
        std::ostringstream level_name;
        level_name << "the level at τ " << tau << ": " << violation;
        violations.push_back(level_name.str());
      }
    }
    asset.stats.contract_ms += milliseconds_since(contract_start);
    for (const CookedPiece& piece : constrained) level.hulls.push_back(piece.hull);
    if (asset.levels.empty()) asset.pieces = std::move(constrained);
    asset.levels.push_back(std::move(level));
  }
  enforce_contract(where, violations);
  asset.stats.hulls = asset.levels.empty() ? 0 : asset.levels.front().hulls.size();
  // The tracer said why (transparent, faint or specks only): this only says what follows.
  if (regions.empty()) asset.warnings.push_back("no region: the asset has no hulls");
  asset.stats.total_ms = milliseconds_since(start);
  return asset;
}

// A grid's empty cells are no assets. A sheet whose every cell is empty is refused when no input
// gave an asset, as a directory without images is (a wrong --grid or --alpha, most likely), and
// is a warning among sheets that did: a folder of tilesets may hold an overlay left transparent
// (Wesnoth's terrain grid.png), which is no reason to stop its cook. Opaque pixels beyond the
// last whole cell are in no asset: a warning says where, or the refusal does.
void drop_empty_cells(const std::vector<InputFile>& files, const Settings& settings,
                      CookResult& result) {
  std::vector<CookedAsset> kept;
  std::vector<std::size_t> kept_index;
  struct SheetCells {
    bool has_cells = false;
    const InputFile* first = nullptr;
  };
  std::map<std::string, SheetCells> sheets;
  for (std::size_t i = 0; i < files.size(); ++i) {
    // By its hulls: the regions may be freed already (Settings::keep_outlines).
    const CookedAsset& asset = result.assets[i];
    const bool cell = files[i].sheet && !files[i].frames;  // a sheet JSON's frames are kept
    const bool empty_cell = cell && asset.stats.hulls == 0;
    if (cell) {
      SheetCells& sheet = sheets[files[i].path];
      sheet.has_cells |= !empty_cell;
      if (!sheet.first) sheet.first = &files[i];
    }
    if (!empty_cell) {
      kept.push_back(std::move(result.assets[i]));
      kept_index.push_back(result.cooked_index[i]);
    }
  }
  for (const auto& [path, sheet] : sheets) {
    const InputFile& file = *sheet.first;
    const int alpha = (file.own ? *file.own : settings).alpha;
    const UncoveredPixels uncovered = uncovered_pixels(*file.sheet, *settings.grid, alpha);
    const std::string beyond =
        uncovered.opaque == 0 ? "" : describe_uncovered(uncovered, *file.sheet, *settings.grid);
    if (sheet.has_cells) {
      if (!beyond.empty())
        result.warnings.push_back(path + ": " + beyond + ": they are in no asset");
      continue;
    }
    const std::string problem = path +
                                ": every cell of the grid is empty or holds only specks (--grid, "
                                "--alpha, --min-blob-area)" +
                                (beyond.empty() ? "" : "; " + beyond);
    if (kept.empty()) throw InputError(problem);
    result.warnings.push_back(problem + ": the sheet gives no asset");
  }
  result.assets = std::move(kept);
  result.cooked_index = std::move(kept_index);
}

}  // namespace

// Holes are resolved one at a time, each on the component holding the rest: time grows with the
// holes times the vertices (each resolution measures that component again). A noisy alpha channel
// traces to thousands of pin holes (a 448 px square of 50 % noise, 3,613 holes among 82,425
// vertices: 233 s and 1.6 GB when the tree kept every component, 11 s and 80 MB since), so such a
// region is refused before it is decomposed, saying what to change. Near the bound, noise takes
// about 3 s (2,067 holes among 27,896 vertices: 3.5 s, 30 MB), and a 256 px grate of 3 px holes
// (1,681 among 14,118) 0.28 s; the bound was 1e7 while the tree kept every component.
constexpr double kMaxHolesTimesVertices = 5e7;

void refuse_too_many_holes(const std::vector<Region>& regions, const std::string& source,
                           TracedFrom traced) {
  for (std::size_t r = 0; r < regions.size(); ++r) {
    std::size_t vertices = regions[r].outer.size();
    for (const Ring& hole : regions[r].holes) vertices += hole.size();
    const std::size_t holes = regions[r].holes.size();
    if (static_cast<double>(holes) * static_cast<double>(vertices) <= kMaxHolesTimesVertices) {
      continue;
    }
    throw InputError(source + ": region " + std::to_string(r + 1) + " has " +
                     std::to_string(holes) + " holes among " + std::to_string(vertices) +
                     " vertices, too many to decompose (holes x vertices must be at most 5e7)" +
                     (traced == TracedFrom::alpha
                          ? "; is the alpha channel noisy? Raise --min-hole-area (smaller holes "
                            "are filled) or --alpha"
                      : traced == TracedFrom::color_key
                          ? "; do many specks of the image have the colour key? Raise "
                            "--min-hole-area (smaller holes are filled), or give another key"
                          : ""));
  }
}

std::filesystem::path physics_sidecar(const std::filesystem::path& input) {
  std::filesystem::path sidecar = input;
  sidecar.replace_extension(".physics.json");
  return sidecar;
}

CookResult cook(const std::vector<std::filesystem::path>& inputs, const Settings& settings,
                const AssetCooked& on_cooked) {
  if (!parse_measure(settings.measure)) {
    throw UsageError("--measure: '" + settings.measure + "' is not one of sl, sp, h1, h2");
  }
  if (!stores_as_positive_float(settings.pixels_per_unit)) {
    throw UsageError("--ppu must be positive and within the range of a 32-bit float");
  }
  AssetSettings asset_settings(settings);
  CookResult result;
  auto listed = std::make_shared<ListedFiles>();
  asset_settings.use_listing(listed);
  result.listed = listed;
  std::vector<InputFile> files =
      collect_inputs(inputs, settings, asset_settings, *listed, result.skipped);
  std::sort(result.skipped.begin(), result.skipped.end());
  for (const InputFile& file : files) {
    if (file.frames &&
        (result.sheet_images.empty() || result.sheet_images.back() != file.frames->image)) {
      result.sheet_images.push_back(file.frames->image);
    }
  }
  // Every asset would pay its page faults again otherwise (a tenth of a cook): see there.
  keep_freed_memory();
  result.assets.resize(files.size());
  result.cooked_index.resize(files.size());
  std::iota(result.cooked_index.begin(), result.cooked_index.end(), std::size_t{0});

  // Assets are independent: cook them on a pool of threads, each into its own
  // slot, so the result never depends on the thread count. The first error (in
  // input order) wins.
  const unsigned all_threads =
      std::max(1u, settings.threads ? settings.threads : std::thread::hardware_concurrency());
  const unsigned threads =
      std::clamp<unsigned>(all_threads, 1, std::max<std::size_t>(files.size(), 1));
  std::vector<std::exception_ptr> errors(files.size());
  // The largest files first (their size stands for their work), so that a large asset does not
  // start last and leave the other threads idle.
  std::vector<std::size_t> order(files.size());
  std::vector<std::uintmax_t> sizes(files.size(), 0);
  for (std::size_t i = 0; i < files.size(); ++i) {
    order[i] = i;
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(files[i].path, error);
    if (!error) sizes[i] = size;
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
  // One huge image or sheet alone: its threads split its regions instead.
  const unsigned per_asset = files.size() == 1 ? all_threads : 1;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k = next++; k < files.size(); k = next++) {
      const std::size_t i = order[k];
      try {
        result.assets[i] = cook_one(files[i], settings, asset_settings, per_asset);
        if (on_cooked) on_cooked(i, files.size(), result.assets[i]);
        if (!settings.keep_hulls) {
          for (CookedLevel& level : result.assets[i].levels) std::vector<Ring>().swap(level.hulls);
        }
        if (!settings.keep_outlines) {
          // Checked already: only the hulls go on to the writers.
          std::vector<Region>().swap(result.assets[i].regions);
          std::vector<CookedPiece>().swap(result.assets[i].pieces);
          std::string().swap(result.assets[i].cutout.image);  // a third copy of the source path
        }
      } catch (const std::logic_error& e) {
        // A broken invariant (the decomposer found no cut, say) is ours: named like a contract
        // violation, with the asset. Naming it allocates: out of memory, the error is that.
        try {
          errors[i] = std::make_exception_ptr(
              ContractError(files[i].path + ": internal error: " + e.what()));
        } catch (...) {
          errors[i] = std::current_exception();
        }
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  // Threads of their own, not the process's pool: each asset's stages run parallel_for on it.
  run_on_new_threads(threads - 1, [&](unsigned) { work(); });
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  if (settings.grid) drop_empty_cells(files, settings, result);
  return result;
}

}  // namespace hullcook
