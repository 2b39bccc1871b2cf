// bench_decompose's table A: our decomposer against the ACD authors' own implementation
// (github jmlien/acd2d) at the paper's τ, either measured in the same run (interleaved with
// acd2d_driver, which scripts/bench --acd2d builds) or from issue 22's static figures.
#pragma once

#include "hullcook/core/decompose.h"
#include "paper_models.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace hullcook::bench {

// τ = fraction × the paper's R, the models and measures the authors' code is compared at.
struct ComparisonRow {
  const Model* model;
  double fraction;
  Measure measure;
  double tau() const { return fraction * model->paper_radius; }
};
const std::vector<ComparisonRow>& comparison_rows();

// One row measured in the same run, both sides the median over rounds of each round's median.
struct PairedRow {
  std::size_t their_fewest = 0, their_most = 0;  // their pieces over all repetitions
  double their_ms = 0, our_ms = 0;
  double speedup = 0;  // median over rounds of their round's median / ours
  int their_repetitions = 0;
};

struct PairedComparison {
  std::vector<PairedRow> rows;  // as comparison_rows()
  int rounds = 0, our_repetitions = 0;
  std::string load_before, load_after;  // /proc/loadavg's 1, 5 and 15 minute figures
};

// Starts driver (acd2d_driver) and times both implementations row by row, round after round,
// who goes first alternating. Throws std::runtime_error if the driver fails.
PairedComparison run_paired_comparison(const std::filesystem::path& driver, int rounds,
                                       int repetitions);

// The first three fields of /proc/loadavg ("?" where there is none).
std::string load_average();

// Table A in markdown: the paired figures when given, otherwise issue 22's static ones against
// our_static_ms (this run's medians, not paired).
void comparison_table(
    std::ostream& md, const std::optional<PairedComparison>& paired,
    const std::function<std::optional<double>(const ComparisonRow&)>& our_static_ms);

}  // namespace hullcook::bench
