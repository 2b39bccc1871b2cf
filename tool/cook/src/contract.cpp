#include "hullcook/cook/contract.h"

#include "cell_grid.h"
#include "contract_text.h"
#include "hull_lines.h"
#include "hullcook/core/parallel_for.h"
#include "outline_distance.h"

#include "hullcook/core/buckets.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

namespace hullcook {
namespace detail {

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string point(Vec2 p) { return "(" + number(p.x) + ", " + number(p.y) + ")"; }

CoordinateReach coordinate_reach(const std::vector<const Ring*>& rings) {
  Vec2 low{std::numeric_limits<double>::infinity()}, high{-std::numeric_limits<double>::infinity()};
  CoordinateReach reach;
  for (const Ring* ring : rings) {
    for (Vec2 p : *ring) {
      low = glm::min(low, p), high = glm::max(high, p);
      reach.largest = std::max({reach.largest, std::abs(p.x), std::abs(p.y)});
    }
  }
  if (low.x <= high.x) reach.extent = std::max(high.x - low.x, high.y - low.y);
  return reach;
}

CoordinateReach coordinate_reach(const std::vector<Region>& outline) {
  std::vector<const Ring*> rings;
  rings.reserve(outline.size());
  for (const Region& region : outline) rings.push_back(&region.outer);
  return coordinate_reach(rings);
}

double slack_for(CoordinateReach reach) {
  return 1e-9 * std::max(reach.extent, 1e-3 * reach.largest);
}

double rounding_slack(const std::vector<Region>& outline) {
  return slack_for(coordinate_reach(outline));
}

// The diagonal of the ring's bounding box: a piece's length, to the sliver test.
double length_of(const Ring& ring) {
  if (ring.empty()) return 0.0;
  Vec2 low = ring.front(), high = low;
  for (Vec2 p : ring) low = glm::min(low, p), high = glm::max(high, p);
  return std::hypot(high.x - low.x, high.y - low.y);
}

// A sliver: zero area but for rounding, thinner than a billionth of its length. Described as
// "area A over a length of L".
std::optional<std::string> sliver_defect(const Region& region, double slack) {
  if (!is_contract_sliver(region, slack)) return std::nullopt;
  return "area " + number(region_area(region)) + " over a length of " +
         number(length_of(region.outer));
}

}  // namespace detail

namespace {

using detail::length_of;
using detail::number;
using detail::point;
using detail::rounding_slack;
using detail::sliver_defect;

// region_area with accurate_twice_area's sums: the shoelace about a vertex rounds by far more
// than a billionth of a long thin piece's area (stop 56: a strip 500,000 units long and 0.001
// wide, in triangles at --max-verts 3, summed 5.2e-7 off its 495, and exited 4).
double accurate_area(const Region& region) { return 0.5 * accurate_twice_area(region); }

// --- The components: valid regions, no slivers. --------------------------------------------

// convex: the component has no hole and is_strictly_convex_ccw. Unless convex, sets cleaned to
// the component without repeated or collinear vertices (what is measured); a convex one is
// measured as it is.
std::optional<std::string> component_defect(const Region& component, bool convex, double slack,
                                            Region& cleaned) {
  try {
    // A convex piece (most of them) is valid by that test; the others are validated whole.
    if (!convex) cleaned = std::move(clean_and_validate({component}, "").front());
  } catch (const InputError& error) {
    // "': region 1 outer boundary: self-intersection ..." names the component's own rings.
    std::string problem = error.what();
    for (const char* prefix : {": region 1: ", ": region 1 ", ": "}) {
      if (problem.starts_with(prefix)) {
        problem.erase(0, std::string(prefix).size());
        break;
      }
    }
    return "its component is not a valid region: " + problem;
  }
  // clean_and_validate orients the rings it cleans: the pieces' own orientation is checked here.
  if (ring_orientation(component.outer) <= 0) {
    return std::string("its component's outer ring is not counter-clockwise");
  }
  for (std::size_t h = 0; h < component.holes.size(); ++h) {
    if (ring_orientation(component.holes[h]) >= 0) {
      return "its component's hole " + std::to_string(h + 1) + " is not clockwise";
    }
  }
  if (const std::optional<std::string> sliver = sliver_defect(component, slack)) {
    return "its component is a sliver: " + *sliver;
  }
  return std::nullopt;
}

// --- The hulls: convex, counter-clockwise, within the engine limits. ------------------------

// Height of vertex i above the line through its neighbours (negative for a reflex turn).
double turn_height(const Ring& ring, std::size_t i) {
  const std::size_t n = ring.size();
  const Vec2 previous = ring[(i + n - 1) % n], next = ring[(i + 1) % n];
  const double base = glm::length(next - previous);
  return base > 0.0 ? cross(next - previous, previous - ring[i]) / base : 0.0;
}

// Why a hull that hull_meets_limits refuses is refused.
std::string limits_defect(const Ring& hull, const EngineLimits& limits) {
  const std::size_t n = hull.size();
  if (limits.max_verts != 0 && n > limits.max_verts) {
    return "its hull has " + std::to_string(n) + " vertices (at most " +
           std::to_string(limits.max_verts) + ")";
  }
  if (limits.keep_inside) {
    for (Vec2 p : hull) {
      if (!limits.keep_inside->holds(p)) {
        return "its hull's vertex " + point(p) + " lies outside the tile " +
               point(limits.keep_inside->low) + " - " + point(limits.keep_inside->high);
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const double apart = glm::length(hull[i] - hull[j]);
      if (apart < limits.weld_distance()) {
        return "its hull's vertices " + point(hull[i]) + " and " + point(hull[j]) + " are " +
               number(apart) + " apart (weld " + number(limits.weld) +
               (limits.rounding > 0
                    ? ", and " + number(limits.rounding) + " for the writers' rounding)"
                    : ")");
      }
    }
  }
  const double collinear = limits.least_turn();
  for (std::size_t i = 0; i < n; ++i) {
    const double height = turn_height(hull, i);
    if (height < collinear) {
      return "its hull's vertex " + point(hull[i]) + " is " + number(height) +
             " from its neighbours' line (at least " + number(collinear) + ")";
    }
  }
  return "its hull does not meet the engine limits";
}

struct HullDefect {
  std::string problem;
  bool convex;  // a convex polygon all the same (only the engine limits are broken)
};

std::optional<HullDefect> hull_defect(const Ring& hull, const EngineLimits& limits) {
  const std::size_t n = hull.size();
  if (n < 3) return HullDefect{"its hull has " + std::to_string(n) + " vertices", false};
  std::size_t left_turns = 0, right_turns = 0, first_other = n;
  // Turning left at every vertex, a polygon that winds k times has 2k changes of vertical
  // direction: once, it is convex.
  std::size_t direction_changes = 0;
  int first_direction = 0, last_direction = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int turn = orientation(hull[(i + n - 1) % n], hull[i], hull[(i + 1) % n]);
    if (turn > 0) {
      ++left_turns;
    } else {
      if (turn < 0) ++right_turns;
      if (first_other == n) first_other = i;
    }
    const double dy = hull[(i + 1) % n].y - hull[i].y;
    const int direction = (dy > 0) - (dy < 0);
    if (direction == 0) continue;
    if (last_direction != 0 && direction != last_direction) ++direction_changes;
    if (first_direction == 0) first_direction = direction;
    last_direction = direction;
  }
  if (last_direction != first_direction) ++direction_changes;
  // No turn either way: every vertex on one line (a glTF node scaled by 0 puts all on a point).
  if (left_turns == 0 && right_turns == 0) {
    return HullDefect{"its hull has no area (its vertices lie on one line)", false};
  }
  if (left_turns == 0) return HullDefect{"its hull is clockwise", false};
  if (first_other < n) {
    return HullDefect{"its hull is not convex at its vertex " + point(hull[first_other]), false};
  }
  if (direction_changes > 2) {
    return HullDefect{"its hull winds " + std::to_string(direction_changes / 2) + " times", false};
  }
  if ((limits.max_verts != 0 || limits.weld > 0 || limits.keep_inside) &&
      !hull_meets_limits(hull, limits)) {
    return HullDefect{limits_defect(hull, limits), true};
  }
  return std::nullopt;
}

// --- Each component within τ of its hull's boundary. ----------------------------------------

// The worst of one kind of fault in a piece: only it is reported.
struct Worst {
  double value = -std::numeric_limits<double>::infinity();
  Vec2 where{0.0, 0.0};
  void offer(double candidate, Vec2 p) {
    if (candidate > value) value = candidate, where = p;
  }
  bool found() const { return value > -std::numeric_limits<double>::infinity(); }
};

// Every point of the component's boundary inside the hull (outside by at most slack) and within
// limit of its boundary.
void check_component_in_hull(const Region& component, const HullLines& lines, double limit,
                             double slack, Worst& outside, Worst& far) {
  auto check_ring = [&](const Ring& ring) {
    const std::size_t n = ring.size();
    // Scratch, reused: this runs for every piece of a cook.
    thread_local std::vector<std::pair<double, std::size_t>> nearest;
    nearest.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      // Consecutive vertices are mostly nearest to one line: the last one's bounds the search.
      nearest[i] = lines.nearest(ring[i], i == 0 ? 0 : nearest[i - 1].second);
      if (nearest[i].first < -slack) outside.offer(-nearest[i].first, ring[i]);
      if (nearest[i].first > limit) far.offer(nearest[i].first, ring[i]);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      if (lines.distance(nearest[i].second, ring[j]) <= limit ||
          lines.distance(nearest[j].second, ring[i]) <= limit ||
          lines.one_within(ring[i], ring[j], limit)) {
        continue;
      }
      const auto [distance, where] = lines.farthest_on(ring[i], ring[j]);
      if (distance > limit) far.offer(distance, where);
    }
  };
  check_ring(component.outer);
  for (const Ring& hole : component.holes) check_ring(hole);
}

// --- Every hull point within τ of the outline. ----------------------------------------------

// A hull vertex by its distance to the outline; a hull edge by OutlineDistance::segment_within,
// which proves it exactly (the points of a segment within τ of one outline edge are an interval
// of it). An edge it refuses holds a point beyond the limit: the farthest of a fine sampling
// names the violation.
class HullReach {
 public:
  // The outline's distance index is built on the first hull point measured: most hulls are
  // proven by their pockets alone.
  HullReach(const std::vector<Region>& outline, double limit) : limit_(limit) {
    for (const Region& region : outline) regions_.push_back(&region);
  }

  void vertex(Vec2 p, Worst& beyond) {
    const double distance = outline().distance(p, limit_);
    if (distance > limit_) beyond.offer(distance, p);
  }

  void edge(Vec2 a, Vec2 b, Worst& beyond) {
    // Hulls repeat: pieces thinner than the weld may share the hull grown round them (a comb of
    // 1,000 teeth: 1,000 hulls alike, each edge searched along every tooth, 80 % of its cook).
    const std::array<double, 4> key{a.x, a.y, b.x, b.y};
    if (within_.count(key) != 0) return;
    if (outline().segment_within(a, b, limit_)) {
      within_.insert(key);
      return;
    }
    constexpr int kSamples = 256;
    Worst farthest;
    for (int k = 1; k < kSamples; ++k) {
      const Vec2 p = a + (b - a) * (double(k) / kSamples);
      farthest.offer(outline().distance(p, std::numeric_limits<double>::infinity()), p);
    }
    // Between two samples, when the sampling missed it: at least the limit.
    beyond.offer(std::max(farthest.value, limit_), farthest.where);
  }

 private:
  const OutlineDistance& outline() {
    if (!outline_) outline_.emplace(regions_);
    return *outline_;
  }

  std::vector<const Region*> regions_;
  std::optional<OutlineDistance> outline_;
  double limit_;
  std::set<std::array<double, 4>> within_;  // edges (a, b) shown within the limit
};

// Where each hull vertex stands in the component's outer ring (ring.size() where it does not):
// the hull's vertices that are the ring's come in the ring's order, so one walk round the ring
// finds them (a vertex the engine limits added costs a walk round it).
void hull_vertices_in_ring(const Ring& hull, const Ring& ring, std::vector<std::size_t>& index) {
  const std::size_t n = ring.size();
  index.assign(hull.size(), n);
  std::size_t from = 0;
  for (std::size_t k = 0; k < hull.size(); ++k) {
    for (std::size_t step = 0, i = from; step < n; ++step, i = i + 1 == n ? 0 : i + 1) {
      if (ring[i] == hull[k]) {
        index[k] = i;
        from = i;
        break;
      }
    }
  }
}

// --- The partition. -------------------------------------------------------------------------

// A stretch of boundary, from before to, lexicographically, run weight times that way.
struct Stretch {
  Vec2 from, to;
  std::int32_t weight;
  std::uint32_t ring;  // where it came from (see RingOf); 32 bits: on a sheet of thousands of
                       // blobs the stretches are a cook's largest buffer (issue 17)
};

bool lexicographically_less(Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

void add_stretch(Vec2 a, Vec2 b, std::int32_t weight, std::uint32_t ring,
                 std::vector<Stretch>& stretches) {
  if (a == b) return;
  if (lexicographically_less(a, b)) {
    stretches.push_back({a, b, weight, ring});
  } else {
    stretches.push_back({b, a, -weight, ring});
  }
}

// Sums the weights of equal stretches; keeps those that do not cancel, with their sum.
void cancel(std::vector<Stretch>& stretches) {
  std::sort(stretches.begin(), stretches.end(), [](const Stretch& x, const Stretch& y) {
    if (x.from != y.from) return lexicographically_less(x.from, y.from);
    if (x.to != y.to) return lexicographically_less(x.to, y.to);
    return x.ring < y.ring;
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < stretches.size();) {
    std::size_t j = i;
    int sum = 0;
    for (; j < stretches.size() && stretches[j].from == stretches[i].from &&
           stretches[j].to == stretches[i].to;
         ++j) {
      sum += stretches[j].weight;
    }
    if (sum != 0) stretches[kept++] = {stretches[i].from, stretches[i].to, sum, stretches[i].ring};
    i = j;
  }
  stretches.resize(kept);
}

// The same, in linear time, but for the order of what is left (for the many stretches of all
// the pieces, most of which cancel).
void cancel_by_hash(std::vector<Stretch>& stretches) {
  auto mix = [](std::uint64_t hash, double value) {
    hash ^= std::bit_cast<std::uint64_t>(value + 0.0);  // + 0.0: -0 and 0 are equal
    hash *= 0x9E3779B97F4A7C15ull;
    return hash ^ (hash >> 32);
  };
  std::size_t capacity = 16;
  while (capacity < 2 * stretches.size()) capacity *= 2;
  constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  // Scratch, reused: every region of a cook is checked this way.
  thread_local std::vector<std::uint32_t> slots;
  slots.assign(capacity, kEmpty);
  std::uint32_t kept = 0;
  for (std::size_t i = 0; i < stretches.size(); ++i) {
    const Stretch stretch = stretches[i];
    const std::uint64_t hash =
        mix(mix(mix(mix(0, stretch.from.x), stretch.from.y), stretch.to.x), stretch.to.y);
    for (std::size_t slot = hash & (capacity - 1);; slot = (slot + 1) & (capacity - 1)) {
      if (slots[slot] == kEmpty) {
        slots[slot] = kept;
        stretches[kept++] = stretch;
        break;
      }
      Stretch& same = stretches[slots[slot]];
      if (same.from == stretch.from && same.to == stretch.to) {
        same.weight += stretch.weight;
        break;
      }
    }
  }
  stretches.resize(kept);
  std::erase_if(stretches, [](const Stretch& stretch) { return stretch.weight == 0; });
}

// Cuts every stretch at the ends of the others that lie on it (within slack).
std::vector<Stretch> cut_at_ends(const std::vector<Stretch>& stretches, double slack) {
  std::vector<Vec2> ends;
  for (const Stretch& stretch : stretches) ends.push_back(stretch.from), ends.push_back(stretch.to);
  Vec2 low = ends.front(), high = low;
  for (Vec2 p : ends) low = glm::min(low, p), high = glm::max(high, p);
  const detail::CellGrid grid(low, high, ends.size());
  Buckets<std::size_t> buckets;
  buckets.build(grid.cells(), [&](auto&& add) {
    for (std::size_t e = 0; e < ends.size(); ++e) {
      add(grid.cell(grid.column(ends[e].x), grid.row(ends[e].y)), e);
    }
  });
  const double margin = slack + 1e-6 * grid.cell_size();
  std::vector<Stretch> cut;
  std::vector<std::pair<double, Vec2>> cuts;
  for (const Stretch& stretch : stretches) {
    const Vec2 a = stretch.from, b = stretch.to, ab = b - a;
    // Along the stretch's longer axis, coordinates order its points exactly. The fraction along
    // it rounds: an end 1e-101 from b, on a stretch 4 long, came out at 1 and was not cut at
    // (the fuzzer's polygon with an edge 1e-101 long, whose pieces' collinear cuts then did not
    // match: exit 4 on a partition).
    const bool by_x = std::abs(ab.x) >= std::abs(ab.y);
    const double a_key = by_x ? a.x : a.y, b_key = by_x ? b.x : b.y;
    const double sign = b_key >= a_key ? 1.0 : -1.0;
    cuts.clear();
    grid.for_each_cell(a, b, margin, [&](std::size_t cell) {
      for (const std::size_t* e = buckets.begin(cell); e != buckets.end(cell); ++e) {
        const Vec2 p = ends[*e];
        const double key = by_x ? p.x : p.y;
        const bool between = sign * (key - a_key) > 0.0 && sign * (b_key - key) > 0.0;
        const double along = glm::dot(p - a, ab) / glm::dot(ab, ab);
        if ((between || (along > 0.0 && along < 1.0)) && p != a && p != b &&
            point_segment_distance(p, a, b) <= slack) {
          cuts.emplace_back(sign * key, p);
        }
      }
    });
    std::sort(cuts.begin(), cuts.end(), [](const auto& x, const auto& y) {
      return x.first != y.first
                 ? x.first < y.first
                 : std::tie(x.second.x, x.second.y) < std::tie(y.second.x, y.second.y);
    });
    Vec2 from = a;
    for (const auto& [along, p] : cuts) {
      add_stretch(from, p, stretch.weight, stretch.ring, cut);
      from = p;
    }
    add_stretch(from, b, stretch.weight, stretch.ring, cut);
  }
  return cut;
}

// Components that partition the outline have boundaries that cancel the outline's as chains:
// every stretch of an edge is run as often one way as the other, counting the outline's edges
// backwards. (A valid component's winding number is 1 inside it and 0 outside, so then the sum of
// the components' equals the outline's everywhere: no point in two, none left out.) Equal edges
// cancel first; a piece may keep a vertex on a straight stretch where its neighbour has none, so
// the edges left are then cut at each other's ends (the cuts that cancel edges elsewhere cancel
// on both sides of them alike) and cancelled again.
//
// The pieces of each region (CookedPiece::region) cancel that region's boundary on their own, so
// the regions are checked apart: on the threads, each with a buffer of its own edges, reused.
// (One buffer of every edge of a sheet of thousands of blobs was a cook's largest, and the time
// to fault its fresh pages in a tenth of the whole cook's: issue 17.)
std::optional<std::string> region_partition_defect(const std::vector<CookedPiece>& pieces,
                                                   const std::uint32_t* first,
                                                   const std::uint32_t* last, const Region& region,
                                                   double slack) {
  struct RingOf {
    const Ring* ring;
    int weight;  // +1 for a component's ring, -1 for the outline's
    std::size_t piece;
  };
  thread_local std::vector<RingOf> rings;
  rings.clear();
  auto add = [&](const Region& region, int weight, std::size_t piece) {
    rings.push_back({&region.outer, weight, piece});
    for (const Ring& hole : region.holes) rings.push_back({&hole, weight, piece});
  };
  for (const std::uint32_t* k = first; k != last; ++k) add(pieces[*k].component, 1, *k);
  add(region, -1, 0);
  thread_local std::vector<Stretch> stretches;
  stretches.clear();
  std::size_t edges = 0;
  for (const RingOf& ring : rings) edges += ring.ring->size();
  stretches.reserve(edges);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r].ring;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      add_stretch(ring[i], ring[(i + 1) % n], rings[r].weight, static_cast<std::uint32_t>(r),
                  stretches);
    }
  }
  cancel_by_hash(stretches);
  if (stretches.empty()) return std::nullopt;
  std::vector<Stretch> left = cut_at_ends(stretches, slack);
  cancel(left);
  if (left.empty()) return std::nullopt;
  const Stretch& unmatched = left.front();
  const RingOf& ring = rings[unmatched.ring];
  const std::string whose =
      ring.weight < 0 ? "of the outline" : "of piece " + std::to_string(ring.piece + 1);
  return "the pieces do not partition the outline (a gap or an overlap): " +
         std::to_string(left.size()) + " stretch" + (left.size() > 1 ? "es" : "") +
         " of boundary unmatched, the first " + point(unmatched.from) + "-" + point(unmatched.to) +
         " " + whose;
}

std::optional<std::string> partition_defect(const std::vector<CookedPiece>& pieces,
                                            const std::vector<Region>& outline, double slack,
                                            unsigned threads) {
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (pieces[k].region >= outline.size()) {
      return "piece " + std::to_string(k + 1) + " is of region " +
             std::to_string(pieces[k].region + 1) + ", but the outline has " +
             std::to_string(outline.size());
    }
  }
  Buckets<std::uint32_t, std::uint32_t> pieces_of;
  pieces_of.build(outline.size(), [&](auto&& add) {
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      add(pieces[k].region, static_cast<std::uint32_t>(k));
    }
  });
  std::vector<std::optional<std::string>> defects(outline.size());
  parallel_for(
      outline.size(), threads,
      [&](std::size_t r, unsigned) {
        defects[r] = region_partition_defect(pieces, pieces_of.begin(r), pieces_of.end(r),
                                             outline[r], slack);
      },
      kRegionsWorthAThread);
  for (std::optional<std::string>& defect : defects) {
    if (defect) return std::move(defect);
  }
  return std::nullopt;
}

// The largest distance of ring's vertices from first to last (cyclic) from the line through
// ring[first] and ring[last].
double pocket_depth(const Ring& ring, std::size_t first, std::size_t last) {
  const Vec2 a = ring[first], along = ring[last] - a;
  const double length = glm::length(along);
  if (!(length > 0.0)) return std::numeric_limits<double>::infinity();
  double depth = 0.0;
  for (std::size_t i = first; i != last; i = i + 1 == ring.size() ? 0 : i + 1) {
    depth = std::max(depth, std::abs(cross(along, ring[i] - a)));
  }
  return depth / length;
}

// What one worker of the check keeps from piece to piece: the whole outline's distances (built
// when a piece first needs them) and scratch.
struct PieceChecker {
  PieceChecker(const std::vector<Region>& outline, double limit) : hull_reach(outline, limit) {}
  HullReach hull_reach;
  HullLines lines;                   // of the piece at hand
  std::vector<std::size_t> in_ring;  // of the piece at hand: see hull_vertices_in_ring
};

// Appends to out the ways piece k breaks the contract (see find_contract_violations).
// tau: the reports' " (τ ...)".
void check_piece(std::size_t k, const CookedPiece& piece, const ContractTerms& terms, double slack,
                 const std::string& tau, bool partitioned, PieceChecker& checker,
                 std::vector<std::string>& out) {
  const double limit = terms.tau + slack;
  HullReach& hull_reach = checker.hull_reach;
  HullLines& lines = checker.lines;
  std::vector<std::size_t>& in_ring = checker.in_ring;
  const std::string name = "piece " + std::to_string(k + 1) + ": ";
  auto report = [&](const std::string& problem) { out.push_back(name + problem); };
  Region cleaned;
  const bool convex =
      piece.component.holes.empty() && is_strictly_convex_ccw(piece.component.outer);
  const std::optional<std::string> component_problem =
      component_defect(piece.component, convex, slack, cleaned);
  if (component_problem) report(*component_problem);
  const std::optional<HullDefect> hull_problem = hull_defect(piece.hull, terms.limits);
  if (hull_problem) report(hull_problem->problem);

  if (!component_problem && !convex) {
    const double concavity = measure_concavity(cleaned, terms.measure, terms.tau);
    if (concavity > limit) {
      report("its concavity, measured afresh under " + std::string(measure_name(terms.measure)) +
             ", is " + number(concavity) + tau);
    }
  }
  // The distances below are measured by a convex polygon's edge lines.
  if (hull_problem && !hull_problem->convex) return;
  Worst outside, far;
  lines.assign(piece.hull);
  check_component_in_hull(piece.component, lines, limit, slack, outside, far);
  if (outside.found()) {
    report("its component's vertex " + point(outside.where) + " lies " + number(outside.value) +
           " outside its hull");
  }
  if (far.found()) {
    report("its component's point " + point(far.where) + " lies " + number(far.value) +
           " from its hull's boundary" + tau);
  }

  // A hull vertex that is a vertex of its component lies in the outline when the components
  // partition it (else that is reported already): only the others are measured.
  // The others are measured first against the component alone (in the outline when the
  // components partition it; a grown hull mostly stays near its own piece), then against the
  // whole outline.
  Worst beyond;
  const Ring& hull = piece.hull;
  hull_vertices_in_ring(hull, piece.component.outer, in_ring);
  const std::size_t ring_size = piece.component.outer.size();
  std::optional<OutlineDistance> own;
  auto near_own = [&]() -> const OutlineDistance* {
    if (!partitioned) return nullptr;
    if (!own) own.emplace(std::vector<const Region*>{&piece.component});
    return &*own;
  };
  for (std::size_t i = 0; i < hull.size(); ++i) {
    if (in_ring[i] < ring_size && partitioned) continue;
    const OutlineDistance* component = near_own();
    if (component && component->distance(hull[i], limit) <= limit) continue;
    hull_reach.vertex(hull[i], beyond);
  }
  if (beyond.found()) {
    report("its hull's vertex " + point(beyond.where) + " lies " + number(beyond.value) +
           " beyond the outline" + tau);
    return;
  }
  // A hull edge that is an edge of the component lies in the outline likewise, and one that
  // bridges a pocket of the component's ring within the limit: the perpendicular through any
  // point of the edge crosses the chain from one end to the other (it separates them), at a
  // point of the outline no farther than the chain's farthest vertex from the edge's line.
  for (std::size_t i = 0, n = hull.size(); i < n; ++i) {
    const std::size_t from = in_ring[i], to = in_ring[(i + 1) % n];
    const bool on_component = partitioned && from < ring_size && to < ring_size &&
                              ((from + 1 == ring_size ? 0 : from + 1) == to ||
                               pocket_depth(piece.component.outer, from, to) <= limit);
    if (on_component) continue;
    const OutlineDistance* component = near_own();
    if (component && component->segment_within(hull[i], hull[(i + 1) % n], limit)) continue;
    hull_reach.edge(hull[i], hull[(i + 1) % n], beyond);
  }
  if (beyond.found()) {
    report("its hull's point " + point(beyond.where) + " lies " + number(beyond.value) +
           " beyond the outline" + tau);
  }
}

}  // namespace

std::vector<std::string> find_contract_violations(const std::vector<CookedPiece>& pieces,
                                                  const std::vector<Region>& outline,
                                                  const ContractTerms& terms, unsigned threads) {
  std::vector<std::string> violations;
  if (outline.empty()) {
    if (!pieces.empty()) violations.push_back(std::to_string(pieces.size()) + " pieces of nothing");
    return violations;
  }
  const double slack = rounding_slack(outline);
  const double limit = terms.tau + slack;
  const std::string tau = " (τ " + number(terms.tau) + ")";

  // Where the shoelace's areas differ by more than a billionth, they are summed again
  // accurately (see accurate_twice_area): a long thin piece's rounding alone can do that.
  double pieces_area = 0.0, outline_area = 0.0;
  for (const CookedPiece& piece : pieces) pieces_area += region_area(piece.component);
  for (const Region& region : outline) outline_area += region_area(region);
  if (!(std::abs(pieces_area - outline_area) <= 1e-9 * outline_area)) {
    pieces_area = outline_area = 0.0;
    for (const CookedPiece& piece : pieces) pieces_area += accurate_area(piece.component);
    for (const Region& region : outline) outline_area += accurate_area(region);
  }
  if (!(std::abs(pieces_area - outline_area) <= 1e-9 * outline_area)) {
    violations.push_back("the pieces' areas add up to " + number(pieces_area) +
                         ", the outline's to " + number(outline_area) + " (a difference of " +
                         number(pieces_area - outline_area) + ")");
  }
  const std::optional<std::string> partition_problem =
      partition_defect(pieces, outline, slack, threads);
  if (partition_problem) violations.push_back(*partition_problem);
  const bool partitioned = violations.empty();

  // Each piece on its own (the work splits over threads), its reports in the pieces' order. A
  // checker per worker: the whole outline's distances keep scratch of their own, so each worker
  // that needs them builds them (most pieces are proven by their own component).
  const unsigned workers = pieces.size() < kItemsWorthAThread
                               ? 1u
                               : static_cast<unsigned>(std::max<std::size_t>(
                                     1, std::min<std::size_t>(threads, pieces.size())));
  std::vector<PieceChecker> checkers(workers, PieceChecker(outline, limit));
  std::vector<std::string> reports = parallel_join<std::string>(
      pieces.size(), workers, [&](std::size_t k, unsigned worker, std::vector<std::string>& out) {
        check_piece(k, pieces[k], terms, slack, tau, partitioned, checkers[worker], out);
      });
  std::move(reports.begin(), reports.end(), std::back_inserter(violations));
  return violations;
}

std::optional<std::string> hull_shape_defect(const Ring& hull) {
  const std::optional<HullDefect> defect = hull_defect(hull, EngineLimits{0, 0.0});
  if (!defect) return std::nullopt;
  return defect->problem;
}

void enforce_contract(const std::string& source, const std::vector<std::string>& violations) {
  if (violations.empty()) return;
  std::string message =
      source + ": internal error: the output breaks its contract: " + violations.front();
  if (violations.size() > 1) message += " (and " + std::to_string(violations.size() - 1) + " more)";
  throw ContractError(message);
}

double contract_slack(const std::vector<const Ring*>& rings) {
  return detail::slack_for(detail::coordinate_reach(rings));
}

bool is_contract_sliver(const Region& region, double slack) {
  if (region.outer.empty()) return true;
  const double length = length_of(region.outer);
  return region_area(region) <= length * std::max(1e-9 * length, slack);
}

std::string sliver_piece_refusal(const Region& piece, std::string_view source) {
  Vec2 low = piece.outer.empty() ? Vec2{0, 0} : piece.outer.front(), high = low;
  for (Vec2 p : piece.outer) low = glm::min(low, p), high = glm::max(high, p);
  std::ostringstream message;
  message << source << ": a piece of " << region_area(piece) << " square units near ("
          << 0.5 * (low.x + high.x) << ", " << 0.5 * (low.y + high.y)
          << ") is a sliver (thinner than the rounding of its coordinates) that no cut avoided";
  return message.str();
}

void refuse_sliver_pieces(const std::vector<CookedPiece>& pieces,
                          const std::vector<Region>& outline, double tau, std::string_view source) {
  const double slack = rounding_slack(outline);
  for (const CookedPiece& piece : pieces) {
    if (!is_contract_sliver(piece.component, slack)) continue;
    std::ostringstream ending;
    ending << " at tau = " << tau << "; raise --tau, or move the input nearer the origin";
    throw InputError(sliver_piece_refusal(piece.component, source) + ending.str());
  }
}

}  // namespace hullcook
