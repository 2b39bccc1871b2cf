// The decomposer's benchmark (issues 3 and 22). One run prints:
//  A. ours against the ACD authors' own implementation (pieces / ms, pieces ratio, speed-up):
//     measured in the same run with `--acd2d DRIVER` (acd2d_driver, which `scripts/bench --acd2d`
//     builds), otherwise issue 22's static figures; and the monkey -> monkey_2 growth;
//  B. the paper's Figures 14-17 (b)-(d) for our code: pieces, time and convexity against τ for the
//     four measures on the maze, monkey, heron and neuron models;
//  C. Chipmunk's cpPolylineConvexDecomposition at the same τ, and CGAL's
//     approx_convex_partition_2 against our τ = 0 (each when built with it).
//  D. with `--first-run HULLCOOK`, the first decomposition in a fresh process (the time `hullcook
//     decompose` prints, and this program's --first-decomposition mode in CPU time) against the
//     same work warm.
// Every other time is the median CPU time of one thread over repetitions (Google Benchmark).
// `--write-docs DIR` also writes DIR/plots/*.svg and the generated section of DIR/benchmarks.md.
// `--quick` uses fewer repetitions and rounds (for trying the program out, not for figures).
#include "authors_comparison.h"
#include "bench_support.h"
#include "first_run.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/geometry.h"
#include "paper_models.h"
#include "svg_plot.h"

#include <benchmark/benchmark.h>
#include <pthread.h>

#ifdef HULLCOOK_BENCH_CHIPMUNK
#include <chipmunk/chipmunk.h>
extern "C" {
#include <chipmunk/cpPolyline.h>
}
#endif
#ifdef HULLCOOK_BENCH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace hullcook;
using namespace hullcook::bench;
namespace fs = std::filesystem;

constexpr Measure kMeasures[] = {Measure::sl, Measure::sp, Measure::h1, Measure::h2};

// ---------------------------------------------------------------------------------------------
void time_decompose(benchmark::State& state, const Model& model, double tau, Measure measure) {
  const std::vector<Region>& regions = regions_of(model);
  for (auto _ : state) {
    for (const Region& region : regions) {
      DecompositionTree tree = decompose(region, settings_for(tau, measure));
      benchmark::DoNotOptimize(tree.nodes().data());
    }
  }
}

#ifdef HULLCOOK_BENCH_CHIPMUNK
// Chipmunk's tolerance is the depth of a vertex below the line of its convex hull edge (its
// DeepestNotch), i.e. the SL concavity; it cuts along the hull edge's normal with a Steiner point
// and returns the convex hulls of the pieces. Only the outer ring (hole-free models).
struct ChipmunkLine {
  cpPolyline* line;
  explicit ChipmunkLine(const Ring& ring) {
    // Closed: the first vertex repeated at the end. Our outer rings are counter-clockwise, the
    // winding cpPolylineConvexDecomposition wants (positive cpAreaForPoly).
    line = static_cast<cpPolyline*>(
        std::malloc(sizeof(cpPolyline) + (ring.size() + 1) * sizeof(cpVect)));
    line->count = line->capacity = static_cast<int>(ring.size() + 1);
    for (std::size_t i = 0; i <= ring.size(); ++i)
      line->verts[i] = cpv(ring[i % ring.size()].x, ring[i % ring.size()].y);
  }
  ~ChipmunkLine() { std::free(line); }
  ChipmunkLine(const ChipmunkLine&) = delete;
  ChipmunkLine& operator=(const ChipmunkLine&) = delete;
};

std::size_t chipmunk_pieces(const Model& model, double tau) {
  std::size_t pieces = 0;
  for (const Region& region : regions_of(model)) {
    ChipmunkLine line(region.outer);
    cpPolylineSet* set = cpPolylineConvexDecomposition(line.line, tau);
    pieces += static_cast<std::size_t>(set->count);
    cpPolylineSetFree(set, cpTrue);
  }
  return pieces;
}

void time_chipmunk(benchmark::State& state, const Model& model, double tau) {
  std::vector<std::unique_ptr<ChipmunkLine>> lines;
  for (const Region& region : regions_of(model))
    lines.push_back(std::make_unique<ChipmunkLine>(region.outer));
  for (auto _ : state) {
    for (auto& line : lines) {
      cpPolylineSet* set = cpPolylineConvexDecomposition(line->line, tau);
      benchmark::DoNotOptimize(set->count);
      cpPolylineSetFree(set, cpTrue);
    }
  }
}
#endif

#ifdef HULLCOOK_BENCH_CGAL
// CGAL's approx_convex_partition_2 (Hertel-Mehlhorn on a constrained triangulation): an exact
// convex partition of a hole-free polygon, so it compares with our τ = 0.
using CgalTraits = CGAL::Partition_traits_2<CGAL::Exact_predicates_inexact_constructions_kernel>;

CgalTraits::Polygon_2 cgal_polygon(const Ring& ring) {
  CgalTraits::Polygon_2 polygon;
  for (const Vec2& p : ring) polygon.push_back(CgalTraits::Point_2(p.x, p.y));
  return polygon;
}

std::size_t cgal_partition(const CgalTraits::Polygon_2& polygon) {
  std::vector<CgalTraits::Polygon_2> parts;
  CGAL::approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(),
                                  std::back_inserter(parts));
  return parts.size();
}

std::size_t cgal_pieces(const Model& model) {
  std::size_t pieces = 0;
  for (const Region& region : regions_of(model))
    pieces += cgal_partition(cgal_polygon(region.outer));
  return pieces;
}

void time_cgal(benchmark::State& state, const Model& model) {
  std::vector<CgalTraits::Polygon_2> polygons;
  for (const Region& region : regions_of(model)) polygons.push_back(cgal_polygon(region.outer));
  for (auto _ : state)
    for (const auto& polygon : polygons) benchmark::DoNotOptimize(cgal_partition(polygon));
}
#endif

// ---------------------------------------------------------------------------------------------
// Registration, and the medians collected from the runs.

int g_table_repetitions = 15;
int g_sweep_repetitions = 5;
int g_paired_rounds = 15;      // tables A (with --acd2d) and D
int g_paired_repetitions = 5;  // per side, row and round

std::string table_name(const std::string& what, const Model& model, double tau) {
  return "table/" + what + "/" + model.name + "/tau=" + tau_label(tau);
}
std::string sweep_name(const Model& model, Measure measure, double tau) {
  return std::string("sweep/") + measure_name(measure) + "/" + model.name +
         "/tau=" + tau_label(tau);
}

std::map<std::string, int> g_registered;

void register_once(const std::string& name, int repetitions, double min_time,
                   std::function<void(benchmark::State&)> body) {
  if (!g_registered.emplace(name, repetitions).second) return;
  benchmark::RegisterBenchmark(name.c_str(), [body](benchmark::State& state) { body(state); })
      ->Unit(benchmark::kMillisecond)
      ->Repetitions(repetitions)
      ->ReportAggregatesOnly(true)
      ->MinTime(min_time);
}

void register_ours_table(const Model& model, double tau, Measure measure) {
  register_once(table_name(measure_name(measure), model, tau), g_table_repetitions, 0.02,
                [&model, tau, measure](benchmark::State& state) {
                  time_decompose(state, model, tau, measure);
                });
}

// The comparisons' τ: the reference table's fractions of the paper's R.
constexpr double kComparisonFractions[] = {0.01, 0.10};
const char* kHoleFreeModels[] = {"maze", "monkey", "monkey_2", "heron", "heron_2"};

void register_all() {
  for (const ComparisonRow& row : comparison_rows())
    register_ours_table(*row.model, row.tau(), row.measure);
  for (const Model& model : models())
    for (Measure measure : kMeasures)
      for (double tau : model.taus)
        register_once(sweep_name(model, measure, tau), g_sweep_repetitions, 0.01,
                      [&model, tau, measure](benchmark::State& state) {
                        time_decompose(state, model, tau, measure);
                      });
  for (const char* name : kHoleFreeModels) {
    const Model& model = model_named(name);
#ifdef HULLCOOK_BENCH_CHIPMUNK
    for (double fraction : kComparisonFractions) {
      double tau = fraction * model.paper_radius;
      register_ours_table(model, tau, Measure::sl);
      register_ours_table(model, tau, Measure::h1);
      register_once(table_name("chipmunk", model, tau), g_table_repetitions, 0.02,
                    [&model, tau](benchmark::State& state) { time_chipmunk(state, model, tau); });
    }
#endif
#ifdef HULLCOOK_BENCH_CGAL
    register_ours_table(model, 0.0, Measure::sl);
    register_ours_table(model, 0.0, Measure::h1);
    register_once(table_name("cgal", model, 0.0), g_table_repetitions, 0.02,
                  [&model](benchmark::State& state) { time_cgal(state, model); });
#endif
  }
}

// Shows only the median of each benchmark and keeps it [ms] for the tables.
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> median_ms;

  void ReportRuns(const std::vector<Run>& runs) override {
    std::vector<Run> shown;
    for (const Run& run : runs) {
      // One repetition (the sweeps under --quick) has no aggregates: its run is its median.
      const bool median =
          run.run_type == Run::RT_Aggregate ? run.aggregate_name == "median" : run.repetitions <= 1;
      if (!median) continue;
      median_ms[run.run_name.function_name] = run.GetAdjustedCPUTime();
      shown.push_back(run);
    }
    if (!shown.empty()) ConsoleReporter::ReportRuns(shown);
  }
};

std::optional<double> median_of(const MedianReporter& reporter, const std::string& name) {
  auto found = reporter.median_ms.find(name);
  if (found == reporter.median_ms.end()) return std::nullopt;
  return found->second;
}

// Reflex vertices: outer rings are counter-clockwise and holes clockwise, so the polygon's
// interior is on the left of every ring and a notch is a right turn.
std::size_t notch_count(const Ring& ring) {
  std::size_t notches = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    Vec2 a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
         c = ring[(i + 1) % ring.size()];
    if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0) ++notches;
  }
  return notches;
}

Series measure_series(Measure measure) {
  switch (measure) {
    case Measure::sl:
      return {"SL", "#d62728", "", {}};
    case Measure::sp:
      return {"SP", "#1f77b4", "", {}};
    case Measure::h1:
      return {"H1", "#2ca02c", "6 3", {}};
    case Measure::h2:
      return {"H2", "#ff7f0e", "2 3", {}};
  }
  return {};
}

// ---------------------------------------------------------------------------------------------
// The report: markdown, printed, and spliced into docs/benchmarks.md with --write-docs.

std::string machine_description() {
  std::string cpu = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  std::ostringstream out;
  out << cpu << ", " << std::thread::hardware_concurrency() << " logical cores; "
#if defined(__clang__)
      << "clang " << __clang_version__
#elif defined(__GNUC__)
      << "GCC " << __VERSION__
#endif
#ifdef NDEBUG
      << ", optimised build (NDEBUG)";
#else
      << ", UNOPTIMISED build (assertions on): not for figures";
#endif
  return out.str();
}

struct SweepPoint {
  double tau;
  Outcome outcome;
  std::optional<double> ms;
};

class Report {
 public:
  Report(const MedianReporter& medians, std::optional<PairedComparison> paired,
         std::optional<FirstRunComparison> first_run)
      : medians_(medians), paired_(std::move(paired)), first_run_(std::move(first_run)) {}

  std::string markdown() {
    std::ostringstream md;
    std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
    md << "Measured " << date << " on " << machine_description() << ". Times are the median CPU "
       << "time of one thread over " << g_table_repetitions << " repetitions (tables A, C) or "
       << g_sweep_repetitions << " (sweeps), from one run of `bench_decompose`.\n\n";
    radius_table(md);
    authors_table(md);
    chipmunk_table(md);
    cgal_table(md);
    first_run_table(md, first_run_);
    sweeps(md);
    return md.str();
  }

  const std::map<std::string, std::string>& plots() const { return plots_; }

 private:
  const MedianReporter& medians_;
  std::optional<PairedComparison> paired_;
  std::optional<FirstRunComparison> first_run_;
  std::map<std::string, std::string> plots_;  // file name -> SVG

  std::optional<double> ms(const std::string& name) const { return median_of(medians_, name); }

  void radius_table(std::ostream& md) {
    md << "### Models and radii\n\n"
       << "The comparisons give τ as a fraction of the paper's R (Table 2). That R is not "
          "the "
          "minimum enclosing circle radius which hullcook's `--tau 1%` uses: it matches the "
          "largest "
          "distance from the vertex centroid. Every τ below is in input units; tables A and C use "
          "τ = fraction × paper's R.\n\n"
       << "| model | file | vertices | notches | holes | paper's R | max distance from vertex "
          "centroid | minimum enclosing circle R |\n|---|---|---|---|---|---|---|---|\n";
    for (const Model& model : models()) {
      const std::vector<Region>& regions = regions_of(model);
      std::size_t vertices = 0, notches = 0, holes = 0;
      Vec2 sum{0, 0};
      std::size_t count = 0;
      for (const Region& region : regions) {
        vertices += region.outer.size();
        notches += notch_count(region.outer);
        holes += region.holes.size();
        for (const Ring& hole : region.holes) {
          vertices += hole.size();
          notches += notch_count(hole);
        }
        for (const Vec2& p : region.outer) sum += p, ++count;
      }
      Vec2 centroid = sum / static_cast<double>(count);
      double farthest = 0;
      for (const Region& region : regions)
        for (const Vec2& p : region.outer)
          farthest = std::max(farthest, std::hypot(p.x - centroid.x, p.y - centroid.y));
      md << "| " << model.name << " | " << model.file << " | " << vertices << " | " << notches
         << " | " << holes << " | " << model.paper_radius << " | " << fixed(farthest, 1) << " | "
         << fixed(enclosing_radius(regions), 1) << " |\n";
    }
    md << "\n";
  }

  // Table A, and how the time grows from monkey to monkey_2 (8x the vertices) on both sides.
  void authors_table(std::ostream& md) {
    auto our_ms = [this](const ComparisonRow& row) {
      return ms(table_name(measure_name(row.measure), *row.model, row.tau()));
    };
    comparison_table(md, paired_, our_ms);
    const Model& monkey = model_named("monkey");
    const Model& monkey_2 = model_named("monkey_2");
    md << "Growth from monkey (" << vertex_count(monkey) << " vertices) to monkey_2 ("
       << vertex_count(monkey_2) << ") at τ = 1% of the paper's R, our time ratio"
       << (paired_ ? " (theirs in brackets, both from table A)" : "") << ":";
    const std::vector<ComparisonRow>& rows = comparison_rows();
    auto row_index = [&](const Model& model, Measure measure) {
      for (std::size_t i = 0; i < rows.size(); ++i)
        if (rows[i].model == &model && rows[i].fraction == 0.01 && rows[i].measure == measure)
          return i;
      throw std::logic_error("no comparison row");
    };
    for (Measure measure : {Measure::sp, Measure::h1, Measure::sl}) {
      const std::size_t small = row_index(monkey, measure), large = row_index(monkey_2, measure);
      md << " " << upper(measure_name(measure)) << " ";
      if (paired_) {
        md << ratio_text(paired_->rows[large].our_ms / paired_->rows[small].our_ms) << " ("
           << ratio_text(paired_->rows[large].their_ms / paired_->rows[small].their_ms) << ")";
      } else {
        std::optional<double> small_ms = our_ms(rows[small]), large_ms = our_ms(rows[large]);
        md << (small_ms && large_ms ? ratio_text(*large_ms / *small_ms) : "—");
      }
      md << (measure == Measure::sl ? ".\n\n" : ",");
    }
  }

  void chipmunk_table(std::ostream& md) {
    md << "### C1. Chipmunk's cpPolylineConvexDecomposition\n\n";
#ifdef HULLCOOK_BENCH_CHIPMUNK
    md << "Chipmunk " << cpVersionString
       << ", outer ring as a closed cpPolyline, the same τ (Chipmunk's tolerance is the depth of a "
          "vertex below its hull edge's line, i.e. SL concavity; it cuts with Steiner points). "
          "Hole-free models. Ratios are ours / Chipmunk's (time ratio < 1: we are faster).\n\n"
       << "| model | τ | Chipmunk pieces | Chipmunk ms | our SL pieces | our SL ms | SL time "
          "ratio | our H1 pieces | our H1 ms | H1 time ratio "
          "|\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const char* name : kHoleFreeModels) {
      const Model& model = model_named(name);
      for (double fraction : kComparisonFractions) {
        double tau = fraction * model.paper_radius;
        std::optional<double> theirs = ms(table_name("chipmunk", model, tau));
        md << "| " << model.name << " | " << percent_text(fraction) << " = " << tau_label(tau)
           << " | " << chipmunk_pieces(model, tau) << " | " << ms_text(theirs);
        for (Measure measure : {Measure::sl, Measure::h1}) {
          std::optional<double> ours = ms(table_name(measure_name(measure), model, tau));
          md << " | " << decompose_model(model, tau, measure).pieces << " | " << ms_text(ours)
             << " | " << (ours && theirs ? fixed(*ours / *theirs, 2) : "—");
        }
        md << " |\n";
      }
    }
    md << "\n";
#else
    md << "Not built (Chipmunk not found).\n\n";
#endif
  }

  void cgal_table(std::ostream& md) {
    md << "### C2. CGAL's approx_convex_partition_2\n\n";
#ifdef HULLCOOK_BENCH_CGAL
    md << "CGAL " << CGAL_VERSION_STR
       << " (Epick kernel): an exact convex partition (Hertel–Mehlhorn), so against our τ = 0. "
          "Hole-free models, outer ring. Ratios are ours / CGAL's.\n\n"
       << "| model | CGAL pieces | CGAL ms | our SL pieces | our SL ms | SL time ratio | our H1 "
          "pieces | our H1 ms | H1 time ratio |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const char* name : kHoleFreeModels) {
      const Model& model = model_named(name);
      std::optional<double> theirs = ms(table_name("cgal", model, 0.0));
      md << "| " << model.name << " | " << cgal_pieces(model) << " | " << ms_text(theirs);
      for (Measure measure : {Measure::sl, Measure::h1}) {
        std::optional<double> ours = ms(table_name(measure_name(measure), model, 0.0));
        md << " | " << decompose_model(model, 0.0, measure).pieces << " | " << ms_text(ours)
           << " | " << (ours && theirs ? fixed(*ours / *theirs, 2) : "—");
      }
      md << " |\n";
    }
    md << "\n";
#else
    md << "Not built (CGAL not found; it is an optional benchmark-only dependency).\n\n";
#endif
  }

  void sweeps(std::ostream& md) {
    md << "### B. The paper's Figures 14–17 (b)–(d) for our code\n\n"
       << "Pieces, decomposition time and convexity (Eq. 9) against τ (input units, log axis), a "
          "fresh decomposition at each τ. τ = 0 (exact convex decomposition) is in the tables "
          "only.\n\n";
    std::map<std::string, std::map<Measure, std::vector<SweepPoint>>> all;
    for (const Model& model : models()) {
      if (model.taus.empty()) continue;
      auto& by_measure = all[model.name];
      for (Measure measure : kMeasures)
        for (double tau : model.taus)
          by_measure[measure].push_back(
              {tau, decompose_model(model, tau, measure), ms(sweep_name(model, measure, tau))});
      sweep_section(md, model, by_measure);
    }
    observations(md, all);
  }

  void sweep_section(std::ostream& md, const Model& model,
                     const std::map<Measure, std::vector<SweepPoint>>& by_measure) {
    md << "#### " << model.name << " (" << model.figure << ", " << model.file << ", paper's R "
       << model.paper_radius << ")\n\n";
    std::vector<double> xs;
    for (double tau : model.taus)
      if (tau > 0) xs.push_back(tau);
    // The paper's Figs. 15(b) and 16(b) also show the 8x finer twin's pieces (not timed here).
    std::vector<std::size_t> twin_pieces;
    if (model.twin)
      for (double tau : model.taus)
        twin_pieces.push_back(decompose_model(model_named(model.twin), tau, Measure::h1).pieces);
    struct Panel {
      const char* key;
      const char* label;
      bool log_y;
      std::function<double(const SweepPoint&)> value;
    };
    const Panel panels[] = {
        {"pieces", "pieces", true,
         [](const SweepPoint& p) { return static_cast<double>(p.outcome.pieces); }},
        {"time", "time [ms]", true, [](const SweepPoint& p) { return p.ms ? *p.ms : NAN; }},
        {"convexity", "convexity (Eq. 9)", false,
         [](const SweepPoint& p) { return p.outcome.convexity; }},
    };
    for (const Panel& panel : panels) {
      std::vector<Series> series;
      for (Measure measure : kMeasures) {
        Series line = measure_series(measure);
        for (const SweepPoint& point : by_measure.at(measure))
          if (point.tau > 0) line.ys.push_back(panel.value(point));
        series.push_back(line);
      }
      if (!twin_pieces.empty() && std::string(panel.key) == "pieces") {
        Series twin{std::string("H1, ") + model.twin, "#7f7f7f", "1 3", {}};
        for (std::size_t i = 0; i < model.taus.size(); ++i)
          if (model.taus[i] > 0) twin.ys.push_back(static_cast<double>(twin_pieces[i]));
        series.push_back(twin);
      }
      std::string file = std::string(model.name) + "-" + panel.key + ".svg";
      plots_[file] = line_plot_svg(std::string(model.name) + ": " + panel.label + " against τ",
                                   "τ [input units]", panel.label, xs, series, panel.log_y);
      md << "![" << model.name << " " << panel.key << "](plots/" << file << ") ";
    }
    md << "\n\n| τ | SL pieces | SP pieces | H1 pieces | H2 pieces |";
    if (model.twin) md << " H1 pieces " << model.twin << " |";
    md << " SL ms | SP ms | H1 ms | H2 ms | SL convexity | SP convexity | H1 convexity | H2 "
          "convexity |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|"
       << (model.twin ? "---|" : "") << "\n";
    for (std::size_t i = 0; i < model.taus.size(); ++i) {
      md << "| " << tau_label(model.taus[i]);
      for (Measure measure : kMeasures) md << " | " << by_measure.at(measure)[i].outcome.pieces;
      if (model.twin) md << " | " << twin_pieces[i];
      for (Measure measure : kMeasures) md << " | " << ms_text(by_measure.at(measure)[i].ms);
      for (Measure measure : kMeasures)
        md << " | " << fixed(by_measure.at(measure)[i].outcome.convexity, 4);
      md << " |\n";
    }
    md << "\n";
  }

  // Facts for the comparison with the paper, computed so that they stay true on a re-run.
  void observations(std::ostream& md,
                    const std::map<std::string, std::map<Measure, std::vector<SweepPoint>>>& all) {
    md << "#### Computed observations\n\n";
    const auto& maze = all.at("maze");
    md << "- Maze, τ ≥ 10 (the paper's Fig. 14(d) has SL miss features there):";
    for (std::size_t i = 0; i < maze.at(Measure::sl).size(); ++i) {
      const SweepPoint& sl = maze.at(Measure::sl)[i];
      const SweepPoint& sp = maze.at(Measure::sp)[i];
      if (sl.tau < 10) continue;
      md << " τ = " << tau_label(sl.tau) << ": SL " << sl.outcome.pieces << " pieces, convexity "
         << fixed(sl.outcome.convexity, 3) << " vs SP " << sp.outcome.pieces << " pieces, "
         << fixed(sp.outcome.convexity, 3) << ";";
    }
    const Region& whole_maze = regions_of(model_named("maze")).front();
    md << " the whole maze's concavity is " << fixed(measure_concavity(whole_maze, Measure::sl), 2)
       << " under SL and " << fixed(measure_concavity(whole_maze, Measure::sp), 2)
       << " under SP.\n";
    std::size_t same = 0, total = 0;
    std::string differing;
    for (const auto& [name, by_measure] : all)
      for (std::size_t i = 0; i < by_measure.at(Measure::sp).size(); ++i) {
        ++total;
        const SweepPoint& sp = by_measure.at(Measure::sp)[i];
        const SweepPoint& h1 = by_measure.at(Measure::h1)[i];
        if (sp.outcome.pieces == h1.outcome.pieces) {
          ++same;
        } else {
          differing += " " + name + " τ = " + tau_label(sp.tau) + " (SP " +
                       std::to_string(sp.outcome.pieces) + ", H1 " +
                       std::to_string(h1.outcome.pieces) + ");";
        }
      }
    md << "- SP and H1 give the same number of pieces at " << same << " of " << total
       << " (model, τ) points of the sweeps" << (differing.empty() ? "." : ", not at:" + differing)
       << "\n";
    double sp_total = 0, h1_total = 0, h2_total = 0, sl_total = 0;
    for (const auto& [name, by_measure] : all)
      for (std::size_t i = 0; i < by_measure.at(Measure::sp).size(); ++i) {
        auto time = [&](Measure m) { return by_measure.at(m)[i].ms.value_or(0.0); };
        sp_total += time(Measure::sp), h1_total += time(Measure::h1);
        h2_total += time(Measure::h2), sl_total += time(Measure::sl);
      }
    md << "- Total sweep time per measure (ms, sum of medians): SL " << ms_text(sl_total) << ", SP "
       << ms_text(sp_total) << ", H1 " << ms_text(h1_total) << ", H2 " << ms_text(h2_total)
       << " (the paper's order, slowest first: SP, H1, H2, SL).\n\n";
  }
};

constexpr const char* kBeginMarker = "<!-- bench_decompose: generated from here -->";
constexpr const char* kEndMarker = "<!-- bench_decompose: generated up to here -->";

void write_text(const fs::path& path, const std::string& text) {
  fs::path temporary = path;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, path);
}

// Replaces the generated section of benchmarks.md (appends one when the markers are absent).
void write_docs(const fs::path& docs, const Report& report, const std::string& markdown) {
  fs::create_directories(docs / "plots");
  for (const auto& [file, svg] : report.plots()) write_text(docs / "plots" / file, svg);
  fs::path page = docs / "benchmarks.md";
  std::string text;
  if (std::ifstream in(page, std::ios::binary); in) {
    std::ostringstream content;
    content << in.rdbuf();
    text = content.str();
  }
  std::string generated = std::string(kBeginMarker) + "\n\n" + markdown + kEndMarker;
  std::size_t begin = text.find(kBeginMarker), end = text.find(kEndMarker);
  if (begin != std::string::npos && end != std::string::npos && end > begin)
    text.replace(begin, end + std::strlen(kEndMarker) - begin, generated);
  else
    text += (text.empty() ? "" : "\n") + generated + "\n";
  write_text(page, text);
  std::cerr << "bench_decompose: wrote " << page << " and " << report.plots().size() << " plots\n";
}

struct Options {
  std::optional<fs::path> docs;
  std::optional<fs::path> acd2d_driver;
  std::optional<fs::path> hullcook;
  std::vector<char*> benchmark_args;
};

int run(Options options) {
  int argc = static_cast<int>(options.benchmark_args.size());
  options.benchmark_args.push_back(nullptr);
  benchmark::Initialize(&argc, options.benchmark_args.data());
  if (benchmark::ReportUnrecognizedArguments(argc, options.benchmark_args.data())) return 1;
  register_all();
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::cout.flush();
  std::optional<PairedComparison> paired;
  if (options.acd2d_driver) {
    std::cerr << "bench_decompose: the authors' code and ours, " << g_paired_rounds
              << " interleaved rounds\n";
    paired = run_paired_comparison(*options.acd2d_driver, g_paired_rounds, g_paired_repetitions);
  }
  std::optional<FirstRunComparison> first_run;
  if (options.hullcook) {
    std::cerr << "bench_decompose: first runs of " << *options.hullcook << ", " << g_paired_rounds
              << " rounds\n";
    first_run = run_first_run_comparison(*options.hullcook, "/proc/self/exe", g_paired_rounds,
                                         g_paired_repetitions);
  }
  Report report(reporter, std::move(paired), std::move(first_run));
  std::string markdown = report.markdown();
  std::cout << "\n" << markdown;
  if (options.docs) write_docs(*options.docs, report, markdown);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::string(argv[1]) == "--first-decomposition") {
    try {
      return print_first_decomposition(argv[2], argv[3], argv[4]);
    } catch (const std::exception& error) {
      std::cerr << "bench_decompose: " << error.what() << "\n";
      return 1;
    }
  }
  Options options;
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--write-docs" && i + 1 < argc) {
      options.docs = argv[++i];
    } else if (arg == "--acd2d" && i + 1 < argc) {
      options.acd2d_driver = argv[++i];
    } else if (arg == "--first-run" && i + 1 < argc) {
      options.hullcook = argv[++i];
    } else if (arg == "--quick") {
      g_table_repetitions = 3;
      g_sweep_repetitions = 1;
      g_paired_rounds = 3;
      g_paired_repetitions = 3;
    } else {
      options.benchmark_args.push_back(argv[i]);
    }
  }
  // Chipmunk's decomposition recurses with alloca'd copies of the polygon (hundreds of kB per
  // level on monkey_2): everything runs on a thread with a large stack.
  int status = 1;
  struct Call {
    Options* options;
    int* status;
  } call{&options, &status};
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstacksize(&attributes, std::size_t{1} << 30);
  pthread_t thread;
  auto body = [](void* data) -> void* {
    auto* call = static_cast<Call*>(data);
    try {
      *call->status = run(*call->options);
    } catch (const std::exception& error) {
      std::cerr << "bench_decompose: " << error.what() << "\n";
      *call->status = 1;
    }
    return nullptr;
  };
  if (pthread_create(&thread, &attributes, body, &call) != 0) {
    std::cerr << "bench_decompose: cannot start the benchmark thread\n";
    return 1;
  }
  pthread_join(thread, nullptr);
  return status;
}
