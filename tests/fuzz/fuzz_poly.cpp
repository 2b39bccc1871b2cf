// libFuzzer target: .poly text through the reader and clean-up, then the decomposer under every
// measure at a small τ, with the output contract that `hullcook decompose` enforces checked on
// every accepted input. Refusing the text (InputError) is fine; a crash, an internal error
// (std::logic_error from the decomposer) or a contract violation is a finding.
#include "fuzz_check.h"
#include "fuzz_limits.h"

#include "hullcook/cook/contract.h"
#include "hullcook/cook/cook.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

using namespace hullcook;

// A small τ: 1 % of the minimum enclosing circle's radius, as `--tau 1%` gives.
constexpr double kRelativeTau = 0.01;

void check_region(const Region& region, Measure measure, double tau) {
  DecompositionTree tree;
  try {
    tree = decompose(region, {tau, measure, 0.1, 1.0});
  } catch (const std::logic_error& e) {
    std::fprintf(stderr, "decompose (%s, tau %.17g): internal error: %s\n", measure_name(measure),
                 tau, e.what());
    std::abort();
  }
  std::vector<CookedPiece> pieces;
  for (Piece& piece : tree.pieces_at(tau)) {
    pieces.push_back({std::move(piece.component), std::move(piece.hull), piece.concavity});
  }
  const std::vector<std::string> violations =
      find_contract_violations(pieces, {region}, {tau, measure, EngineLimits{0, 0.0}});
  if (!violations.empty()) {
    std::fprintf(stderr, "decompose (%s, tau %.17g) breaks the contract: %s (and %zu more)\n",
                 measure_name(measure), tau, violations.front().c_str(), violations.size() - 1);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<Region> regions;
  try {
    // As read_poly_file reads a file.
    regions = parse_poly(text, "fuzz.poly");
    refuse_tiny_rings(regions, "fuzz.poly");
    regions = clean_and_validate(std::move(regions), "fuzz.poly");
    refuse_too_many_holes(regions, "fuzz.poly", TracedFrom::polygons);
    for (std::size_t r = 0; r < regions.size(); ++r) {
      refuse_sliver_regions({regions[r]}, "fuzz.poly", r + 1);
    }
  } catch (const InputError&) {
    return 0;
  }
  if (fuzz::vertex_count(regions) > fuzz::kMaxPolyVertices) return 0;
  const double tau = kRelativeTau * enclosing_radius(regions);
  for (const Region& region : regions) {
    for (Measure measure : {Measure::sl, Measure::sp, Measure::h1, Measure::h2}) {
      check_region(region, measure, tau);
    }
  }
  return 0;
}
