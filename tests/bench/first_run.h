// bench_decompose's table D: the first decomposition in a fresh process against the same
// decomposition warm (issue 22: within 1.5×), interleaved round after round. Two fresh processes
// a round: `hullcook decompose`, whose printed (wall) time is what a user sees, and this
// benchmark itself in its --first-decomposition mode, which prepares the heap as the command does
// and times the same work in CPU time, which load disturbs far less.
#pragma once

#include "hullcook/core/decompose.h"
#include "paper_models.h"

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace hullcook::bench {

struct FirstRunRow {
  const Model* model;
  Measure measure;
  double tau;
  // Medians over the rounds: of the fresh processes' times, of each round's warm median, and of
  // each round's first / warm.
  double cli_first_ms = 0, warm_wall_ms = 0, cli_ratio = 0;
  double fresh_cpu_ms = 0, warm_cpu_ms = 0, cpu_ratio = 0;
};

struct FirstRunComparison {
  std::vector<FirstRunRow> rows;
  int rounds = 0, repetitions = 0;
  std::string load_before, load_after;
};

// Runs hullcook and self (this executable) once per row and round; throws std::runtime_error if
// either fails or prints no time.
FirstRunComparison run_first_run_comparison(const std::filesystem::path& hullcook,
                                            const std::filesystem::path& self, int rounds,
                                            int repetitions);

// The --first-decomposition mode: in this fresh process, prepares the heap as `hullcook
// decompose` does, then prints the thread CPU time [ms] of the model's first decomposition and
// its pieces at tau.
int print_first_decomposition(const std::string& model, const std::string& tau,
                              const std::string& measure);

// The table in markdown, or a line saying how to get it.
void first_run_table(std::ostream& md, const std::optional<FirstRunComparison>& comparison);

}  // namespace hullcook::bench
