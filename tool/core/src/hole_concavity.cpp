#include "hole_concavity.h"

#include "hullcook/core/buckets.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace hullcook::detail {
namespace {

std::pair<std::size_t, std::size_t> principal_axis_extremes(const Ring& hole) {
  Vec2 mean{0.0, 0.0};
  for (Vec2 p : hole) mean += p;
  mean /= double(hole.size());
  double xx = 0.0, xy = 0.0, yy = 0.0;
  for (Vec2 p : hole) {
    const Vec2 d = p - mean;
    xx += d.x * d.x;
    xy += d.x * d.y;
    yy += d.y * d.y;
  }
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
  const Vec2 axis{std::cos(angle), std::sin(angle)};
  std::size_t low = 0, high = 0;
  double low_value = std::numeric_limits<double>::infinity(), high_value = -low_value;
  for (std::size_t i = 0; i < hole.size(); ++i) {
    const double v = (hole[i].x - mean.x) * axis.x + (hole[i].y - mean.y) * axis.y;
    if (v < low_value) low_value = v, low = i;
    if (v > high_value) high_value = v, high = i;
  }
  return {low, high};
}

// Squared distances decide which vertices need the exact distance: a vertex whose squared
// distance exceeds the smallest seen by this relative margin cannot be the closest (rounding is a
// few ulps), provided no square overflows or loses precision to underflow.
constexpr double kSquaredMargin = 1.0 + 1e-9;
bool squares_are_accurate(double squared) { return squared > 1e-200 && squared < 1e200; }

// The closest vertex to point on ring ring_id, by a scan.
void scan_ring(const Ring& ring, int ring_id, Vec2 point, NearVertex& best) {
  // The squared distance beyond which a vertex is farther than the best (infinity: not known).
  auto limit_of = [](double bound) {
    return bound > 1e-100 && bound < 1e100 ? bound * bound * kSquaredMargin
                                           : std::numeric_limits<double>::infinity();
  };
  double limit = limit_of(best.distance);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 offset = ring[i] - point;
    if (offset.x * offset.x + offset.y * offset.y > limit) continue;
    best.offer(distance(ring[i], point), ring_id, i);
    limit = limit_of(best.distance);
  }
}

// The closest vertex to point on every ring but skip_ring, by a scan.
NearVertex nearest_by_scan(const Region& region, Vec2 point, int skip_ring) {
  NearVertex best;
  scan_ring(region.outer, 0, point, best);
  for (std::size_t o = 0; o < region.holes.size(); ++o) {
    const int ring_id = static_cast<int>(o + 1);
    if (ring_id != skip_ring) scan_ring(region.holes[o], ring_id, point, best);
  }
  return best;
}

// Every vertex of a region in a uniform grid of square cells, for Eq. 5's nearest-vertex searches
// (each hole's two ends against all the other rings).
class VertexGrid {
 public:
  // Out of line: whether GCC inlines it into evaluate() flips with unrelated edits of this file,
  // and inlined it ran more instructions.
  [[gnu::noinline]] explicit VertexGrid(const Region& region) {
    std::size_t count = region.outer.size();
    for (const Ring& hole : region.holes) count += hole.size();
    // The holes lie inside the outer ring, so its box holds every vertex.
    double max_x = region.outer[0].x, max_y = region.outer[0].y;
    min_x_ = max_x, min_y_ = max_y;
    for (Vec2 p : region.outer) {
      min_x_ = std::min(min_x_, p.x), max_x = std::max(max_x, p.x);
      min_y_ = std::min(min_y_, p.y), max_y = std::max(max_y, p.y);
    }
    // About one vertex per cell if they were spread evenly over the box.
    const double width = max_x - min_x_, height = max_y - min_y_;
    cell_size_ = std::sqrt(width * height / static_cast<double>(count));
    if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) cell_size_ = std::max(width, height);
    if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) return;  // no grid: scans only
    columns_ = static_cast<int>(std::clamp(width / cell_size_, 0.0, 1023.0)) + 1;
    rows_ = static_cast<int>(std::clamp(height / cell_size_, 0.0, 1023.0)) + 1;
    scale_ = 1.0 / cell_size_;
    cells_.build(static_cast<std::size_t>(columns_ * rows_), [&](auto&& add) {
      auto file_ring = [&](const Ring& ring, int ring_id) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Vec2 p = ring[i];
          add(static_cast<std::size_t>(row_of(p.y) * columns_ + column_of(p.x)),
              Entry{p, ring_id, i});
        }
      };
      file_ring(region.outer, 0);
      for (std::size_t h = 0; h < region.holes.size(); ++h) {
        file_ring(region.holes[h], static_cast<int>(h + 1));
      }
    });
  }

  // The closest vertex to point on the rings that searched(ring id) takes, as a scan finds it;
  // nullopt where squared distances could mislead (then scan).
  template <typename Searched>
  std::optional<NearVertex> nearest(Vec2 point, Searched&& searched) const {
    if (cells_.bucket_count() == 0) return std::nullopt;
    const int column = column_of(point.x), row = row_of(point.y);
    NearVertex best;
    double best_squared = std::numeric_limits<double>::infinity();
    auto visit_cell = [&](int x, int y) {
      const std::size_t cell = static_cast<std::size_t>(y * columns_ + x);
      for (const Entry* k = cells_.begin(cell); k != cells_.end(cell); ++k) {
        const Entry& entry = *k;
        if (!searched(entry.ring)) continue;
        const Vec2 offset = entry.point - point;
        const double squared = offset.x * offset.x + offset.y * offset.y;
        if (squared > best_squared * kSquaredMargin) continue;
        best_squared = std::min(best_squared, squared);
        best.offer(distance(entry.point, point), entry.ring, entry.index);
      }
    };
    // Square layers of cells around point's cell. After layer L every vertex left lies more than
    // L cells away in x or y; one cell less covers the rounding of the cell assignment.
    for (int layer = 0;; ++layer) {
      const int x0 = column - layer, x1 = column + layer, y0 = row - layer, y1 = row + layer;
      if (x0 < 0 && y0 < 0 && x1 >= columns_ && y1 >= rows_) break;
      const int clipped_x0 = std::max(x0, 0), clipped_x1 = std::min(x1, columns_ - 1);
      if (y0 >= 0) {
        for (int x = clipped_x0; x <= clipped_x1; ++x) visit_cell(x, y0);
      }
      if (y1 < rows_ && y1 != y0) {
        for (int x = clipped_x0; x <= clipped_x1; ++x) visit_cell(x, y1);
      }
      for (int y = std::max(y0 + 1, 0); y <= std::min(y1 - 1, rows_ - 1); ++y) {
        if (x0 >= 0) visit_cell(x0, y);
        if (x1 < columns_ && x1 != x0) visit_cell(x1, y);
      }
      const double reach = (layer - 1) * cell_size_;
      if (reach > 0.0 && reach * reach > best_squared * (1.0 + 1e-6)) break;
    }
    if (!squares_are_accurate(best_squared)) return std::nullopt;
    return best;
  }

 private:
  struct Entry {
    Vec2 point;
    int ring;
    std::size_t index;
  };
  int column_of(double x) const {
    return static_cast<int>(std::clamp((x - min_x_) * scale_, 0.0, columns_ - 1.0));
  }
  int row_of(double y) const {
    return static_cast<int>(std::clamp((y - min_y_) * scale_, 0.0, rows_ - 1.0));
  }
  double min_x_ = 0.0, min_y_ = 0.0, cell_size_ = 0.0, scale_ = 0.0;
  int columns_ = 1, rows_ = 1;
  Buckets<Entry, int> cells_;  // the vertices in each cell (none: no grid)
};

// Eq. 5's closest vertex x for the two ends (p, q) of a hole: the end nearer to a vertex is joined
// first; on a tie, the vertex first in ring order, then p.
HoleConcavity closest_to_ends(std::size_t p, std::size_t q, const NearVertex& from_p,
                              const NearVertex& from_q) {
  const bool take_q = from_q.before(from_p);
  const NearVertex& chosen = take_q ? from_q : from_p;
  HoleConcavity info;
  info.closest_ring = chosen.ring, info.closest = chosen.index;
  info.joined = take_q ? q : p;
  info.far_end = take_q ? p : q;
  return info;
}

constexpr std::size_t kSearchesForVertexGrid = 6;

}  // namespace

std::vector<HoleConcavity> measure_holes(const Region& region, const OuterConcavity& outer,
                                         const std::vector<HoleEnds>& inherited,
                                         std::vector<HoleEnds>& ends) {
  const std::size_t k = region.holes.size();
  std::vector<HoleConcavity> holes(k);
  const double delta = outer.value;
  ends.assign(k, HoleEnds{});
  std::size_t searches = 0;
  for (std::size_t h = 0; h < k; ++h) {
    HoleEnds& hole_ends = ends[h];
    if (inherited.size() == k) hole_ends = inherited[h];
    if (hole_ends.p == kNone) {
      std::tie(hole_ends.p, hole_ends.q) = principal_axis_extremes(region.holes[h]);
    }
    searches += !hole_ends.from_p.known() + !hole_ends.from_q.known();
  }
  // The grid pays for its building from six searches on (three holes without inherited ends);
  // fewer are plain scans.
  std::optional<VertexGrid> grid;
  bool grid_built = false;
  auto vertex_grid = [&]() -> const VertexGrid* {
    if (!grid_built && searches >= kSearchesForVertexGrid) grid.emplace(region);
    grid_built = true;
    return grid ? &*grid : nullptr;
  };
  // Fills nearest, unless known, with the vertex nearest to point on the rings searched takes: by
  // the grid where there is one and it can tell, else by scan(point).
  auto find_nearest = [&](Vec2 point, auto&& searched, auto&& scan, NearVertex& nearest) {
    if (nearest.known()) return;
    if (const VertexGrid* const index = vertex_grid()) {
      if (const auto found = index->nearest(point, searched)) {
        nearest = *found;
        return;
      }
    }
    nearest = scan(point);
  };
  for (std::size_t h = 0; h < k; ++h) {
    const Ring& hole = region.holes[h];
    HoleEnds& hole_ends = ends[h];
    const int hole_ring = static_cast<int>(h + 1);
    auto other_rings = [&](int ring) { return ring != hole_ring; };
    auto scan = [&](Vec2 point) { return nearest_by_scan(region, point, hole_ring); };
    find_nearest(hole[hole_ends.p], other_rings, scan, hole_ends.from_p);
    find_nearest(hole[hole_ends.q], other_rings, scan, hole_ends.from_q);
    holes[h] = closest_to_ends(hole_ends.p, hole_ends.q, hole_ends.from_p, hole_ends.from_q);
  }
  // The closest vertex of ∂P0 alone, where the chain of closest vertices cycles.
  auto outer_fallback = [&](std::size_t h) {
    const Ring& hole = region.holes[h];
    HoleEnds& hole_ends = ends[h];
    auto scan = [&](Vec2 point) {
      NearVertex best;
      scan_ring(region.outer, 0, point, best);
      return best;
    };
    auto outer_only = [](int ring) { return ring == 0; };
    find_nearest(hole[hole_ends.p], outer_only, scan, hole_ends.outer_from_p);
    find_nearest(hole[hole_ends.q], outer_only, scan, hole_ends.outer_from_q);
    return closest_to_ends(hole_ends.p, hole_ends.q, hole_ends.outer_from_p,
                           hole_ends.outer_from_q);
  };
  // Depth through the chain of closest vertices (Fig. 12(b)); a cycle falls back to ∂P0.
  std::vector<int> state(k, 0);  // 0 new, 1 in progress, 2 done
  auto vertex_of = [&](const HoleConcavity& info) {
    return info.closest_ring == 0 ? region.outer[info.closest]
                                  : region.holes[std::size_t(info.closest_ring - 1)][info.closest];
  };
  auto evaluate = [&](auto&& self, std::size_t h) -> double {
    if (state[h] == 2) return holes[h].value;
    state[h] = 1;
    HoleConcavity& info = holes[h];
    if (info.closest_ring != 0 && state[std::size_t(info.closest_ring - 1)] == 1) {
      info = outer_fallback(h);
    }
    const Ring& hole = region.holes[h];
    const std::vector<double>& depth = outer.depth.empty() ? outer.vertex : outer.depth;
    double base = info.closest_ring == 0 ? depth[info.closest]
                                         : self(self, std::size_t(info.closest_ring - 1));
    info.value = base + distance(vertex_of(info), hole[info.joined]) +
                 distance(hole[info.joined], hole[info.far_end]) + delta;
    state[h] = 2;
    return info.value;
  };
  for (std::size_t h = 0; h < k; ++h) evaluate(evaluate, h);
  return holes;
}

}  // namespace hullcook::detail
