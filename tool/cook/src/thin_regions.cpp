// Refusing input regions that no decomposition could cut within the output's contract: slivers,
// and walls or necks no thicker than twice the sliver width (refuse_sliver_regions, contract.h).
#include "cell_grid.h"
#include "contract_text.h"
#include "point_tree.h"

#include "hullcook/cook/contract.h"
#include "hullcook/core/buckets.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/parallel_for.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace hullcook {
namespace {

using detail::number;
using detail::point;

// A wall between two rings of a region (a hole and the outer ring, or two holes) no thicker than
// twice the sliver width of the edge it stands on. The vertex nearest the edge is a notch, and the
// diagonals that resolve it (Algorithm 4.2 cuts between vertices) point into the wall: only the
// edge's ends are there to reach, and the triangle they leave, of area |edge| t / 2 for a wall t
// thick, is a sliver by the contract (issue 19's fuzzing: a hole vertex 1.2e-9 above a 0.76 long
// edge, whose sliver width is 7.6e-10). At the contract's resolution the rings touch. Described
// as "hole 1 comes within D of the outer boundary at (x, y): a wall up to W thick there is
// thinner than the output's contract resolves" (W, the limit, was read as the wall's thickness).
// A ring that comes that near itself (a vertex near an edge it is not an end of, unless that is
// only the length of the edge between them) is a spike or a neck no wider than that: issue 19's
// fuzzing found a spike 6e7 long and 1.2 wide beside a longer one that set the slack to 0.83;
// every piece holding its tip was a sliver. At the contract's resolution its sides touch.
// Beyond this many pairs of corners sharing a cell per corner, the grid's cells test too many.
constexpr double kCrowdedCornerPairs = 64.0;

std::optional<std::string> thin_wall_defect(const Region& region, double slack) {
  std::vector<const Ring*> rings{&region.outer};
  for (const Ring& hole : region.holes) rings.push_back(&hole);
  struct Corner {
    Vec2 point;
    std::size_t ring;
    std::size_t index;  // in its ring
  };
  std::vector<Corner> corners;
  std::size_t corner_count = 0;
  for (const Ring* ring : rings) corner_count += ring->size();
  corners.reserve(corner_count);
  double longest = 0.0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      corners.push_back({ring[i], r, i});
      longest = std::max(longest, glm::length(ring[(i + 1) % ring.size()] - ring[i]));
    }
  }
  auto thickest_refused = [&](double edge_length) {
    return 2.0 * std::max(slack, 1e-9 * edge_length);
  };
  Vec2 low = region.outer.front(), high = low;
  for (Vec2 p : region.outer) low = glm::min(low, p), high = glm::max(high, p);
  const detail::CellGrid grid(low, high, corners.size());
  Buckets<std::size_t> buckets;
  buckets.build(grid.cells(), [&](auto&& add) {
    for (std::size_t c = 0; c < corners.size(); ++c) {
      add(grid.cell(grid.column(corners[c].point.x), grid.row(corners[c].point.y)), c);
    }
  });
  const double margin = thickest_refused(longest) + 1e-6 * grid.cell_size();
  auto ring_name = [](std::size_t r) {
    return r == 0 ? std::string("the outer boundary") : "hole " + std::to_string(r);
  };
  // Corners crowded into a few cells (a star's core, which every spike passes by) make the
  // cells' tests quadratic: then a k-d tree finds each edge's near corners, and of its defects the
  // one the cells would have met first is reported.
  double crowding = 0.0;
  for (std::size_t cell = 0; cell < grid.cells(); ++cell) {
    const double count = double(buckets.end(cell) - buckets.begin(cell));
    crowding += count * count;
  }
  std::vector<Vec2> corner_points;
  std::optional<detail::PointTree> tree;
  if (crowding > kCrowdedCornerPairs * double(corners.size())) {
    corner_points.reserve(corners.size());
    for (const Corner& corner : corners) corner_points.push_back(corner.point);
    tree.emplace(corner_points);
  }
  const double largest = largest_coordinate(corner_points);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const double limit = thickest_refused(glm::length(b - a));
      auto defect_at = [&](std::size_t c) -> std::optional<std::string> {
        const Corner& corner = corners[c];
        const std::size_t n = ring.size(), j = (i + 1) % n;
        if (corner.ring == r) {
          if (corner.index == i || corner.index == j) return std::nullopt;
          const SegmentProjection nearest = project_on_segment(corner.point, a, b);
          // Nearest at the end it shares an edge with: that edge's length, not a wall.
          if (nearest.along == 0.0 && corner.index == (i + n - 1) % n) return std::nullopt;
          if (nearest.along == 1.0 && corner.index == (j + 1) % n) return std::nullopt;
          if (nearest.distance > limit) return std::nullopt;
          return ring_name(r) + " comes within " + number(nearest.distance) + " of itself at " +
                 point(corner.point) + ": a spike or neck up to " + number(limit) +
                 " wide there is thinner than the output's contract resolves";
        }
        const double wall = point_segment_distance(corner.point, a, b);
        if (wall > limit) return std::nullopt;
        // Named from a hole's side: it comes near the outer boundary or another hole.
        const std::size_t hole = corner.ring == 0 ? r : corner.ring;
        const std::size_t other = corner.ring == 0 ? 0 : r;
        return ring_name(hole) + " comes within " + number(wall) + " of " + ring_name(other) +
               " at " + point(corner.point) + ": a wall up to " + number(limit) +
               " thick there is thinner than the output's contract resolves";
      };
      std::optional<std::string> defect;
      if (!tree) {
        grid.for_each_cell(a, b, margin, [&](std::size_t cell) {
          for (const std::size_t* c = buckets.begin(cell); c != buckets.end(cell) && !defect; ++c) {
            defect = defect_at(*c);
          }
        });
      } else {
        // The cells' order: by row, then column, then corner.
        std::tuple<int, int, std::size_t> first{0, 0, 0};
        tree->for_each_near(a, b, margin, 1e-9 * largest, [&](std::size_t c) {
          const Vec2 p = corners[c].point;
          const std::tuple<int, int, std::size_t> order{grid.row(p.y), grid.column(p.x), c};
          if (defect && order >= first) return;
          if (std::optional<std::string> found = defect_at(c))
            defect = std::move(found), first = order;
        });
      }
      if (defect) return defect;
    }
  }
  return std::nullopt;
}

// When the slack comes from the coordinates' distance from the origin (a thousandth of the
// largest) rather than from the outline's size, a region refused as too thin is one that moving
// nearer the origin would let through: the message says so (a Koch curve 1e-3 across at 1e9).
std::string far_from_origin_hint(detail::CoordinateReach reach, double slack) {
  if (!(slack > 1e-9 * reach.extent)) return "";
  return "; its coordinates reach " + number(reach.largest) +
         ", where the contract's slack for rounding is " + number(slack) +
         ": move it nearer the origin";
}

}  // namespace

void refuse_sliver_regions(const std::vector<Region>& outline, const std::string& source,
                           std::size_t first_region_number, unsigned threads) {
  if (outline.empty()) return;
  const detail::CoordinateReach reach = detail::coordinate_reach(outline);
  const double slack = detail::slack_for(reach);
  // Each region on its own; the first error by region is the one thrown, whatever the threads.
  parallel_for(
      outline.size(), threads,
      [&](std::size_t r, unsigned) {
        std::optional<std::string> defect = detail::sliver_defect(outline[r], slack);
        if (!defect) defect = thin_wall_defect(outline[r], slack);
        if (defect) {
          throw InputError(source + ": region " + std::to_string(first_region_number + r) +
                           " is too thin to cut into pieces within the output's contract (" +
                           *defect + ")" + far_from_origin_hint(reach, slack));
        }
      },
      kRegionsWorthAThread);
}

}  // namespace hullcook
