// Hole resolution at tileset scale (issue 16): sheets of many holes walled in by other holes, the
// normal case for tilesets, frames and UI art. One run prints, per input and τ: holes, vertices,
// pieces and the median time of one decomposition (one thread, Google Benchmark), beside the
// target. The inputs are made here: the 1000 x 1000 px sheet of 400 cells behind 3 px
// frame lines (traced as `hullcook cook` traces it), and polygon grids of 20 x 20 octagonal and
// round holes and a row of 40 hexagons with rounded coordinates, each in a 4-vertex rectangle.
#include "hullcook/core/clean.h"
#include "hullcook/core/decompose.h"
#include "hullcook/trace/trace.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace hullcook;

// The issue asks for the time on the sheet; this is the bound we hold it to (a decomposition of
// the sheet is under a tenth of a second on these machines when they are calm).
constexpr double kSheetTargetMs = 250.0;

// A sheet of cells x cells transparent cells inside opaque frame lines `line` px wide.
AlphaImage grid_sheet(int size, int cells, int line) {
  AlphaImage image{size, size, std::vector<std::uint8_t>(std::size_t(size) * size, 0)};
  const double pitch = double(size - line) / cells;
  auto on_line = [&](int v) {
    for (int k = 0; k <= cells; ++k) {
      const int start = int(std::lround(k * pitch));
      if (v >= start && v < start + line) return true;
    }
    return false;
  };
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (on_line(x) || on_line(y)) image.alpha[std::size_t(y) * size + x] = 255;
    }
  }
  return image;
}

// The traced sheet, simplified as `hullcook cook --tau T` simplifies it (τ / 4, within 0.05-1).
Region traced_sheet(double tau) {
  TraceSettings settings;
  settings.simplify = std::clamp(tau / 4, 0.05, 1.0);
  const TraceResult traced = trace_alpha(grid_sheet(1000, 20, 3), settings);
  return clean_and_validate(traced.regions, "sheet")[0];
}

// columns x rows regular `sides`-gons of circumradius 5, `wall` apart, in a 4-vertex rectangle,
// the coordinates rounded to `decimals`.
Region polygon_grid(int columns, int rows, int sides, double wall, double turn, int decimals) {
  const double cell = 10.0, pitch = cell + wall, unit = std::pow(10.0, decimals);
  auto round = [&](Vec2 p) {
    return Vec2{std::round(p.x * unit) / unit, std::round(p.y * unit) / unit};
  };
  Region region{{{0, 0},
                 {wall + columns * pitch, 0},
                 {wall + columns * pitch, wall + rows * pitch},
                 {0, wall + rows * pitch}},
                {}};
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      Ring hole;
      for (int k = 0; k < sides; ++k) {
        const double angle = turn - 2 * M_PI * k / sides;
        hole.push_back(round(Vec2{wall + i * pitch + cell / 2 + cell / 2 * std::cos(angle),
                                  wall + j * pitch + cell / 2 + cell / 2 * std::sin(angle)}));
      }
      region.holes.push_back(hole);
    }
  }
  return clean_and_validate({region}, "grid")[0];
}

struct Input {
  std::string name;
  Region (*make)(double tau);
};

const std::vector<Input>& inputs() {
  static const std::vector<Input> all = {
      {"sheet 1000 px, 400 cells", traced_sheet},
      {"20x20 octagons, wall 2", [](double) { return polygon_grid(20, 20, 8, 2.0, M_PI / 8, 9); }},
      {"20x20 round holes, wall 1", [](double) { return polygon_grid(20, 20, 16, 1.0, 0.0, 9); }},
      {"40 hexagons in a row, rounded", [](double) { return polygon_grid(40, 1, 6, 0.5, 0.0, 3); }},
  };
  return all;
}

struct Row {
  std::size_t holes = 0, vertices = 0, pieces = 0;
  double milliseconds = 0.0;
};
std::map<std::string, Row> rows;

void register_all() {
  for (const Input& input : inputs()) {
    for (double tau : {1.0, 4.0}) {
      for (Measure measure : {Measure::h1, Measure::sl}) {
        const std::string name =
            input.name + " | tau " + std::to_string(int(tau)) + " | " + measure_name(measure);
        benchmark::RegisterBenchmark(
            name.c_str(),
            [input, tau, measure, name](benchmark::State& state) {
              const Region region = input.make(tau);
              Row row;
              row.holes = region.holes.size();
              row.vertices = region.outer.size();
              for (const Ring& hole : region.holes) row.vertices += hole.size();
              for (auto _ : state) {
                const DecompositionTree tree = decompose(region, {tau, measure, 0.1, 1.0});
                row.pieces = tree.piece_count_at(tau);
                benchmark::DoNotOptimize(row.pieces);
              }
              rows[name] = row;
            })
            ->Unit(benchmark::kMillisecond)
            ->Repetitions(5)
            ->ReportAggregatesOnly(true)
            ->MeasureProcessCPUTime()
            ->UseRealTime();
      }
    }
  }
}

// Keeps each benchmark's median for the table printed after the run.
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.aggregate_name == "median") {
        rows[run.run_name.function_name].milliseconds = run.GetAdjustedRealTime();
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nHole resolution (issue 16): one decomposition, median of 5, one thread\n");
  std::printf("%-32s %5s %-3s %6s %8s %7s %10s\n", "input", "tau", "", "holes", "vertices",
              "pieces", "ms");
  for (const auto& [name, row] : rows) {
    const std::size_t first = name.find(" | "), second = name.find(" | ", first + 3);
    std::printf("%-32s %5s %-3s %6zu %8zu %7zu %10.2f\n", name.substr(0, first).c_str(),
                name.substr(first + 7, second - first - 7).c_str(), name.substr(second + 3).c_str(),
                row.holes, row.vertices, row.pieces, row.milliseconds);
  }
  for (const auto& [name, row] : rows) {
    if (name.rfind("sheet", 0) == 0 && name.find("tau 1 | h1") != std::string::npos) {
      std::printf("\nsheet of 400 cells at tau 1 px (h1): %.1f ms, target <= %.0f ms: %s\n",
                  row.milliseconds, kSheetTargetMs,
                  row.milliseconds <= kSheetTargetMs ? "met" : "MISSED");
    }
  }
  benchmark::Shutdown();
  return 0;
}
