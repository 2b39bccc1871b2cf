#include "quantize.h"

#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace hullcook {
namespace {

using format::HullRecord;
using format::VertexRecord;

struct GridPoint {
  std::int64_t x = 0, y = 0;
  bool operator<(const GridPoint& o) const { return x < o.x || (x == o.x && y < o.y); }
  bool operator==(const GridPoint& o) const { return x == o.x && y == o.y; }
};

std::int64_t cross(const GridPoint& o, const GridPoint& a, const GridPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain on the integer grid, exact: counter-clockwise, strictly convex (no
// repeated or collinear vertex), into hull. Fewer than 3 points when the rounded hull is
// degenerate. Sorts points.
void strict_convex_hull(std::vector<GridPoint>& points, std::vector<GridPoint>& hull) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) {
    hull = points;
    return;
  }
  hull.resize(2 * points.size());
  std::size_t k = 0;
  for (const GridPoint& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
}

// Distance from p to the region bounded by ring (0 inside), for any simple ring.
double distance_to_polygon(Vec2 p, const Ring& ring) {
  bool inside = false;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
    best = std::min(best, point_segment_distance_squared(p, a, b));
  }
  return inside ? 0.0 : std::sqrt(best);
}

// Two-sided Hausdorff distance of two simple polygons whose farthest points are vertices (true
// for convex polygons: the distance to a convex set is a convex function).
double hausdorff(const Ring& a, const Ring& b) {
  double worst = 0.0;
  for (const Vec2& p : a) worst = std::max(worst, distance_to_polygon(p, b));
  for (const Vec2& p : b) worst = std::max(worst, distance_to_polygon(p, a));
  return worst;
}

enum class Attempt { ok, too_coarse, too_wide };

// How a hull vertex meets the grid. nearest: the closest grid point. outward: of the corners of
// the grid cell holding it that lie as close (step/√2, the error bound readers report), the one
// farthest from the hull's vertex centroid. A hull thinner than a quantum rounds to a segment;
// the finer steps that would keep it a polygon may no longer store the asset's largest hull in
// 16-bit deltas, while pushing its sides apart may keep it one at the same step.
enum class Rounding { nearest, outward };

// The grid point for p at quantum; centroid only for outward.
GridPoint round_to_grid(Vec2 p, double quantum, Rounding rounding, Vec2 centroid) {
  if (rounding == Rounding::nearest)
    return {static_cast<std::int64_t>(std::nearbyint(p.x / quantum)),
            static_cast<std::int64_t>(std::nearbyint(p.y / quantum))};
  const double low_x = std::floor(p.x / quantum), low_y = std::floor(p.y / quantum);
  GridPoint best = round_to_grid(p, quantum, Rounding::nearest, centroid);
  const Vec2 away = p - centroid;
  double best_reach = glm::dot(Vec2{best.x * quantum, best.y * quantum} - p, away);
  for (int corner = 0; corner < 4; ++corner) {
    const double gx = low_x + (corner & 1), gy = low_y + (corner >> 1);
    const Vec2 moved{gx * quantum - p.x, gy * quantum - p.y};
    if (glm::dot(moved, moved) > 0.5 * quantum * quantum) continue;
    const double reach = glm::dot(moved, away);
    if (reach > best_reach) {
      best_reach = reach;
      best = {static_cast<std::int64_t>(gx), static_cast<std::int64_t>(gy)};
    }
  }
  return best;
}

// Quantizes one hull at step; too_coarse when the rounded hull degenerates or strays beyond
// the bound (a finer step may fix both), too_wide when it spans more than 16-bit deltas hold.
Attempt quantize_hull(const CookedAsset& asset, const Ring& hull, float step, double bound,
                      Rounding rounding, QuantizedHull& out, double& extent) {
  const double quantum = step;
  // Scratch, reused: one hull after the other.
  thread_local std::vector<GridPoint> points, grid;
  points.clear();
  Vec2 centroid{0.0, 0.0};
  if (rounding == Rounding::outward) {
    for (const Vec2& p : hull) centroid += p;
    centroid /= static_cast<double>(hull.size());
  }
  // The farthest a vertex moves [output units, squared], and the largest coordinate.
  double moved_squared = 0.0, size = 0.0;
  for (const Vec2& p : hull) {
    // Keep |base| + 2^15 within int32.
    if (std::fabs(p.x / quantum) > 2.0e9 || std::fabs(p.y / quantum) > 2.0e9) {
      bundle_asset_error(asset,
                         "a hull vertex at (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                             ") is too far from the origin for the bundle's 32-bit grid (at most " +
                             std::to_string(2.0e9 * quantum) + " output units at its step of " +
                             std::to_string(quantum) +
                             "); move the input nearer the origin, or write glTF");
    }
    const GridPoint q = round_to_grid(p, quantum, rounding, centroid);
    points.push_back(q);
    // format::dequantize gives the grid point's value as qx * quantum exactly.
    const double dx = static_cast<double>(q.x) * quantum - p.x;
    const double dy = static_cast<double>(q.y) * quantum - p.y;
    moved_squared = std::max(moved_squared, dx * dx + dy * dy);
    size = std::max({size, std::fabs(p.x), std::fabs(p.y)});
  }
  strict_convex_hull(points, grid);
  if (grid.size() < format::kMinHullVertices) return Attempt::too_coarse;

  std::int64_t min_x = grid[0].x, max_x = min_x, min_y = grid[0].y, max_y = min_y;
  for (const GridPoint& p : grid) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  constexpr std::int64_t kDeltaRange = 65535;  // int16 span
  if (max_x - min_x > kDeltaRange || max_y - min_y > kDeltaRange) {
    extent = static_cast<double>(std::max(max_x - min_x, max_y - min_y)) * quantum;
    return Attempt::too_wide;
  }
  // Centre the base so that deltas fall in [-32768, 32767].
  const std::int64_t base_x = min_x + 32768, base_y = min_y + 32768;
  out.record.base_x = static_cast<std::int32_t>(base_x);
  out.record.base_y = static_cast<std::int32_t>(base_y);
  out.vertices.clear();
  out.vertices.reserve(grid.size());
  for (const GridPoint& p : grid) {
    out.vertices.push_back(
        {static_cast<std::int16_t>(p.x - base_x), static_cast<std::int16_t>(p.y - base_y)});
  }
  // Each stored vertex is a hull vertex moved, and each hull vertex moved lies in the stored
  // (convex) hull: no vertex of either is farther from the other polygon than the farthest move.
  // The margin covers the rounding of hausdorff() below, which then could not say otherwise.
  if (std::sqrt(moved_squared) <= bound - 1e-12 * size) return Attempt::ok;
  Ring stored;
  stored.reserve(grid.size());
  for (const VertexRecord& v : out.vertices) {
    stored.push_back({format::dequantize(out.record.base_x, v.dx, step),
                      format::dequantize(out.record.base_y, v.dy, step)});
  }
  return hausdorff(hull, stored) <= bound ? Attempt::ok : Attempt::too_coarse;
}

}  // namespace

void bundle_asset_error(const CookedAsset& asset, const std::string& problem) {
  throw OutputError("bundle: asset '" + asset.name + "': " + problem);
}

QuantizedAsset quantize_asset(const CookedAsset& asset, const std::vector<CookedLevel>& levels) {
  // A large sprite's hulls may extend beyond 65 535 quanta at 1 % of τ: the quantum grows with
  // them (SPEC §9) rather than the asset being refused.
  double largest_extent = 0.0;
  for (const CookedLevel& level : levels) {
    for (const Ring& hull : level.hulls) {
      if (hull.empty()) continue;
      double min_x = hull[0].x, max_x = min_x, min_y = hull[0].y, max_y = min_y;
      for (const Vec2& p : hull) {
        min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
        min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
      }
      largest_extent = std::max({largest_extent, max_x - min_x, max_y - min_y});
    }
  }
  const double bound =
      format::quantization_error_bound(levels[0].tau, asset.pixels_per_unit, largest_extent);
  QuantizedAsset result;
  // Rounding alone moves a vertex by at most step/√2 = bound; halving covers dropped vertices.
  // The f32 step is rounded down, so that step/√2 never exceeds the bound: rounded up, a vertex
  // half a quantum off in x and y could miss the bound and halve a step that large hulls need.
  result.step = static_cast<float>(bound * std::sqrt(2.0));
  if (static_cast<double>(result.step) > bound * std::sqrt(2.0)) {
    result.step = std::nextafter(result.step, 0.0f);
  }
  if (asset.tile) {
    // Half a pixel over the largest power of two that fits: the cell's borders, at whole or half
    // pixels from the pivot, fall on the grid (and stay on it when the step is halved below), so
    // neighbouring tiles' hulls meet exactly.
    const double half_pixel = 0.5 / asset.pixels_per_unit;
    double aligned = half_pixel;
    while (aligned > result.step && aligned > 0.0) aligned *= 0.5;
    // Exact when pixels per unit is a power of two; otherwise the borders are off by the f32
    // rounding of the step, far below any engine's slop.
    if (aligned > 0.0) result.step = static_cast<float>(aligned);
  }
  // A tiny pixels per unit makes the 1/64 px floor of the bound huge (issue 19's fuzzing of link:
  // 2.9e-39 px per unit); readers refuse a step beyond kMaxQuantStep.
  if (!(result.step <= format::kMaxQuantStep)) {
    bundle_asset_error(asset,
                       "pixels per unit too small for the bundle's quantization grid (a step of " +
                           std::to_string(result.step) + " output units)");
  }
  // At each step each hull is rounded to the nearest grid points, else outward (which may keep a
  // hull thinner than a quantum a polygon); the step is halved until every hull is stored within
  // the bound.
  double too_wide_extent = 0.0;
  const float first_step = result.step;
  bool refined = false;  // whether the step that spanned too many quanta was halved
  for (int attempt = 0; attempt < 24 && too_wide_extent == 0.0; ++attempt, result.step *= 0.5f) {
    if (!(result.step > 0.0f)) break;
    result.levels.assign(levels.size(), {});
    Attempt outcome = Attempt::ok;
    for (std::size_t l = 0; l < levels.size() && outcome == Attempt::ok; ++l) {
      for (const Ring& hull : levels[l].hulls) {
        QuantizedHull quantized;
        for (Rounding rounding : {Rounding::nearest, Rounding::outward}) {
          outcome =
              quantize_hull(asset, hull, result.step, bound, rounding, quantized, too_wide_extent);
          if (outcome != Attempt::too_coarse) break;
        }
        if (outcome != Attempt::ok) break;
        result.levels[l].push_back(std::move(quantized));
      }
    }
    if (outcome == Attempt::ok) return result;
    if (outcome == Attempt::too_wide) refined = result.step < first_step;
  }
  if (too_wide_extent > 0.0) {
    // The step is first halved for a hull that rounds to a segment, a sliver of the outline
    // that simplifying it (--simplify) or a larger tau removes.
    bundle_asset_error(
        asset, "a hull spans " + std::to_string(too_wide_extent) +
                   " output units, more than the 65535 quanta of 16-bit deltas at the required "
                   "precision of " +
                   std::to_string(bound) + " units" +
                   (refined ? " once the step is refined for a hull thinner than it; cook it with "
                              "--simplify or a larger tau"
                            : "; cook it with a larger tau"));
  }
  bundle_asset_error(asset, "a hull is too thin to be stored as a convex polygon within " +
                                std::to_string(bound) + " output units");
}

}  // namespace hullcook
