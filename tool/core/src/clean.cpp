#include "hullcook/core/clean.h"

#include "crossing_sweep.h"
#include "hullcook/core/buckets.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/parallel_for.h"
#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace hullcook {

void remove_degenerate_vertices_in_place(Ring& ring) {
  // The kept prefix ring[0, kept) never overtakes the vertex being read.
  std::size_t kept = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Vec2 p = ring[k];
    while (kept >= 2 && detail::fast_orient2d(ring[kept - 2], ring[kept - 1], p) == 0.0) --kept;
    if (kept > 0 && ring[kept - 1] == p) continue;
    ring[kept++] = p;
  }
  ring.resize(kept);
  Ring& out = ring;
  // The closing edge: drop vertices that are repeated or collinear across the seam.
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    if (out.back() == out.front()) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(out[out.size() - 2], out.back(), out.front()) == 0.0) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(out.back(), out[0], out[1]) == 0.0) {
      out.erase(out.begin());
      changed = true;
    }
  }
  if (out.size() == 2 && out[0] == out[1]) out.pop_back();
}

Ring remove_degenerate_vertices(const Ring& ring) {
  Ring out = ring;
  remove_degenerate_vertices_in_place(out);
  return out;
}

namespace {

std::string format_number(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

std::string format_point(Vec2 p) {
  char buffer[80];
  std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g)", p.x, p.y);
  return buffer;
}

using detail::RingEdge;
using Edge = RingEdge;

struct Crossing {
  const Edge* first;
  const Edge* second;
};

// A uniform grid over the edges in which each edge is entered in the cells its segment passes
// through: entered in every cell of its box, the edges of a zigzag of long diagonal teeth nearly
// all shared every cell, and validation was cubic.
class EdgeGrid {
 public:
  explicit EdgeGrid(const std::vector<Edge>& edges) {
    double min_x = edges[0].a.x, max_x = min_x, min_y = edges[0].a.y, max_y = min_y;
    for (const Edge& e : edges) {
      min_x = std::min(min_x, e.a.x);
      max_x = std::max(max_x, e.a.x);
      min_y = std::min(min_y, e.a.y);
      max_y = std::max(max_y, e.a.y);
    }
    side_ = static_cast<int>(std::clamp<std::size_t>(
        static_cast<std::size_t>(std::sqrt(double(edges.size()))), 1, 1024));
    x_ = Axis(min_x, max_x, side_);
    y_ = Axis(min_y, max_y, side_);
    // The cells a segment passes through are about as many as it is long in cells, across and
    // down: when the edges are long (the spikes of a star) the grid alone is superlinear.
    double entries = 0.0;
    for (const Edge& e : edges) {
      entries += std::abs(x_.cell_coordinate(e.b.x) - x_.cell_coordinate(e.a.x)) +
                 std::abs(y_.cell_coordinate(e.b.y) - y_.cell_coordinate(e.a.y)) + 1.0;
    }
    entries_ = entries;
    dense_ = entries > kEntriesPerEdge * double(edges.size());
    if (!dense_) build(edges);
  }

  // Enters the edges in their cells (the constructor leaves a dense grid empty).
  void build(const std::vector<Edge>& edges) {
    cells_.build(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_),
                 [&](auto&& add) {
                   for (std::size_t i = 0; i < edges.size(); ++i) {
                     for_each_cell(edges[i], [&](std::size_t cell) { add(cell, i); });
                   }
                 });
  }

  // Calls visit(cell) for each cell that the segment of e passes through or comes within
  // kMargin cells of. The cell coordinates of the end points are exact to about 1e-12 cells
  // (a few roundings of numbers at most side_ <= 1024), and so is each row's span of the
  // segment: the margin, a thousand times that, makes the cells a superset of those the exact
  // segment meets, so two edges that meet share the cell of their meeting point. Computed from
  // the grid's corner in cells (unlike RegionView's widening, in input units), the bound holds
  // however far the coordinates are from the origin.
  template <typename Visit>
  void for_each_cell(const Edge& e, Visit&& visit) const {
    double ax = x_.cell_coordinate(e.a.x), ay = y_.cell_coordinate(e.a.y);
    double bx = x_.cell_coordinate(e.b.x), by = y_.cell_coordinate(e.b.y);
    if (ay > by) std::swap(ax, bx), std::swap(ay, by);
    const int row0 = index(ay - kMargin), row1 = index(by + kMargin);
    for (int row = row0; row <= row1; ++row) {
      double low = std::min(ax, bx), high = std::max(ax, bx);
      if (by > ay) {
        auto x_at = [&](double y) {
          return ax + std::clamp((y - ay) / (by - ay), 0.0, 1.0) * (bx - ax);
        };
        const double u = x_at(row - kMargin), w = x_at(row + 1 + kMargin);
        low = std::min(u, w), high = std::max(u, w);
      }
      const std::size_t first = static_cast<std::size_t>(row) * static_cast<std::size_t>(side_);
      for (int column = index(low - kMargin); column <= index(high + kMargin); ++column) {
        visit(first + static_cast<std::size_t>(column));
      }
    }
  }

  // Whether its edges are too long for a grid to pay (and it was not built, yet).
  bool dense() const { return dense_; }
  // About how many entries its cells hold (or would, built).
  double entries() const { return entries_; }

  // The pairs of edges that share a cell, counted once per cell they share.
  double pairs_sharing_cells() const {
    double pairs = 0.0;
    for (std::size_t cell = 0; cell < std::size_t(side_) * std::size_t(side_); ++cell) {
      const double count = double(end(cell) - begin(cell));
      pairs += count * (count - 1.0) / 2.0;
    }
    return pairs;
  }

  // The edges entered in a cell, in increasing order.
  const std::size_t* begin(std::size_t cell) const { return cells_.begin(cell); }
  const std::size_t* end(std::size_t cell) const { return cells_.end(cell); }

 private:
  static constexpr double kMargin = 1e-9;
  static constexpr double kEntriesPerEdge = 16.0;

  // Maps a coordinate to [0, side] in cells.
  struct Axis {
    Axis() = default;
    Axis(double low, double high, int cells) : min(low), side(cells) {
      // Halving is exact for coordinates this large, and keeps the extent finite.
      if (!std::isfinite(high - low)) half = 0.5;
      extent = std::max(half * high - half * low, 1e-300);
    }
    double cell_coordinate(double v) const { return (half * v - half * min) / extent * side; }
    double min = 0.0, extent = 1.0, half = 1.0;
    int side = 1;
  };

  int index(double cell_coordinate) const {
    if (!(cell_coordinate > 0.0)) return 0;
    if (cell_coordinate >= side_ - 1.0) return side_ - 1;
    return static_cast<int>(cell_coordinate);
  }

  int side_ = 1;
  bool dense_ = false;
  double entries_ = 0.0;
  Axis x_, y_;
  Buckets<std::size_t> cells_;  // the edges entered in each cell
};

// Beyond this many pairs per edge sharing grid cells, the sweep is faster than the grid.
constexpr double kGridPairsPerEdge = 128.0;
// Naming the first of the crossings the sweep found costs the grid's time: within these many
// entries and pair tests per edge (and a million more tests), else the sweep's crossing is named.
constexpr double kNamingEntriesPerEdge = 128.0;
constexpr double kNamingPairsPerEdge = 256.0;

// The first crossing in (ring, index) order: the first edge that meets a non-adjacent edge, and
// the first edge it meets. Each pair that shares a cell is tested once. (Where the edges are so
// long and crowded that finding the first would take seconds, the sweep's crossing instead.)
std::optional<Crossing> find_crossing(const std::vector<Edge>& edges,
                                      const std::vector<std::size_t>& ring_sizes) {
  auto boxes_apart = [](const Edge& e, const Edge& f) {
    return std::max(f.a.x, f.b.x) < std::min(e.a.x, e.b.x) ||
           std::min(f.a.x, f.b.x) > std::max(e.a.x, e.b.x) ||
           std::max(f.a.y, f.b.y) < std::min(e.a.y, e.b.y) ||
           std::min(f.a.y, f.b.y) > std::max(e.a.y, e.b.y);
  };
  // A few edges (a piece that the output contract checks is often a handful): every pair costs
  // less than building the grid.
  if (edges.size() <= 32) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const Edge& e = edges[i];
        const Edge& f = edges[j];
        if (boxes_apart(e, f) || detail::consecutive(e, f, ring_sizes)) continue;
        if (segments_intersect(e.a, e.b, f.a, f.b)) return Crossing{&e, &f};
      }
    }
    return std::nullopt;
  }
  EdgeGrid grid(edges);
  // Long edges side by side (a star's spikes, a comb's teeth) share cells by the thousand, and
  // testing every pair that shares one is quadratic: then the sweep decides, in O(n log n), and
  // the grid is built to name the first crossing only when there is one.
  const double n = double(edges.size());
  std::optional<Crossing> swept;
  if (grid.dense() || grid.pairs_sharing_cells() > kGridPairsPerEdge * n) {
    const auto pair = detail::find_crossing_by_sweep(edges, ring_sizes);
    if (!pair) return std::nullopt;
    swept = Crossing{&edges[pair->first], &edges[pair->second]};
    if (grid.entries() > kNamingEntriesPerEdge * n) return swept;
  }
  if (grid.dense()) grid.build(edges);
  // Pair tests left before the sweep's crossing is named instead of the first.
  double tests_left = kNamingPairsPerEdge * n + double(1 << 20);
  // tested_with[j] == i: the pair (i, j) was tested in an earlier cell of edge i.
  std::vector<std::size_t> tested_with(edges.size(), edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    std::size_t second = edges.size();
    grid.for_each_cell(e, [&](std::size_t cell) {
      // Entries are in increasing order: the pairs with an earlier edge were tested from it.
      for (const std::size_t* k = std::upper_bound(grid.begin(cell), grid.end(cell), i);
           k != grid.end(cell) && *k < second; ++k) {
        const std::size_t j = *k;
        if (tested_with[j] == i) continue;
        tested_with[j] = i;
        tests_left -= 1.0;
        const Edge& f = edges[j];
        if (boxes_apart(e, f) || detail::consecutive(e, f, ring_sizes)) continue;
        if (segments_intersect(e.a, e.b, f.a, f.b)) second = j;
      }
    });
    if (second < edges.size()) return Crossing{&e, &edges[second]};
    if (swept && tests_left < 0.0) return swept;
  }
  return swept;
}

struct Box {
  double min_x, min_y, max_x, max_y;
  bool overlaps(const Box& o) const {
    return min_x <= o.max_x && o.min_x <= max_x && min_y <= o.max_y && o.min_y <= max_y;
  }
};

Box box_of(const Ring& ring) {
  Box box{ring[0].x, ring[0].y, ring[0].x, ring[0].y};
  for (Vec2 p : ring) {
    box.min_x = std::min(box.min_x, p.x);
    box.max_x = std::max(box.max_x, p.x);
    box.min_y = std::min(box.min_y, p.y);
    box.max_y = std::max(box.max_y, p.y);
  }
  return box;
}

// Calls visit(a, b) for each pair a < b of boxes that overlap, in ascending (a, b) order, as the
// loop over every pair does, so that a visit that throws names the same pair; but finds each a's
// partners through a grid of the boxes (about one cell per box), where every pair's boxes took
// 30 s on an image of 180,000 holes. A box that spans more than kCellsPerBox cells is not filed:
// it is compared with every box, and every box with it, as before. Nothing is kept beyond one
// a's partners (collecting every pair first took 4.25 GB for 20,000 nested holes, whose first
// pair was the bad one).
template <typename Visit>
void for_each_overlapping_box_pair(const std::vector<Box>& boxes, Visit visit) {
  constexpr std::size_t kCellsPerBox = 16;
  const std::size_t n = boxes.size();
  if (n < 2) return;
  Box bounds = boxes[0];
  for (const Box& box : boxes) {
    bounds.min_x = std::min(bounds.min_x, box.min_x);
    bounds.max_x = std::max(bounds.max_x, box.max_x);
    bounds.min_y = std::min(bounds.min_y, box.min_y);
    bounds.max_y = std::max(bounds.max_y, box.max_y);
  }
  const std::size_t side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double width = (bounds.max_x - bounds.min_x) / static_cast<double>(side);
  const double height = (bounds.max_y - bounds.min_y) / static_cast<double>(side);
  // Monotone in the coordinate, so boxes that overlap share a cell.
  auto cell_of = [&](double v, double low, double size) -> std::size_t {
    const double cell = size > 0.0 ? std::floor((v - low) / size) : 0.0;
    if (!(cell > 0.0)) return 0;
    return std::min(side - 1, static_cast<std::size_t>(std::min(cell, 1e18)));
  };
  struct Span {
    std::size_t x0, x1, y0, y1;
    bool filed() const { return (x1 - x0 + 1) * (y1 - y0 + 1) <= kCellsPerBox; }
  };
  std::vector<Span> spans(n);
  std::vector<std::size_t> unfiled;  // the boxes of too many cells, ascending
  for (std::size_t i = 0; i < n; ++i) {
    spans[i] = {cell_of(boxes[i].min_x, bounds.min_x, width),
                cell_of(boxes[i].max_x, bounds.min_x, width),
                cell_of(boxes[i].min_y, bounds.min_y, height),
                cell_of(boxes[i].max_y, bounds.min_y, height)};
    if (!spans[i].filed()) unfiled.push_back(i);
  }
  Buckets<std::size_t> cells;
  cells.build(side * side, [&](auto&& add) {
    for (std::size_t i = 0; i < n; ++i) {
      const Span& span = spans[i];
      if (!span.filed()) continue;
      for (std::size_t y = span.y0; y <= span.y1; ++y) {
        for (std::size_t x = span.x0; x <= span.x1; ++x) add(y * side + x, i);
      }
    }
  });
  std::vector<std::size_t> partners;
  for (std::size_t a = 0; a < n; ++a) {
    partners.clear();
    const Span& span = spans[a];
    if (!span.filed()) {
      for (std::size_t b = a + 1; b < n; ++b) partners.push_back(b);
    } else {
      for (std::size_t y = span.y0; y <= span.y1; ++y) {
        for (std::size_t x = span.x0; x <= span.x1; ++x) {
          for (const std::size_t* b = cells.begin(y * side + x); b != cells.end(y * side + x);
               ++b) {
            if (*b > a) partners.push_back(*b);
          }
        }
      }
      for (std::size_t b : unfiled) {
        if (b > a) partners.push_back(b);
      }
      std::sort(partners.begin(), partners.end());
      partners.erase(std::unique(partners.begin(), partners.end()), partners.end());
    }
    for (std::size_t b : partners) {
      if (boxes[a].overlaps(boxes[b])) visit(a, b);
    }
  }
}

// Above this many holes, their first vertices are located in the outer ring by a RingLocator.
constexpr std::size_t kHolesWorthALocator = 16;

constexpr double kLargestCoordinate = 1e150;
// Below it the orientation predicates' products of coordinate differences reach the subnormal
// range, where their exact error terms round away: a ring that small decomposed into different,
// and below about 1e-155 invalid, pieces than the same ring scaled up.
constexpr double kSmallestSpan = 1e-140;

}  // namespace

void refuse_tiny_rings(const std::vector<Region>& regions, std::string_view source) {
  for (std::size_t r = 0; r < regions.size(); ++r) {
    auto check = [&](const Ring& ring, const std::string& name) {
      if (ring.empty()) return;
      const Box box = box_of(ring);
      const double span = std::max(box.max_x - box.min_x, box.max_y - box.min_y);
      if (span > 0.0 && span < kSmallestSpan) {
        throw InputError(std::string(source) + ": region " + std::to_string(r + 1) + " " + name +
                         ": too small: it spans " + format_number(span) +
                         " (less than 1e-140), beyond the precision of its orientation tests; "
                         "scale its coordinates up");
      }
    };
    check(regions[r].outer, "outer boundary");
    for (std::size_t h = 0; h < regions[r].holes.size(); ++h) {
      check(regions[r].holes[h], "hole " + std::to_string(h + 1));
    }
  }
}

std::vector<Region> clean_and_validate(std::vector<Region> regions, std::string_view source,
                                       unsigned threads) {
  const std::string file(source);
  if (regions.empty()) throw InputError(file + ": no polygon");
  // Each region on its own; the first error by region is the one thrown, whatever the threads.
  parallel_for(
      regions.size(), threads,
      [&](std::size_t r, unsigned) {
        Region& region = regions[r];
        const std::string region_name = "region " + std::to_string(r + 1);
        auto ring_name = [&](int ring) {
          return ring == 0 ? region_name + " outer boundary"
                           : region_name + " hole " + std::to_string(ring);
        };
        auto fail = [&](const std::string& problem) -> void {
          throw InputError(file + ": " + problem);
        };
        // Only finite points are oriented: a ring with another fails before its first test.
        const detail::CoordinateBound coordinate_bound(detail::max_abs_coordinate(region));
        auto clean_ring = [&](Ring& ring, int ring_index) {
          for (std::size_t i = 0; i < ring.size(); ++i) {
            if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y)) {
              fail(ring_name(ring_index) + ": vertex " + std::to_string(i + 1) +
                   " has a NaN or infinite coordinate");
            }
            // Beyond it the orientation predicates' products overflow.
            if (std::abs(ring[i].x) > kLargestCoordinate ||
                std::abs(ring[i].y) > kLargestCoordinate) {
              fail(ring_name(ring_index) + ": vertex " + std::to_string(i + 1) +
                   " has a coordinate too large (beyond 1e150 in magnitude)");
            }
          }
          remove_degenerate_vertices_in_place(ring);
          if (ring.size() < 3) {
            fail(ring_name(ring_index) +
                 ": fewer than 3 distinct points after removing repeated and collinear vertices");
          }
          // Zero area with 3 non-collinear points means the ring meets itself: reported below. Once
          // the rings are known to be simple, their orientation is settled exactly.
          const double area = signed_area(ring);
          const bool want_ccw = ring_index == 0;
          if (area != 0.0 && (area > 0.0) != want_ccw) std::reverse(ring.begin(), ring.end());
        };
        clean_ring(region.outer, 0);
        for (std::size_t h = 0; h < region.holes.size(); ++h) {
          clean_ring(region.holes[h], static_cast<int>(h + 1));
        }

        std::vector<Edge> edges;
        std::vector<std::size_t> ring_sizes;
        std::size_t edge_count = region.outer.size();
        for (const Ring& hole : region.holes) edge_count += hole.size();
        edges.reserve(edge_count);
        ring_sizes.reserve(1 + region.holes.size());
        auto add_edges = [&](const Ring& ring, int ring_index) {
          ring_sizes.push_back(ring.size());
          for (std::size_t i = 0; i < ring.size(); ++i) {
            edges.push_back({ring_index, i, ring[i], ring[(i + 1) % ring.size()]});
          }
        };
        add_edges(region.outer, 0);
        for (std::size_t h = 0; h < region.holes.size(); ++h) {
          add_edges(region.holes[h], static_cast<int>(h + 1));
        }
        if (const auto crossing = find_crossing(edges, ring_sizes)) {
          const Edge& e = *crossing->first;
          const Edge& f = *crossing->second;
          const std::string where = " (edge " + format_point(e.a) + "-" + format_point(e.b) +
                                    " meets edge " + format_point(f.a) + "-" + format_point(f.b) +
                                    ")";
          if (e.ring == f.ring) {
            fail(ring_name(e.ring) + ": self-intersection" + where);
          } else if (e.ring == 0) {
            fail(ring_name(f.ring) + " crosses or touches the outer boundary" + where);
          } else {
            fail(region_name + ": holes " + std::to_string(e.ring) + " and " +
                 std::to_string(f.ring) + " cross or touch" + where);
          }
        }
        auto orient_exactly = [&](Ring& ring, int ring_index) {
          const int turn = ring_orientation(ring);
          if (turn == 0) fail(ring_name(ring_index) + ": zero area");
          if ((turn > 0) != (ring_index == 0)) std::reverse(ring.begin(), ring.end());
        };
        orient_exactly(region.outer, 0);
        for (std::size_t h = 0; h < region.holes.size(); ++h) {
          orient_exactly(region.holes[h], static_cast<int>(h + 1));
        }
        // No boundaries meet, so one vertex decides containment.
        std::vector<Box> boxes;
        // Locating 180,000 holes' first vertices in a checkerboard's outer ring of 4,800 edges
        // by scans of the whole ring took 20 s.
        std::optional<RingLocator> outer;
        if (region.holes.size() > kHolesWorthALocator) outer.emplace(region.outer);
        for (std::size_t h = 0; h < region.holes.size(); ++h) {
          const Ring& hole = region.holes[h];
          if ((outer ? outer->locate(hole[0]) : locate_point(region.outer, hole[0])) !=
              Location::inside) {
            fail(ring_name(static_cast<int>(h + 1)) + " is outside the outer boundary");
          }
          boxes.push_back(box_of(hole));
        }
        for_each_overlapping_box_pair(boxes, [&](std::size_t a, std::size_t b) {
          if (locate_point(region.holes[b], region.holes[a][0]) == Location::inside ||
              locate_point(region.holes[a], region.holes[b][0]) == Location::inside) {
            fail(region_name + ": holes " + std::to_string(a + 1) + " and " +
                 std::to_string(b + 1) + " overlap");
          }
        });
      },
      kRegionsWorthAThread);
  return regions;
}

}  // namespace hullcook
