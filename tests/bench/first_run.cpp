#include "first_run.h"

#include "authors_comparison.h"
#include "bench_support.h"
#include "child_process.h"
#include "hullcook/cook/process_heap.h"

#include <chrono>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hullcook::bench {
namespace {

constexpr double kFraction = 0.01;  // of the paper's R
constexpr const char* kModels[] = {"monkey", "monkey_2", "heron", "neuron"};
constexpr Measure kRowMeasures[] = {Measure::sl, Measure::sp, Measure::h1};
constexpr double kTarget = 1.5;

std::string exact(double value) {
  std::ostringstream out;
  out << std::setprecision(17) << value;
  return out.str();
}

// The milliseconds of "..., 1.234 ms (tau ...": what `hullcook decompose` printed.
double printed_ms(const std::string& output) {
  const std::size_t unit = output.find(" ms (tau ");
  const std::size_t start = unit == std::string::npos ? unit : output.rfind(' ', unit - 1);
  if (start == std::string::npos)
    throw std::runtime_error("hullcook decompose printed no time: " + output);
  return std::stod(output.substr(start + 1, unit - start - 1));
}

// What `hullcook decompose` times: every region's tree and its pieces at τ.
std::size_t decompose_and_read_pieces(const Model& model, double tau, Measure measure) {
  const DecomposeSettings settings = settings_for(tau, measure);
  std::size_t pieces = 0;
  for (const Region& region : regions_of(model))
    pieces += decompose(region, settings).pieces_at(tau).size();
  if (pieces == 0) throw std::logic_error("a decomposition without pieces");
  return pieces;
}

struct Times {
  double wall_ms, cpu_ms;
};

Times time_warm(const FirstRunRow& row) {
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_ms();
  decompose_and_read_pieces(*row.model, row.tau, row.measure);
  const double cpu = thread_cpu_ms() - cpu_start;
  return {
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
      cpu};
}

}  // namespace

int print_first_decomposition(const std::string& model, const std::string& tau,
                              const std::string& measure) {
  prepare_process_heap();
  const Model& chosen = model_named(model);
  const std::optional<Measure> parsed = parse_measure(measure);
  if (!parsed) throw std::invalid_argument("no measure " + measure);
  regions_of(chosen);  // read before the clock starts, as the command does
  const double start = thread_cpu_ms();
  decompose_and_read_pieces(chosen, std::stod(tau), *parsed);
  std::printf("%.6f\n", thread_cpu_ms() - start);
  return 0;
}

FirstRunComparison run_first_run_comparison(const std::filesystem::path& hullcook,
                                            const std::filesystem::path& self, int rounds,
                                            int repetitions) {
  FirstRunComparison result;
  result.rounds = rounds, result.repetitions = repetitions;
  for (const char* name : kModels) {
    const Model& model = model_named(name);
    for (Measure measure : kRowMeasures)
      result.rows.push_back({&model, measure, kFraction * model.paper_radius});
  }
  result.load_before = load_average();
  for (FirstRunRow& row : result.rows) time_warm(row);  // warms this process up
  const std::size_t n = result.rows.size();
  std::vector<std::vector<double>> cli(n), warm_wall(n), cli_ratio(n), fresh(n), warm_cpu(n),
      cpu_ratio(n);
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < n; ++i) {
      const FirstRunRow& row = result.rows[i];
      const std::string tau = exact(row.tau), measure = measure_name(row.measure);
      cli[i].push_back(
          printed_ms(run_for_output({hullcook.string(), "decompose", path_of(*row.model).string(),
                                     "--measure", measure, "--tau", tau})));
      fresh[i].push_back(std::stod(
          run_for_output({self.string(), "--first-decomposition", row.model->name, tau, measure})));
      std::vector<double> wall, cpu;
      for (int r = 0; r < repetitions; ++r) {
        const Times times = time_warm(row);
        wall.push_back(times.wall_ms), cpu.push_back(times.cpu_ms);
      }
      warm_wall[i].push_back(median(wall)), warm_cpu[i].push_back(median(cpu));
      cli_ratio[i].push_back(cli[i].back() / warm_wall[i].back());
      cpu_ratio[i].push_back(fresh[i].back() / warm_cpu[i].back());
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    FirstRunRow& row = result.rows[i];
    row.cli_first_ms = median(cli[i]), row.warm_wall_ms = median(warm_wall[i]);
    row.cli_ratio = median(cli_ratio[i]);
    row.fresh_cpu_ms = median(fresh[i]), row.warm_cpu_ms = median(warm_cpu[i]);
    row.cpu_ratio = median(cpu_ratio[i]);
  }
  result.load_after = load_average();
  return result;
}

void first_run_table(std::ostream& md, const std::optional<FirstRunComparison>& comparison) {
  md << "### D. The first decomposition in a fresh process\n\n";
  if (!comparison) {
    md << "Not measured (`bench_decompose --first-run PATH/TO/hullcook`; scripts/bench passes "
          "it).\n\n";
    return;
  }
  md << "Each round runs, per row, `hullcook decompose FILE --measure M --tau τ` (its printed "
        "time: wall time of the decomposition and its pieces, the first in that process) and "
        "`bench_decompose --first-decomposition` (the same work after the same heap preparation, "
        "in thread CPU time), then the same work warm in this process ("
     << comparison->repetitions << " repetitions, median, wall and CPU); " << comparison->rounds
     << " rounds. Ratios: median over the rounds of first / warm (target ≤ 1.5×). The wall "
        "times suffer from load far more than the CPU times: the load average (1, 5, 15 min) was "
     << comparison->load_before << " at the start, " << comparison->load_after << " at the end.\n\n"
     << "| model | τ | measure | CLI first ms (wall) | warm ms (wall) | ratio | fresh process "
        "first ms (CPU) | warm ms (CPU) | ratio | target (CPU) |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FirstRunRow& row : comparison->rows) {
    md << "| " << row.model->name << " | " << percent_text(kFraction) << " = " << tau_label(row.tau)
       << " | " << upper(measure_name(row.measure)) << " | " << ms_text(row.cli_first_ms) << " | "
       << ms_text(row.warm_wall_ms) << " | " << ratio_text(row.cli_ratio) << " | "
       << ms_text(row.fresh_cpu_ms) << " | " << ms_text(row.warm_cpu_ms) << " | "
       << ratio_text(row.cpu_ratio) << " | " << (row.cpu_ratio <= kTarget ? "met" : "**not met**")
       << " |\n";
  }
  md << "\n";
}

}  // namespace hullcook::bench
