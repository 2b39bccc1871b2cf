#include "hullcook/cook/report.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/fragment.h"
#include "hullcook/core/error.h"
#include "hullcook/format/bundle_layout.h"

#include <nlohmann/json.hpp>

namespace hullcook {
namespace {

using json = nlohmann::ordered_json;

// The asset's share of a bundle: a bundle of it alone, less what every bundle has once (the
// header) and the name table, whose size depends on the asset count.
// null for an asset no bundle can store (the bundle writer names it when asked to).
json bundle_bytes(const CookedAsset& asset) {
  try {
    const std::size_t alone = write_bundle({asset}).size();
    return alone - sizeof(format::BundleHeader) - 4 * format::writer_slot_count(1);
  } catch (const OutputError&) {
    return nullptr;
  }
}

}  // namespace

std::string cook_report(const CookResult& result, bool with_timings) {
  json assets = json::array();
  std::size_t pieces = 0, hulls = 0, hull_vertices = 0, bytes = 0;
  double milliseconds = 0;
  for (const CookedAsset& asset : result.assets) {
    std::size_t asset_hulls = 0, asset_vertices = 0;
    if (!asset.levels.empty()) {
      asset_hulls = asset.levels.front().hulls.size();
      for (const Ring& hull : asset.levels.front().hulls) asset_vertices += hull.size();
    }
    const json asset_bytes = bundle_bytes(asset);
    json entry = {{"name", asset.name},
                  {"source", asset.source},
                  {"vertices_traced", asset.stats.traced_vertices},
                  {"pieces", asset.stats.pieces},
                  {"hulls", asset_hulls},
                  {"hull_vertices", asset_vertices},
                  {"levels", asset.levels.size()},
                  {"tau", asset.tau},
                  {"max_concavity", asset.stats.max_concavity},
                  {"bundle_bytes", asset_bytes}};
    if (with_timings) {
      entry["ms"] = {{"decode", asset.stats.decode_ms},       {"trace", asset.stats.trace_ms},
                     {"decompose", asset.stats.decompose_ms}, {"limits", asset.stats.limits_ms},
                     {"contract", asset.stats.contract_ms},   {"total", asset.stats.total_ms}};
    }
    if (!asset.warnings.empty()) entry["warnings"] = asset.warnings;
    assets.push_back(std::move(entry));
    pieces += asset.stats.pieces;
    hulls += asset_hulls;
    hull_vertices += asset_vertices;
    if (asset_bytes.is_number()) bytes += asset_bytes.get<std::size_t>();
    milliseconds += asset.stats.total_ms;
  }
  json totals = {{"assets", result.assets.size()},
                 {"pieces", pieces},
                 {"hulls", hulls},
                 {"hull_vertices", hull_vertices},
                 {"bundle_bytes", bytes}};
  if (with_timings) totals["ms"] = milliseconds;
  const json report = {
      {"hullcook", tool_version()}, {"assets", std::move(assets)}, {"totals", std::move(totals)}};
  return report.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace hullcook
