#include "paper_models.h"

#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"

#include <iterator>
#include <map>
#include <stdexcept>

namespace hullcook::bench {
namespace {

// τ sweeps over the paper's figures' ranges, 1-2-5 steps on a log axis (0 is tabled, not plotted).
std::vector<double> one_two_five(double from, double to) {
  std::vector<double> taus{0.0};
  for (double decade = from; decade <= to * 1.0001; decade *= 10)
    for (double step : {1.0, 2.0, 5.0})
      if (decade * step <= to * 1.0001) taus.push_back(decade * step);
  return taus;
}

}  // namespace

const std::vector<Model>& models() {
  static const std::vector<Model> all = {
      {"maze", "misc/wierd2.poly", 15.3, one_two_five(0.01, 50), "Fig. 14", nullptr},
      {"monkey", "nazca/nazca_monkey.poly", 81.7, one_two_five(0.01, 100), "Fig. 15", "monkey_2"},
      {"monkey_2", "nazca/nazca_monkey_2.poly", 81.7, {}, "", nullptr},
      {"heron", "nazca/nazca_heron.poly", 137.1, one_two_five(0.01, 100), "Fig. 16", "heron_2"},
      {"heron_2", "nazca/nazca_heron_2.poly", 137.1, {}, "", nullptr},
      {"neuron", "neuron/neuron.poly", 19.6, one_two_five(0.001, 20), "Fig. 17", nullptr},
  };
  return all;
}

const Model& model_named(const std::string& name) {
  for (const Model& model : models())
    if (name == model.name) return model;
  throw std::logic_error("no model " + name);
}

std::filesystem::path path_of(const Model& model) {
  return std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons" / model.file;
}

const std::vector<Region>& regions_of(const Model& model) {
  static std::map<std::string, std::vector<Region>> cache;
  auto found = cache.find(model.name);
  if (found == cache.end()) found = cache.emplace(model.name, read_poly_file(path_of(model))).first;
  return found->second;
}

std::size_t vertex_count(const Model& model) {
  std::size_t vertices = 0;
  for (const Region& region : regions_of(model)) {
    vertices += region.outer.size();
    for (const Ring& hole : region.holes) vertices += hole.size();
  }
  return vertices;
}

DecomposeSettings settings_for(double tau, Measure measure) {
  return DecomposeSettings{tau, measure, 0.1, 1.0};
}

Outcome decompose_model(const Model& model, double tau, Measure measure) {
  std::vector<Piece> all;
  for (const Region& region : regions_of(model)) {
    DecompositionTree tree = decompose(region, settings_for(tau, measure));
    std::vector<Piece> pieces = tree.pieces_at(tau);
    all.insert(all.end(), std::make_move_iterator(pieces.begin()),
               std::make_move_iterator(pieces.end()));
  }
  return {all.size(), convexity(all)};
}

}  // namespace hullcook::bench
