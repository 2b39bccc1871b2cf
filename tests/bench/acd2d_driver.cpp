// Times the ACD authors' own implementation (github jmlien/acd2d, MIT) for bench_decompose's
// paired comparison. `scripts/bench --acd2d DIR` builds the authors' library from the user's
// checkout DIR and links this file against it; nothing of their code is in this repository.
// It is not part of the CMake build (it needs their headers and their archive).
//
// A long-lived child of bench_decompose, so that both programs stay warm and take turns:
// every line on stdin asks for one row,
//   <file.poly> <τ in input units> <sl|sp|h1> <repetitions> [<warm-up ms>]
// and gets one line back,
//   ok <R> <fewest pieces> <most pieces> <ms> ... (one CPU time per repetition)
// or `error <text>`. The polygon is read and normalised the way the authors' command line does
// (acd2d_main_gui.cpp: operator>>, then normalize(), which scales by 1/R with R the largest
// distance of the outer boundary's vertices from their centroid, so that its -t is a fraction
// of R), with its default cut weights (alpha 0, beta 1). The τ asked for is divided by that R,
// so both programs cut at the same τ in input units whatever R the caller assumed. Only
// cd_2d::decomposeAll is timed: reading, copying the polygon into cd_2d and freeing the pieces are
// not. With a warm-up, the row is first decomposed untimed until that much CPU time has passed
// (at least once), as bench_decompose does for ours: see authors_comparison.cpp.
#include "acd2d.h"

#include <time.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

double thread_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

struct LoadedPolygon {
  acd2d::cd_polygon polygon;  // normalised: R = 1
  double radius = 0;          // R in input units, before normalising
};

// Reads each file once; the authors' reader prints nothing and accepts anything, so an empty
// or invalid result is refused here.
const LoadedPolygon& load(const std::string& path, std::map<std::string, LoadedPolygon>& cache) {
  auto found = cache.find(path);
  if (found != cache.end()) return found->second;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  LoadedPolygon loaded;
  in >> loaded.polygon;
  if (loaded.polygon.empty() || !loaded.polygon.valid())
    throw std::runtime_error(path + " is not a valid polygon for acd2d");
  loaded.radius = loaded.polygon.front().getRadius();
  loaded.polygon.normalize();
  return cache.emplace(path, loaded).first->second;
}

std::string measure_name(const std::string& ours) {
  if (ours == "sl" || ours == "sp") return ours;
  if (ours == "h1") return "hybrid1";
  throw std::runtime_error("unknown measure " + ours + " (sl, sp or h1)");
}

std::string time_row(const std::string& request, std::map<std::string, LoadedPolygon>& cache) {
  std::istringstream fields(request);
  std::string path, measure;
  double tau = 0;
  int repetitions = 0;
  double warm_up_ms = 0;
  if (!(fields >> path >> tau >> measure >> repetitions) || repetitions < 1)
    throw std::runtime_error("expected: <file.poly> <tau> <measure> <repetitions> [<warm-up ms>]");
  if (!(fields >> warm_up_ms)) warm_up_ms = 0;
  const LoadedPolygon& loaded = load(path, cache);
  const double fraction = tau / loaded.radius;
  const std::string their_measure = measure_name(measure);
  std::ostringstream reply;
  std::size_t fewest = SIZE_MAX, most = 0;
  std::vector<double> times;
  // One decomposition; its CPU time [ms] and pieces.
  auto decompose_once = [&](std::size_t& pieces) {
    acd2d::cd_2d decomposition;
    decomposition.addPolygon(loaded.polygon);
    std::unique_ptr<acd2d::IConcavityMeasure> concavity(
        acd2d::ConcavityMeasureFac::createMeasure(their_measure));
    decomposition.updateCutDirParameters(0, 1);
    const double start = thread_cpu_ms();
    decomposition.decomposeAll(fraction, concavity.get());
    const double ms = thread_cpu_ms() - start;
    pieces = decomposition.getDoneList().size();
    return ms;
  };
  std::size_t pieces = 0;
  if (warm_up_ms > 0) {
    const double warm_up_end = thread_cpu_ms() + warm_up_ms;
    do decompose_once(pieces);
    while (thread_cpu_ms() < warm_up_end);
  }
  for (int r = 0; r < repetitions; ++r) {
    times.push_back(decompose_once(pieces));
    fewest = std::min(fewest, pieces);
    most = std::max(most, pieces);
  }
  reply << "ok " << loaded.radius << ' ' << fewest << ' ' << most;
  for (double ms : times) reply << ' ' << ms;
  return reply.str();
}

}  // namespace

int main() {
  std::map<std::string, LoadedPolygon> cache;
  std::cout.precision(6);
  for (std::string request; std::getline(std::cin, request);) {
    if (request.empty()) continue;
    try {
      std::cout << time_row(request, cache) << std::endl;
    } catch (const std::exception& error) {
      std::cout << "error " << error.what() << std::endl;
    }
  }
  return 0;
}
