// What a cook reads: its inputs expanded into asset files (directories walked, grid sheets cut
// into cells, sheet JSONs into frames), each named as its asset will be, in name order.
#pragma once

#include "asset_settings.h"
#include "grid.h"
#include "hullcook/cook/cook.h"
#include "hullcook/trace/trace.h"
#include "listed_files.h"
#include "sheet.h"

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace hullcook {

using Clock = std::chrono::steady_clock;

inline double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct InputFile {
  // A string, not a std::filesystem::path: a path holds a list of its components, which at
  // 10,000 assets was a fifth of a cook's memory (issue 19).
  std::string path;
  std::string name;  // relative to the input root, '/'-separated
  // A cell of a grid (--grid): the sheet, decoded once for all its cells, and where it lies.
  std::shared_ptr<const AlphaImage> sheet;
  GridCell cell;
  double decode_ms = 0;  // [ms] the sheet's decoding, counted on its first cell
  // A frame of a sheet JSON (path): frames->frames[frame] lies in `sheet`, its atlas.
  std::shared_ptr<const Sheet> frames;
  std::size_t frame = 0;
  // The image's own settings (asset_settings.h), once resolved: null when none differ.
  std::shared_ptr<const Settings> own;
  bool own_resolved = false;
};

inline bool is_poly_file(const std::filesystem::path& path) { return path.extension() == ".poly"; }

// The tracer's settings of a cook's, with simplify_px as its simplification bound [px].
TraceSettings trace_settings(const Settings& settings, double simplify_px);

// Expands directories (recursively) into image files; files are taken as given. In name order.
std::vector<InputFile> collect_inputs(const std::vector<std::filesystem::path>& inputs,
                                      const Settings& settings, AssetSettings& asset_settings,
                                      ListedFiles& listed,
                                      std::vector<std::filesystem::path>& skipped);

}  // namespace hullcook
