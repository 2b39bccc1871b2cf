// The ACD paper's models as bench_decompose uses them, and one decomposition of a whole model.
#pragma once

#include "hullcook/core/decompose.h"
#include "hullcook/core/polygon.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace hullcook::bench {

// The paper's models (samples/polygons/README.md). paper_radius is the paper's R (Table 2), which
// the comparisons' "τ as a fraction of R" use. It is not the minimum enclosing circle of
// hullcook's `--tau 1%` (the paper's R matches the largest distance from the vertex centroid,
// which the program prints for checking, and which the authors' code normalises by).
struct Model {
  const char* name;
  const char* file;          // under samples/polygons
  double paper_radius;       // [input units] R of the paper's Table 2
  std::vector<double> taus;  // [input units] the τ sweep of its figure (empty: no figure)
  const char* figure;        // the paper's figure
  const char* twin;          // the same shape with 8x the vertices (its pieces are plotted too)
};

const std::vector<Model>& models();
const Model& model_named(const std::string& name);  // throws std::logic_error if unknown
std::filesystem::path path_of(const Model& model);
const std::vector<Region>& regions_of(const Model& model);  // read once
std::size_t vertex_count(const Model& model);

// The settings every decomposition of the benchmark uses (the CLI's default weights).
DecomposeSettings settings_for(double tau, Measure measure);

// What one decomposition of a whole model gives (sum over its regions).
struct Outcome {
  std::size_t pieces = 0;
  double convexity = 1.0;  // Eq. 9 over all pieces
};
Outcome decompose_model(const Model& model, double tau, Measure measure);

}  // namespace hullcook::bench
