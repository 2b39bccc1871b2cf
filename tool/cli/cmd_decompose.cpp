// hullcook decompose: the ACD of one .poly file, its one-line summary and the debug JSON.
#include "commands.h"
#include "cook_options.h"
#include "counted.h"

#include "hullcook/cook/contract.h"
#include "hullcook/cook/cook.h"
#include "hullcook/cook/debug_json.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/cook/process_heap.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

namespace hullcook::cli {
namespace {

struct DecomposeOptions {
  std::string input;
  std::string tau = "0";
  std::string measure = "h1";
  double sc = 0.1;
  double sd = 1.0;
  std::size_t max_pieces = 0;
  std::string json;
};

int run_decompose(const DecomposeOptions& options) {
  const Tolerance tolerance = Tolerance::parse(options.tau);
  const std::optional<Measure> measure = parse_measure(options.measure);
  if (!measure) {
    throw UsageError("--measure: '" + options.measure + "' is not one of sl, sp, h1, h2");
  }
  if (!options.json.empty()) check_not_an_input(options.json, {options.input});
  // Before the first allocation of the work, so that the decomposition's fresh memory is the
  // prepared heap (the first decomposition in a process would otherwise pay its page faults).
  prepare_process_heap();
  const std::vector<Region> regions = read_poly_file(options.input);
  refuse_too_many_holes(regions, options.input, TracedFrom::polygons);
  // Each region's pieces are checked against that region alone (below).
  for (std::size_t r = 0; r < regions.size(); ++r) {
    refuse_sliver_regions({regions[r]}, options.input, r + 1);
  }
  const double tau = tolerance.resolve(enclosing_radius(regions));
  const DecomposeSettings settings{tau, *measure, options.sc, options.sd, false};

  const auto start = std::chrono::steady_clock::now();
  std::vector<Piece> pieces;
  std::vector<std::size_t> first_piece;  // per region, its first piece
  std::vector<double> level_tau;         // per region, the τ its pieces were cut at
  for (const Region& region : regions) {
    DecompositionTree tree;
    try {
      tree = decompose(region, settings);
    } catch (const std::logic_error& e) {
      throw ContractError(options.input + ": internal error: " + e.what());
    }
    level_tau.push_back(options.max_pieces ? tree.tau_within(options.max_pieces) : tau);
    // The budget's level is known only from the tree: it is built again (the same cuts) keeping
    // that level's outlines, rather than keeping every node's.
    if (level_tau.back() > tau) {
      DecomposeSettings keeping = settings;
      keeping.kept_levels = {level_tau.back()};
      try {
        tree = decompose(region, keeping);
      } catch (const std::logic_error& e) {
        throw ContractError(options.input + ": internal error: " + e.what());
      }
    }
    std::vector<Piece> part = tree.pieces_at(level_tau.back());
    first_piece.push_back(pieces.size());
    for (Piece& piece : part) pieces.push_back(std::move(piece));
  }
  first_piece.push_back(pieces.size());
  const double milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  CookedAsset asset;
  asset.name = std::filesystem::path(options.input).filename().string();
  asset.source = options.input;
  asset.tau = tau;
  asset.measure = measure_name(*measure);
  asset.regions = regions;
  for (const Piece& piece : pieces) {
    asset.pieces.push_back({piece.component, piece.hull, piece.concavity});
  }
  asset.levels.push_back({tau, {}});
  for (const Piece& piece : pieces) asset.levels[0].hulls.push_back(piece.hull);
  asset.stats.pieces = pieces.size();
  asset.stats.max_concavity = max_concavity(pieces);
  asset.stats.convexity = convexity(pieces);
  asset.stats.decompose_ms = milliseconds;
  asset.stats.total_ms = milliseconds;

  // Each region's pieces against that region, at the τ of their level.
  const auto contract_start = std::chrono::steady_clock::now();
  std::vector<std::string> violations;
  std::exception_ptr refusal;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const std::vector<CookedPiece> region_pieces(
        asset.pieces.begin() + std::ptrdiff_t(first_piece[r]),
        asset.pieces.begin() + std::ptrdiff_t(first_piece[r + 1]));
    // A sliver that only a cut resolving a notch left is bad input at that τ, as the cook
    // refuses it (stop 57: a near-duplicate vertex 1e-9 along an edge, at --tau 0, exited 4);
    // after every region's check, so that a real violation elsewhere is still told as one.
    try {
      refuse_sliver_pieces(region_pieces, {regions[r]}, level_tau[r], options.input);
    } catch (const InputError&) {
      if (!refusal) refusal = std::current_exception();
      continue;
    }
    const ContractTerms terms{level_tau[r], *measure, EngineLimits{0, 0.0}};
    for (const std::string& violation :
         find_contract_violations(region_pieces, {regions[r]}, terms)) {
      violations.push_back(
          regions.size() == 1 ? violation : "region " + std::to_string(r + 1) + ": " + violation);
    }
  }
  asset.stats.contract_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - contract_start)
          .count();
  enforce_contract(options.input, violations);
  if (refusal) std::rethrow_exception(refusal);

  if (!options.json.empty()) write_file_atomically(options.json, debug_json({asset}));
  std::printf("%s: %s, max concavity %.6g, convexity %.6f, %.3f ms (tau %.6g, %s)\n",
              options.input.c_str(), counted(pieces.size(), "piece", "pieces").c_str(),
              asset.stats.max_concavity, asset.stats.convexity, milliseconds, tau,
              asset.measure.c_str());
  return 0;
}

void add_decompose(CLI::App& root, CommandAction& action) {
  auto options = std::make_shared<DecomposeOptions>();
  CLI::App* command = root.add_subcommand(
      "decompose", "Approximate convex decomposition of a .poly file (debug JSON and summary)");
  command->add_option("input", options->input, "Input .poly file")->required();
  command
      ->add_option("--tau", options->tau,
                   "Concavity tolerance: input units (0.5) or percent of the minimum "
                   "enclosing circle's radius (1%); 0 = exact convex decomposition")
      ->required();
  command->add_option("--measure", options->measure, "Concavity measure: sl, sp, h1 or h2")
      ->capture_default_str();
  command->add_option("--sc", options->sc, "Eq. 8 weight of the concavity at the cut's far end")
      ->check(number_in(0, 1e9, "a weight in [0, 1e9]"))
      ->capture_default_str();
  command->add_option("--sd", options->sd, "Eq. 8 weight of the cut's length")
      ->check(number_in(1e-9, 1e9, "a weight in [1e-9, 1e9]"))
      ->capture_default_str();
  command
      ->add_option("--max-pieces", options->max_pieces,
                   "Shape budget: the finest level with at most this many pieces per region")
      ->check(number_in(0, 1e9, "a count of pieces (0 = no budget)"));
  command->add_option("--json", options->json, "Write the debug JSON here");
  command->callback([options, &action] { action = [options] { return run_decompose(*options); }; });
}

const CommandRegistration registered{30, "decompose", add_decompose};

}  // namespace
}  // namespace hullcook::cli
