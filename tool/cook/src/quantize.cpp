#include "quantize.h"

#include "contract_text.h"

#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
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

// Grid coordinates reach ±2e9 (quantize_hull), so their differences' products need more than
// 64 bits before a hull is found too wide.
using Wide = __int128;

Wide cross(const GridPoint& o, const GridPoint& a, const GridPoint& b) {
  return Wide{a.x - o.x} * (b.y - o.y) - Wide{a.y - o.y} * (b.x - o.x);
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

enum class Attempt { ok, too_coarse, too_wide, too_far, broken_by_floats };

// Why a hull was not stored at a step: the span of a too wide one, or what is too far.
struct Refusal {
  double extent = 0.0;     // [output units] of the hull too wide, at the step it met
  float wide_step = 0.0f;  // [output units] that step
  std::string too_far;     // the message
  // The last hull too coarse at its step: the one that made the step finer (when it was).
  std::size_t thin_level = 0, thin_hull = 0;
  Vec2 thin_at{0.0, 0.0};
  double thin_thickness = 0.0;  // [output units]
  bool thin_known = false;
};

// value rounded up to two significant digits, for advice that must not fall short.
double rounded_up(double value) {
  if (!(value > 0.0) || !std::isfinite(value)) return value;
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1);
  return std::ceil(value / unit) * unit;
}

// How a hull vertex meets the grid. nearest: the closest grid point. outward: of the corners of
// the grid cell holding it that lie as close (step/√2, the error bound readers report), the one
// farthest from the hull's vertex centroid. nudged: the nearest grid points, then, while they
// lie on one line, the vertex moved to another of those corners that spreads them most (see
// spread_nudged). A hull thinner than a quantum rounds to a segment; the finer steps that would
// keep it a polygon may no longer store the asset's largest hull in 16-bit deltas, while pushing
// its sides apart may keep it one at the same step.
enum class Rounding { nearest, outward, nudged };

// The corners of p's grid cell within quantum/√2 of p (nearest rounding's worst move), in the
// cell's order; the nearest grid point is always one of them.
struct Corners {
  std::array<GridPoint, 4> points;
  int count = 0;
  const GridPoint* begin() const { return points.data(); }
  const GridPoint* end() const { return points.data() + count; }
};

Corners close_corners(Vec2 p, double quantum) {
  Corners corners;
  const double low_x = std::floor(p.x / quantum), low_y = std::floor(p.y / quantum);
  for (int corner = 0; corner < 4; ++corner) {
    const double gx = low_x + (corner & 1), gy = low_y + (corner >> 1);
    const Vec2 moved{gx * quantum - p.x, gy * quantum - p.y};
    if (glm::dot(moved, moved) <= 0.5 * quantum * quantum) {
      corners.points[static_cast<std::size_t>(corners.count++)] = {static_cast<std::int64_t>(gx),
                                                                   static_cast<std::int64_t>(gy)};
    }
  }
  return corners;
}

// The grid point for p at quantum; centroid only for outward.
GridPoint round_to_grid(Vec2 p, double quantum, Rounding rounding, Vec2 centroid) {
  if (rounding != Rounding::outward)
    return {static_cast<std::int64_t>(std::nearbyint(p.x / quantum)),
            static_cast<std::int64_t>(std::nearbyint(p.y / quantum))};
  GridPoint best = round_to_grid(p, quantum, Rounding::nearest, centroid);
  const Vec2 away = p - centroid;
  double best_reach = glm::dot(Vec2{best.x * quantum, best.y * quantum} - p, away);
  for (const GridPoint& corner : close_corners(p, quantum)) {
    const Vec2 moved{static_cast<double>(corner.x) * quantum - p.x,
                     static_cast<double>(corner.y) * quantum - p.y};
    const double reach = glm::dot(moved, away);
    if (reach > best_reach) best_reach = reach, best = corner;
  }
  return best;
}

// How far apart points are, to compare nudges exactly: a polygon's twice area beats a segment's
// squared length, which beats a single point.
struct Spread {
  int dimension = 0;
  Wide size = 0;  // twice the area, or the squared length, exact
  bool operator>(const Spread& o) const {
    return dimension > o.dimension || (dimension == o.dimension && size > o.size);
  }
};

Spread spread_of(std::vector<GridPoint> points, std::vector<GridPoint>& hull) {
  strict_convex_hull(points, hull);
  if (hull.size() < 2) return {};
  if (hull.size() == 2) {
    const Wide dx = hull[1].x - hull[0].x, dy = hull[1].y - hull[0].y;
    return {1, dx * dx + dy * dy};
  }
  Wide twice_area = 0;
  for (std::size_t i = 1; i + 1 < hull.size(); ++i)
    twice_area += cross(hull[0], hull[i], hull[i + 1]);
  return {2, twice_area};
}

// Nudged rounding of hull's vertices, rounded to the nearest grid points in points: while the
// points lie on one line, the one move of a vertex to another close corner that spreads them
// most (the first such in vertex and corner order). Each move keeps every vertex within
// quantum/√2 of its grid point, so the bound holds as for the other roundings; the points stay one
// per vertex, so the stored hull has no more vertices than the cooked one.
void spread_nudged(const Ring& hull, double quantum, std::vector<GridPoint>& points) {
  // Each try sorts the points: O(n² log n) a move. A hull of more vertices is left to the finer
  // steps (a thin arc of 8,000 vertices took 12 s over the second pass's steps).
  constexpr std::size_t kMostVertices = 64;
  if (hull.size() > kMostVertices) return;
  std::vector<GridPoint> scratch;
  Spread current = spread_of(points, scratch);
  // Two moves make a polygon of points that all rounded to one; a third is spare.
  for (int moves = 0; current.dimension < 2 && moves < 3; ++moves) {
    Spread best = current;
    std::size_t best_vertex = hull.size();
    GridPoint best_corner;
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const GridPoint kept = points[i];
      for (const GridPoint& corner : close_corners(hull[i], quantum)) {
        if (corner == kept) continue;
        points[i] = corner;
        const Spread spread = spread_of(points, scratch);
        if (spread > best) best = spread, best_vertex = i, best_corner = corner;
      }
      points[i] = kept;
    }
    if (best_vertex == hull.size()) return;  // no move spreads them: a finer step must
    points[best_vertex] = best_corner;
    current = best;
  }
}

// Whether 32-bit floats at some point of grid are coarser than its step.
bool floats_coarser(const std::vector<GridPoint>& grid, double quantum) {
  return std::any_of(grid.begin(), grid.end(), [&](const GridPoint& q) {
    return !format::floats_resolve(static_cast<double>(q.x) * quantum, quantum) ||
           !format::floats_resolve(static_cast<double>(q.y) * quantum, quantum);
  });
}

// The runtime's f32 vertices of grid: each grid point's value rounded to float once. Scratch of
// the calling thread, valid until the next call.
Ring& runtime_floats(const std::vector<GridPoint>& grid, double quantum) {
  thread_local Ring floats;
  floats.clear();
  for (const GridPoint& q : grid) {
    floats.push_back({format::nearest_float(static_cast<double>(q.x) * quantum),
                      format::nearest_float(static_cast<double>(q.y) * quantum)});
  }
  return floats;
}

// Whether the runtime's f32 vertices no longer bound a convex polygon, for a grid where floats
// are coarser than the grid (floats_coarser): a line, a point, a reflex vertex
// (stop 48's review: a sprite cooked with --pivot 2e5,2e5 had 8 of 22 hulls reflex in the
// runtime) or a spike. They may repeat a vertex, or make it collinear. (Nearer the origin a
// reader's floats lie within half a step of the grid, and a hull thinner than that, a sliver
// stored at the grid's step beside a wide hull, is within the bound whatever its floats do.)
bool floats_break(const std::vector<GridPoint>& grid, double quantum) {
  return !is_weakly_convex(runtime_floats(grid, quantum));
}

// Leaves out of grid (strictly convex, counter-clockwise) each vertex whose f32 value turns right
// between its neighbours' in the runtime, one at a time; whether any was. Where floats resolve the
// grid (floats_break looks at the rest) they still move each point by up to half their spacing, so
// a vertex whose height over its neighbours' line is below that can turn the reader's hull reflex
// (stop 55's sweep: Koch snowflakes 1e5 from the origin, 5 of 613 hulls up to 0.0037 units inward
// at floats 0.0078 apart). Left out, it lies on the kept edge's side within that half spacing: the
// caller measures the stored hull against the bound again.
bool drop_float_reflex(std::vector<GridPoint>& grid, double quantum) {
  Ring& floats = runtime_floats(grid, quantum);
  bool dropped = false;
  for (bool changed = true; changed && grid.size() >= format::kMinHullVertices;) {
    changed = false;
    for (std::size_t k = 0; k < grid.size() && grid.size() >= format::kMinHullVertices;) {
      const std::size_t m = grid.size();
      if (orientation(floats[(k + m - 1) % m], floats[k], floats[(k + 1) % m]) >= 0) {
        ++k;
        continue;
      }
      grid.erase(grid.begin() + static_cast<std::ptrdiff_t>(k));
      floats.erase(floats.begin() + static_cast<std::ptrdiff_t>(k));
      changed = dropped = true;
    }
  }
  return dropped;
}

// Why a hull that floats_break is refused.
std::string broken_by_floats(const Ring& hull, const std::vector<GridPoint>& grid, double quantum) {
  double spacing = 0.0, low_x = hull[0].x, high_x = low_x, low_y = hull[0].y, high_y = low_y;
  for (const GridPoint& q : grid) {
    spacing = std::max({spacing, format::float_spacing(static_cast<double>(q.x) * quantum),
                        format::float_spacing(static_cast<double>(q.y) * quantum)});
  }
  for (const Vec2& p : hull) {
    low_x = std::min(low_x, p.x), high_x = std::max(high_x, p.x);
    low_y = std::min(low_y, p.y), high_y = std::max(high_y, p.y);
  }
  return "a hull at " + detail::point(hull[0]) + ", " + detail::number(high_x - low_x) + " x " +
         detail::number(high_y - low_y) +
         " output units, would reach the runtime as a line, a point or a polygon that is not "
         "convex: 32-bit floats there are " +
         detail::number(spacing) + " apart, coarser than the grid's step of " +
         detail::number(quantum) + "; move the input nearer the origin (for an image, --pivot)";
}

// Quantizes one hull at step; too_coarse when the rounded hull degenerates or strays beyond
// the bound (a finer step may fix both), too_wide when it spans more than 16-bit deltas hold,
// too_far when a vertex lies beyond the 32-bit grid (neither a finer step fixes),
// broken_by_floats when the runtime's floats break the stored hull (another rounding may not; a
// finer step does not).
Attempt quantize_hull(const Ring& hull, float step, double bound, Rounding rounding,
                      QuantizedHull& out, Refusal& refusal) {
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
      refusal.too_far = "a hull vertex at (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                        ") is too far from the origin for the bundle's 32-bit grid (at most " +
                        std::to_string(2.0e9 * quantum) + " output units at its step of " +
                        std::to_string(quantum) +
                        "); move the input nearer the origin, or write glTF";
      return Attempt::too_far;
    }
    const GridPoint q = round_to_grid(p, quantum, rounding, centroid);
    points.push_back(q);
    // format::dequantize gives the grid point's value as qx * quantum exactly.
    const double dx = static_cast<double>(q.x) * quantum - p.x;
    const double dy = static_cast<double>(q.y) * quantum - p.y;
    moved_squared = std::max(moved_squared, dx * dx + dy * dy);
    size = std::max({size, std::fabs(p.x), std::fabs(p.y)});
  }
  if (rounding == Rounding::nudged) {
    spread_nudged(hull, quantum, points);
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const double dx = static_cast<double>(points[i].x) * quantum - hull[i].x;
      const double dy = static_cast<double>(points[i].y) * quantum - hull[i].y;
      moved_squared = std::max(moved_squared, dx * dx + dy * dy);
    }
  }
  strict_convex_hull(points, grid);
  // Where floats are coarser than the grid, floats_break decides (below); leaving vertices out
  // does not change which.
  const bool coarse = floats_coarser(grid, quantum);
  const bool dropped = !coarse && drop_float_reflex(grid, quantum);
  if (grid.size() < format::kMinHullVertices) return Attempt::too_coarse;

  std::int64_t min_x = grid[0].x, max_x = min_x, min_y = grid[0].y, max_y = min_y;
  for (const GridPoint& p : grid) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  constexpr std::int64_t kDeltaRange = 65535;  // int16 span
  if (max_x - min_x > kDeltaRange || max_y - min_y > kDeltaRange) {
    refusal.extent = static_cast<double>(std::max(max_x - min_x, max_y - min_y)) * quantum;
    refusal.wide_step = step;
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
  // (convex) hull: no vertex of either is farther from the other polygon than the farthest move
  // (unless a vertex was left out for the floats).
  // The margin covers the rounding of hausdorff() below, which then could not say otherwise.
  if (dropped || !(std::sqrt(moved_squared) <= bound - 1e-12 * size)) {
    Ring stored;
    stored.reserve(grid.size());
    for (const VertexRecord& v : out.vertices) {
      stored.push_back({format::dequantize(out.record.base_x, v.dx, step),
                        format::dequantize(out.record.base_y, v.dy, step)});
    }
    if (!(hausdorff(hull, stored) <= bound)) return Attempt::too_coarse;
  }
  if (coarse && floats_break(grid, quantum)) {
    refusal.too_far = broken_by_floats(hull, grid, quantum);
    return Attempt::broken_by_floats;
  }
  return Attempt::ok;
}

}  // namespace

void bundle_asset_error(const std::string& name, const std::string& problem) {
  // A name too long for the bundle is shown by its start: a sheet's frame named by 70 KB of
  // text was repeated whole in the message (a helper's sheets, stop 59).
  constexpr std::size_t kShown = 120;
  const std::string shown = name.size() <= kShown ? name
                                                  : name.substr(0, kShown) + "... (" +
                                                        std::to_string(name.size()) + " bytes)";
  throw OutputError("bundle: asset '" + shown + "': " + problem);
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
    // Neighbouring tiles' hulls meet exactly. With pixels per unit not a power of two, the
    // borders are off by the f32 rounding of the step, far below any engine's slop.
    const double aligned = format::tile_step(asset.pixels_per_unit, result.step);
    if (aligned > 0.0) result.step = static_cast<float>(aligned);
  }
  // A tiny pixels per unit makes the 1/64 px floor of the bound huge (issue 19's fuzzing of link:
  // 2.9e-39 px per unit); readers refuse a step beyond kMaxQuantStep.
  if (!(result.step <= format::kMaxQuantStep)) {
    bundle_asset_error(asset,
                       "pixels per unit too small for the bundle's quantization grid (a step of " +
                           std::to_string(result.step) + " output units)");
  }
  // Stores every hull at step with the first rounding_count roundings (nearest, outward, nudged)
  // into result; refusal says why a hull was not.
  Refusal refusal;
  const auto store_at = [&](float step, std::size_t rounding_count) {
    constexpr Rounding kRoundings[] = {Rounding::nearest, Rounding::outward, Rounding::nudged};
    result.step = step;
    result.levels.assign(levels.size(), {});
    for (std::size_t l = 0; l < levels.size(); ++l) {
      for (const Ring& hull : levels[l].hulls) {
        QuantizedHull quantized;
        Attempt outcome = Attempt::too_coarse;
        for (std::size_t r = 0; r < rounding_count && (outcome == Attempt::too_coarse ||
                                                       outcome == Attempt::broken_by_floats);
             ++r)
          outcome = quantize_hull(hull, step, bound, kRoundings[r], quantized, refusal);
        if (outcome == Attempt::broken_by_floats) return Attempt::too_far;
        if (outcome == Attempt::too_coarse) {
          refusal.thin_level = l, refusal.thin_hull = result.levels[l].size();
          refusal.thin_at = hull[0], refusal.thin_known = true;
          refusal.thin_thickness = convex_thickness(hull);
        }
        if (outcome != Attempt::ok) return outcome;
        result.levels[l].push_back(std::move(quantized));
      }
    }
    return Attempt::ok;
  };
  // At each step each hull is rounded to the nearest grid points, else outward (which may keep a
  // hull thinner than a quantum a polygon); the step is halved until every hull is stored within
  // the bound. A finer step cannot store a hull too wide or too far.
  const float first_step = result.step;
  Attempt outcome = Attempt::too_coarse;
  bool refined = false;  // whether the step that met a hull too wide or too far was halved
  float step = first_step;
  for (int attempt = 0; attempt < 24 && step > 0.0f; ++attempt, step *= 0.5f) {
    outcome = store_at(step, 2);
    if (outcome == Attempt::ok) return result;
    if (outcome == Attempt::too_wide || outcome == Attempt::too_far) {
      refined = attempt > 0;
      break;
    }
  }
  // When no step does, the asset starts again with nudged rounding as a third choice, at the
  // first step and each halving of it, each followed by the 8 steps up to 1/128 finer (at the
  // first, still within 16-bit deltas for the widest hull, whose span sets it at 65 000 quanta;
  // each is a different alignment of the grid for a hull far from the origin): a hull thinner
  // than a quantum beside one that spans nearly the grid (a comb's sliver beside its spine) is
  // then stored at the step the spine needs, and a speck of an exact decomposition at a step
  // near its size. This comes last so that every asset the first pass stores keeps its bytes; a
  // hull too wide or too far at the first step is beyond it.
  if (outcome == Attempt::too_coarse || refined) {
    // A tile's step stays a power of two of its half pixel, so that its borders stay on the grid.
    const int variants = asset.tile ? 1 : 9;
    float level = first_step;  // halved as the first pass halves
    for (int halvings = 0; halvings < 24 && level > 0.0f; ++halvings, level *= 0.5f) {
      for (int k = 0; k < variants; ++k) {
        outcome = store_at(k == 0 ? level : static_cast<float>(level * (1.0 - k / 1024.0)), 3);
        if (outcome == Attempt::ok) return result;
        // Every later step is finer still: a hull too wide or too far stays so.
        if (outcome == Attempt::too_wide || outcome == Attempt::too_far) break;
      }
      if (outcome == Attempt::too_wide || outcome == Attempt::too_far) break;
    }
  }
  if (outcome == Attempt::too_far) bundle_asset_error(asset, refusal.too_far);
  if (outcome == Attempt::too_wide) {
    // Name the step, the quanta and, when the step was made finer, the hull that needed it: the
    // fix is for that hull (a sliver of the outline that a weld, --simplify or a larger tau
    // removes), not for the wide one.
    const double quanta = refusal.extent / static_cast<double>(refusal.wide_step);
    std::string problem = "a hull spans " + detail::number(refusal.extent) + " output units, " +
                          detail::number(std::floor(quanta)) + " quanta at a step of " +
                          detail::number(refusal.wide_step) + " units: more than the 65535 that " +
                          "16-bit deltas hold";
    if (refusal.wide_step < first_step && refusal.thin_known) {
      problem += "; the step is that fine because hull " + std::to_string(refusal.thin_hull) +
                 " of level " + std::to_string(refusal.thin_level) + ", at " +
                 detail::point(refusal.thin_at) + ", " + detail::number(refusal.thin_thickness) +
                 " units thick, is thinner or smaller than a coarser step keeps a polygon within "
                 "the required precision of " +
                 detail::number(bound) + " units; cook it with a larger tau" +
                 // --simplify bounds the traced outline's error [px]: images only.
                 (asset.image_width > 0 ? ", a larger --simplify" : "") +
                 // Every hull at least twice the first step wide keeps a polygon at that step
                 // (stop 55's sweep: the advice said "a weld" where the default one was on, and a
                 // weld above this hull's thickness left the next thin hull).
                 " or a weld of " + detail::number(rounded_up(2.0 * first_step)) +
                 " or more, twice the coarser step (--weld, with tau above 0: a piece thinner "
                 "than the weld is merged into a neighbour or given a hull that wide, within "
                 "tau), or write glTF (.glb), which stores that hull if 32-bit floats resolve it";
    } else {
      problem += " within the required precision of " + detail::number(bound) +
                 " units; cook it with a larger tau, or write glTF (.glb), which stores any hull "
                 "that 32-bit floats resolve";
    }
    bundle_asset_error(asset, problem);
  }
  bundle_asset_error(asset, "a hull is too thin to be stored as a convex polygon within " +
                                std::to_string(bound) + " output units");
}

}  // namespace hullcook
