// bench_output: the size and write time of every output format (issue 20) on samples/sprites
// (--tau 2 --ppu 32) and on the paper's polygons (--tau 1% of R, 1 unit per unit): bytes, bytes
// per hull vertex over all levels, and the median CPU time of one thread to write the bytes (the
// cook itself and the file system are not timed). Prints a markdown table; with
// --write-docs DIR it also replaces the generated part of DIR/benchmarks.md's "Output sizes".
#include "bench_support.h"
#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/cook.h"
#include "hullcook/cook/gltf_writer.h"

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace hullcook;

namespace {

double thread_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

struct Format {
  const char* name;
  std::function<std::string(const std::vector<CookedAsset>&)> write;
};

const std::vector<Format>& formats() {
  static const std::vector<Format> all = {
      {".hcb", [](const auto& assets) { return write_bundle(assets); }},
      {".gltf", [](const auto& assets) { return write_gltf(assets, {}); }},
      {".glb", [](const auto& assets) { return write_gltf(assets, {.binary = true}); }},
      {".glb --meshopt",
       [](const auto& assets) { return write_gltf(assets, {.binary = true, .meshopt = true}); }},
      {".glb --draco",
       [](const auto& assets) { return write_gltf(assets, {.binary = true, .draco = true}); }},
  };
  return all;
}

std::size_t vertex_count(const std::vector<CookedAsset>& assets) {
  std::size_t vertices = 0;
  for (const CookedAsset& asset : assets) {
    for (const CookedLevel& level : asset.levels) {
      for (const Ring& hull : level.hulls) vertices += hull.size();
    }
  }
  return vertices;
}

// One row per format: bytes, bytes per vertex, median write time over `runs` (at least 50 ms of
// writing in all, so that fast writers are timed over several calls).
std::string table_rows(const std::string& set, const std::vector<CookedAsset>& assets, int runs) {
  const std::size_t vertices = vertex_count(assets);
  std::string rows;
  for (const Format& format : formats()) {
    const std::size_t bytes = format.write(assets).size();
    std::vector<double> times;
    double spent = 0.0;
    for (int run = 0; run < runs || spent < 50.0; ++run) {
      const double start = thread_cpu_ms();
      const std::size_t again = format.write(assets).size();
      const double ms = thread_cpu_ms() - start;
      if (again != bytes) throw std::runtime_error("a writer gave two sizes");
      times.push_back(ms);
      spent += ms;
    }
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    char row[256];
    std::snprintf(row, sizeof row, "| %s | %s | %zu | %zu | %.2f | %.3g |\n", set.c_str(),
                  format.name, vertices, bytes, static_cast<double>(bytes) / vertices,
                  times[times.size() / 2]);
    rows += row;
  }
  return rows;
}

void write_docs(const fs::path& directory, const std::string& generated) {
  const fs::path page = directory / "benchmarks.md";
  if (!bench::replace_generated_section(page, "bench_output", generated)) {
    throw std::runtime_error(page.string() + ": no bench_output markers");
  }
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 15;
  fs::path docs;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) runs = 3;
    if (std::strcmp(argv[i], "--write-docs") == 0 && i + 1 < argc) docs = argv[++i];
  }
  const fs::path samples = fs::path(HULLCOOK_SOURCE_DIR) / "samples";
  Settings sprites;
  sprites.tau = Tolerance{2.0, false};
  sprites.pixels_per_unit = 32;
  sprites.threads = 1;
  Settings polygons;
  polygons.tau = Tolerance{0.01, true};
  polygons.threads = 1;
  std::vector<fs::path> paper;
  for (const char* file :
       {"misc/wierd2.poly", "nazca/nazca_monkey.poly", "nazca/nazca_monkey_2.poly",
        "nazca/nazca_heron.poly", "nazca/nazca_heron_2.poly", "neuron/neuron.poly",
        "misc/texas.poly", "misc/simple6.poly", "misc/bird.poly", "misc/mammoth.poly"}) {
    paper.push_back(samples / "polygons" / file);
  }
  std::string table =
      "| input | format | hull vertices | bytes | bytes per hull vertex | write ms |\n"
      "|---|---|---|---|---|---|\n";
  table += table_rows("samples/sprites, `--tau 2 --ppu 32`",
                      cook({samples / "sprites"}, sprites).assets, runs);
  table += table_rows("the paper's 10 polygons, `--tau 1%`", cook(paper, polygons).assets, runs);
  std::printf("%s", table.c_str());
  if (!docs.empty()) {
    std::ostringstream generated;
    generated << "\nMeasured by `bench_output` (median CPU time of one thread over at least "
              << runs << " writes; the cook is not timed).\n\n"
              << table << "\n";
    write_docs(docs, generated.str());
  }
  return 0;
}
