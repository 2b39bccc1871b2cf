// `--report report.json`: per-asset figures of a cook or a link, for CI dashboards.
#pragma once

#include "hullcook/cook/cook.h"

#include <string>

namespace hullcook {

// JSON (formatted, keys in a fixed order) with one object per asset, in the result's order:
// its name and source, vertices traced, pieces, hulls and hull vertices of the finest level,
// levels, τ and the max concavity [output units], the bytes it takes in a bundle (its records,
// physics, name, levels, hulls and vertices; null if no bundle can store it: a bundle of assets
// all with physics or all without is these plus the 64-byte header and 4 bytes a name-table
// slot), with timings its milliseconds per stage, its warnings; then the totals.
// Links pass with_timings false: fragments carry no timings.
std::string cook_report(const CookResult& result, bool with_timings);

}  // namespace hullcook
