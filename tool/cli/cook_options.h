// The options shared by every command that cooks (cook, preview, decompose-like uses).
#pragma once

#include "hullcook/cook/cook.h"

#include <CLI/CLI.hpp>

namespace hullcook::cli {

// Options that need parsing after CLI11 is done; see finish_cook_options().
struct CookOptions {
  std::string tau = "2";
  std::string lods;
  std::string color_key;
  std::string pivot = "0.5,0.5";
  double weld = -1;
  double simplify = -1;
  std::string grid;
  int margin = 0;
  int spacing = 0;
  bool tile = false;
  double snap = 1.0;  // [px]
  PhysicsProperties physics;
};

// A finite number in [low, high], described as what ("a weight in [0, 1e9]"). CLI11's
// NonNegativeNumber lets nan and inf through, and an unsigned option would wrap -1 round to
// "unlimited".
CLI::Validator number_in(double low, double high, const std::string& what);

// Registers the decomposition, tracing, world-mapping, engine and physics options on command,
// writing into settings and options.
void add_cook_options(CLI::App& command, Settings& settings, CookOptions& options);

// After parsing: converts the textual options into settings. Throws UsageError.
void finish_cook_options(const CLI::App& command, Settings& settings, const CookOptions& options);

}  // namespace hullcook::cli
