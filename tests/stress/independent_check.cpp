#include "independent_check.h"

#include "box_grid.h"
#include "distance_bounds.h"
#include "edge_index.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace hullcook::stress {
namespace {

constexpr std::size_t kExamplesPerRule = 3;

std::string point_text(Vec2 p) {
  std::ostringstream text;
  text.precision(17);
  text << "(" << p.x << ", " << p.y << ")";
  return text.str();
}

// A message's numbers with 9 digits: enough to tell how far beyond tau.
std::ostringstream detail_stream() {
  std::ostringstream stream;
  stream.precision(9);
  return stream;
}

double length(Vec2 v) { return std::hypot(v.x, v.y); }

double perimeter(const Ring& ring) {
  double total = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    total += length(ring[(i + 1) % ring.size()] - ring[i]);
  return total;
}

template <typename Visit>
void for_each_edge(const Region& region, Visit visit) {
  auto ring_edges = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) visit(ring[i], ring[(i + 1) % ring.size()]);
  };
  ring_edges(region.outer);
  for (const Ring& hole : region.holes) ring_edges(hole);
}

// Two segments cross at one point interior to both, and not merely within eps of touching: the
// tolerance keeps a vertex placed on an edge by rounding from counting as a crossing.
bool cross_clearly(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double eps) {
  if (!segments_cross_properly(a, b, c, d)) return false;
  return point_segment_distance(a, c, d) > eps && point_segment_distance(b, c, d) > eps &&
         point_segment_distance(c, a, b) > eps && point_segment_distance(d, a, b) > eps;
}

// A point strictly inside a polygon with holes (O'Rourke's: the lowest-leftmost vertex v is
// convex; if no vertex lies in the triangle of v and its neighbours, its centroid is inside,
// otherwise the midpoint of v and the vertex in it nearest to v's corner). nullopt when rounding
// puts the candidate on the boundary (a sliver).
std::optional<Vec2> interior_point(const Region& region) {
  const Ring& outer = region.outer;
  const std::size_t n = outer.size();
  if (n < 3) return std::nullopt;
  std::size_t v = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (outer[i].x < outer[v].x || (outer[i].x == outer[v].x && outer[i].y < outer[v].y)) v = i;
  }
  const Vec2 a = outer[(v + n - 1) % n], b = outer[v], c = outer[(v + 1) % n];
  const Vec2 chord = c - a;
  std::optional<Vec2> nearest;
  double nearest_height = -1;
  auto consider = [&](Vec2 q) {
    if (q == a || q == b || q == c) return;
    if (orientation(a, b, q) < 0 || orientation(b, c, q) < 0 || orientation(c, a, q) < 0) return;
    // Height over the chord ac towards b: the largest is nearest to b's corner.
    const double height = std::abs(orient2d(a, c, q)) / length(chord);
    if (height > nearest_height) nearest_height = height, nearest = q;
  };
  for (const Vec2& q : outer) consider(q);
  for (const Ring& hole : region.holes) {
    for (const Vec2& q : hole) consider(q);
  }
  const Vec2 candidate = nearest ? (b + *nearest) * 0.5 : (a + b + c) / 3.0;
  if (locate_point(region, candidate) != Location::inside) return std::nullopt;
  return candidate;
}

// Why a ring cannot be a component's (fewer than 3 vertices, or not oriented counter-clockwise
// for an outer ring, clockwise for a hole); empty when it can.
std::string ring_problem(const Ring& ring, bool outer, const std::string& what) {
  const double area = signed_area(ring);
  if (ring.size() >= 3 && (outer ? area > 0 : area < 0)) return "";
  std::ostringstream text = detail_stream();
  text << what << " of " << ring.size() << " vertices has signed area " << area;
  return text.str();
}

// The hull's shape: strictly convex and counter-clockwise, and its width (the smallest over its
// edges of the farthest vertex from the edge's line).
struct HullShape {
  bool convex = false;
  double width = 0;
};

HullShape hull_shape(const Ring& hull) {
  const std::size_t n = hull.size();
  HullShape shape;
  if (n < 3) return shape;
  shape.convex = true;
  shape.width = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = hull[k], b = hull[(k + 1) % n];
    if (orientation(hull[(k + n - 1) % n], a, b) <= 0) shape.convex = false;
    double farthest = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const int side = orientation(a, b, hull[j]);
      if (side < 0) shape.convex = false;
      farthest = std::max(farthest, std::abs(orient2d(a, b, hull[j])) / length(b - a));
    }
    shape.width = std::min(shape.width, farthest);
  }
  return shape;
}

bool same_cycle(const Ring& a, const Ring& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  const auto start = std::find(b.begin(), b.end(), a.front());
  if (start == b.end()) return false;
  const std::size_t offset = static_cast<std::size_t>(start - b.begin());
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != b[(i + offset) % b.size()]) return false;
  }
  return true;
}

// The smallest width of a ring's convex hull: half of it bounds every point's distance to the
// ring from inside (the two rays along the narrow direction both meet the ring).
double min_width(const Ring& ring) { return hull_shape(convex_hull(ring)).width; }

class Checker {
 public:
  Checker(const std::vector<Region>& regions, const std::vector<CheckedPiece>& pieces,
          const CheckOptions& options)
      : regions_(regions), pieces_(pieces), options_(options) {
    Bounds all;
    for (const Region& region : regions) all.add(region.outer);
    const double largest = std::max({std::abs(all.low.x), std::abs(all.low.y), std::abs(all.high.x),
                                     std::abs(all.high.y), 1e-300});
    diagonal_ = regions.empty() ? 0 : length(all.high - all.low);
    rounding_ = 8 * (std::nextafter(largest, INFINITY) - largest);
    report_.eps = 1e-9 * diagonal_ + rounding_;
    // The contract's rounding slack, as the README states it: a billionth of the shape's size, or
    // of a thousandth of its largest coordinate. Far from the origin that is far above a few
    // units in the last place: a hull fitted from its edges' lines (--max-verts at τ 0, without
    // a weld) meets nearly parallel lines, where rounding moves it by more (3e-9 at 1e5).
    const double extent =
        regions.empty() ? 0 : std::max(all.high.x - all.low.x, all.high.y - all.low.y);
    tau_slack_ = std::max(report_.eps, 1e-9 * std::max(extent, 1e-3 * largest));
  }

  CheckReport run() {
    for (std::size_t k = 0; k < pieces_.size(); ++k) check_piece(k);
    check_partition();
    return std::move(report_);
  }

 private:
  void fail(const std::string& rule, const std::string& detail) {
    if (report_.counts[rule]++ < kExamplesPerRule) report_.examples.push_back({rule, detail});
  }

  std::string piece_name(std::size_t k) const { return "piece " + std::to_string(k); }

  double eps() const { return report_.eps; }
  // What a distance may exceed τ by (see tau_slack_).
  double tau_limit() const { return options_.tau + tau_slack_; }

  void check_piece(std::size_t k) {
    const Region& component = *pieces_[k].component;
    const Ring& hull = *pieces_[k].hull;
    const std::string name = piece_name(k);
    std::string problem = ring_problem(component.outer, true, "outer ring");
    for (std::size_t h = 0; h < component.holes.size() && problem.empty(); ++h) {
      problem = ring_problem(component.holes[h], false, "hole " + std::to_string(h));
    }
    bool valid = problem.empty();
    if (valid) {
      try {
        clean_and_validate({component}, name);
      } catch (const InputError& error) {
        valid = false;
        problem = error.what();
      }
    }
    if (!valid) fail("component.invalid", name + ": " + problem);

    const HullShape shape = hull_shape(hull);
    if (!shape.convex || signed_area(hull) <= 0) {
      fail("hull.degenerate", name + ": hull of " + std::to_string(hull.size()) +
                                  " vertices is not strictly convex and counter-clockwise");
    }
    const double sliver = kSliverWidth * diagonal_;
    const double area = region_area(component);
    if (shape.width < sliver || area < sliver * sliver) {
      std::ostringstream detail = detail_stream();
      detail << name << ": area " << area << ", hull width " << shape.width << " (sliver below "
             << sliver << ")";
      fail("component.sliver", detail.str());
    }
    if (options_.engine) check_engine(name, hull, *options_.engine);
    if (!valid || hull.size() < 3) return;

    const bool exact = same_cycle(convex_hull(component.outer), hull);
    if (options_.exact_hulls && !exact) {
      fail("hull.not_convex_hull", name + ": the hull is not the convex hull of the component");
    }
    const ConvexLines lines(hull);
    for (Vec2 v : component.outer) {
      if (lines.depth(v) < -eps()) {
        fail("hull.misses_component", name + ": vertex " + point_text(v) + " is outside the hull");
        return;
      }
    }
    check_component_to_hull(name, component, lines);
    if (shape.convex) check_hull_to_component(name, component, hull, exact);
  }

  void check_engine(const std::string& name, const Ring& hull, const EngineRules& rules) {
    const std::size_t n = hull.size();
    if (rules.max_verts && n > rules.max_verts) {
      fail("engine.max_verts", name + ": " + std::to_string(n) + " vertices");
    }
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const double gap = length(hull[i] - hull[j]);
        if (gap < rules.weld) {
          std::ostringstream detail = detail_stream();
          detail << name << ": vertices " << i << " and " << j << " are " << gap << " apart (weld "
                 << rules.weld << ")";
          fail("engine.weld", detail.str());
        }
      }
      const Vec2 a = hull[(i + n - 1) % n], b = hull[i], c = hull[(i + 1) % n];
      const double height = std::abs(orient2d(a, c, b)) / length(c - a);
      if (height < rules.collinear_fraction * rules.weld) {
        std::ostringstream detail = detail_stream();
        detail << name << ": vertex " << i << " is " << height << " from its neighbours' line";
        fail("engine.collinear", detail.str());
      }
    }
  }

  void check_component_to_hull(const std::string& name, const Region& component,
                               const ConvexLines& lines) {
    const double limit = tau_limit();
    auto check_ring = [&](const Ring& ring, const char* rule, const std::string& what) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        Vec2 at;
        const double depth = lines.max_depth(ring[i], ring[(i + 1) % ring.size()], limit, at);
        if (depth > limit) {
          std::ostringstream detail = detail_stream();
          detail << name << ": " << what << " point " << point_text(at) << " is " << depth
                 << " from the hull's boundary (tau " << options_.tau << ")";
          fail(rule, detail.str());
          return;
        }
      }
    };
    check_ring(component.outer, "tau.component_to_hull", "outer boundary");
    for (std::size_t h = 0; h < component.holes.size(); ++h) {
      check_ring(component.holes[h], "tau.hole_to_hull", "hole " + std::to_string(h));
    }
  }

  // Every hull point within tau of the component. When the hull's vertices are the component's,
  // the hull minus the component is the pockets under each hull edge and the holes; a pocket's
  // point is within the pocket's depth below its bridge's line (the ray away from the bridge meets
  // the chain no farther), a hole's within half the hole's width. Where those bounds exceed tau,
  // and for grown hulls, the subdivision of the hull decides.
  void check_hull_to_component(const std::string& name, const Region& component, const Ring& hull,
                               bool exact) {
    const double limit = tau_limit();
    if (exact && pockets_and_holes_within(component, hull, limit)) return;
    const FarthestPoint far =
        farthest_from_target(hull, {component}, limit, eps(), options_.subdivision_budget);
    if (far.proven) return;
    // A cook's contract bounds hulls by the outline: a piece thinner than the weld may be given
    // an engine-ready hull that reaches over its neighbours (issue 16's "grown to the smallest
    // hull the engine accepts"), so only the outline decides.
    if (options_.engine) {
      check_hull_to_outline(name, hull);
      return;
    }
    std::ostringstream detail = detail_stream();
    if (far.distance > limit) {
      detail << name << ": hull point " << point_text(far.point) << " is " << far.distance
             << " from the component (tau " << options_.tau << ")";
      fail("tau.hull_to_component", detail.str());
    } else {
      detail << name << ": no proof in " << options_.subdivision_budget
             << " triangles that the hull is within tau " << options_.tau
             << " of the component (the farthest point found, " << point_text(far.point) << ", is "
             << far.distance << " from it)";
      fail("tau.unproven", detail.str());
    }
  }

  static bool pockets_and_holes_within(const Region& component, const Ring& hull, double limit) {
    const Ring& outer = component.outer;
    std::map<std::pair<double, double>, std::size_t> index;
    for (std::size_t i = 0; i < outer.size(); ++i) index[{outer[i].x, outer[i].y}] = i;
    for (std::size_t k = 0; k < hull.size(); ++k) {
      const Vec2 a = hull[k], b = hull[(k + 1) % hull.size()];
      double depth = 0;
      for (std::size_t i = index.at({a.x, a.y}); outer[i] != b; i = (i + 1) % outer.size()) {
        depth = std::max(depth, std::abs(orient2d(a, b, outer[i])) / length(b - a));
      }
      if (depth > limit) return false;
    }
    return std::all_of(component.holes.begin(), component.holes.end(),
                       [&](const Ring& hole) { return min_width(hole) / 2 <= limit; });
  }

  void check_hull_to_outline(const std::string& name, const Ring& hull) {
    const double limit = tau_limit();
    const FarthestPoint far =
        farthest_from_target(hull, regions_, limit, eps(), options_.subdivision_budget);
    if (far.proven) return;
    std::ostringstream detail = detail_stream();
    detail << name << ": hull point " << point_text(far.point) << " is " << far.distance
           << " from the outline (tau " << options_.tau << ")"
           << (far.distance > limit ? "" : " (unproven)");
    fail("tau.hull_to_outline", detail.str());
  }

  void check_partition();

  // The edges of piece k in a grid, built when first needed.
  EdgeIndex& piece_index(std::size_t k) {
    if (!piece_indexes_[k]) {
      piece_indexes_[k] = std::make_unique<EdgeIndex>(std::vector<Region>{*pieces_[k].component});
    }
    return *piece_indexes_[k];
  }

  // p is within eps of an edge of index.
  bool near_boundary(EdgeIndex& index, Vec2 p) const {
    Bounds box;
    box.add(p - Vec2{eps(), eps()});
    box.add(p + Vec2{eps(), eps()});
    for (std::size_t e : index.near(box)) {
      if (point_segment_distance(p, index.edge(e).a, index.edge(e).b) <= eps()) return true;
    }
    return false;
  }

  // p lies inside piece k, farther than eps from its boundary.
  bool clearly_inside(std::size_t k, const Bounds& bounds, Vec2 p) {
    return bounds.contains(p) && piece_index(k).locate(0, p) == Location::inside &&
           !near_boundary(piece_index(k), p);
  }

  // Pieces k and other overlap: an edge of one clearly crosses an edge of the other, or a vertex,
  // an edge's midpoint or the inside point of one lies clearly inside the other. Only the edges
  // in the common part of their boxes can.
  bool overlapping(std::size_t k, std::size_t other, const std::vector<Bounds>& bounds,
                   const std::vector<std::optional<Vec2>>& inner) {
    Bounds common;
    common.add(Vec2{std::max(bounds[k].low.x, bounds[other].low.x),
                    std::max(bounds[k].low.y, bounds[other].low.y)});
    common.add(Vec2{std::min(bounds[k].high.x, bounds[other].high.x),
                    std::min(bounds[k].high.y, bounds[other].high.y)});
    bool found = false;
    auto visit = [&](std::size_t from, std::size_t into) {
      for_each_edge(*pieces_[from].component, [&](Vec2 p, Vec2 q) {
        const Bounds edge = bounds_of(p, q);
        if (found || !edge.overlaps(common)) return;
        found = clearly_inside(into, bounds[into], p) ||
                clearly_inside(into, bounds[into], (p + q) * 0.5);
        for (std::size_t e : piece_index(into).near(edge)) {
          const EdgeIndex::Edge& crossing = piece_index(into).edge(e);
          found = found || cross_clearly(p, q, crossing.a, crossing.b, eps());
        }
      });
    };
    visit(k, other);
    visit(other, k);
    return found || (inner[k] && clearly_inside(other, bounds[other], *inner[k])) ||
           (inner[other] && clearly_inside(k, bounds[k], *inner[other]));
  }

  const std::vector<Region>& regions_;
  const std::vector<CheckedPiece>& pieces_;
  CheckOptions options_;
  CheckReport report_;
  double diagonal_ = 0;
  double rounding_ = 0;
  double tau_slack_ = 0;  // see the constructor
  std::vector<std::unique_ptr<EdgeIndex>> piece_indexes_;
};

void Checker::check_partition() {
  // Areas: a piece lost, or two pieces on the same ground, shows here.
  double region_total = 0, piece_total = 0, perimeters = 0;
  for (const Region& region : regions_) region_total += region_area(region);
  for (const CheckedPiece& piece : pieces_) {
    piece_total += region_area(*piece.component);
    perimeters += perimeter(piece.component->outer);
    for (const Ring& hole : piece.component->holes) perimeters += perimeter(hole);
  }
  if (std::abs(piece_total - region_total) > 1e-9 * region_total + rounding_ * perimeters) {
    std::ostringstream detail = detail_stream();
    detail << "the components' areas add up to " << piece_total << ", the regions' to "
           << region_total << " (" << pieces_.size() << " pieces)";
    fail("partition.area", detail.str());
  }

  // Each component inside a region: its interior point names the region, then none of its
  // vertices or edge midpoints is outside it, and none of its edges crosses the region's.
  std::vector<Bounds> region_bounds;
  for (const Region& region : regions_) region_bounds.push_back(bounds_of(region.outer));
  EdgeIndex index(regions_);

  std::vector<std::optional<Vec2>> inner(pieces_.size());
  std::vector<Bounds> piece_bounds;
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    const Region& component = *pieces_[k].component;
    piece_bounds.push_back(bounds_of(component.outer));
    inner[k] = interior_point(component);
    if (!inner[k]) continue;
    std::optional<std::size_t> home;
    for (std::size_t r = 0; r < regions_.size() && !home; ++r) {
      if (region_bounds[r].contains(*inner[k]) && index.locate(r, *inner[k]) == Location::inside) {
        home = r;
      }
    }
    if (!home) {
      fail("partition.outside",
           piece_name(k) + ": its inside " + point_text(*inner[k]) + " is in no region");
      continue;
    }
    bool outside = false;
    for_each_edge(component, [&](Vec2 a, Vec2 b) {
      for (Vec2 p : {a, (a + b) * 0.5}) {
        if (outside || index.locate(*home, p) != Location::outside) continue;
        if (near_boundary(index, p)) continue;
        outside = true;
        fail("partition.outside",
             piece_name(k) + ": point " + point_text(p) + " is outside its region");
      }
      if (outside) return;
      for (std::size_t e : index.near(bounds_of(a, b))) {
        if (cross_clearly(a, b, index.edge(e).a, index.edge(e).b, eps())) {
          outside = true;
          fail("partition.outside",
               piece_name(k) + ": edge from " + point_text(a) + " crosses the region's boundary");
          return;
        }
      }
    });
  }

  // No two components overlap: no clear crossing of their edges, no vertex and no inside point of
  // one clearly inside the other.
  piece_indexes_.resize(pieces_.size());
  BoxGrid grid(piece_bounds);
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    for (std::size_t other : grid.query(piece_bounds[k])) {
      if (other <= k) continue;
      if (overlapping(k, other, piece_bounds, inner)) {
        fail("partition.overlap", piece_name(k) + " and " + piece_name(other) + " overlap");
      }
    }
  }
}

}  // namespace

std::string CheckReport::summary() const {
  if (ok()) return "ok";
  std::ostringstream text;
  for (const auto& [rule, count] : counts) {
    text << rule << " x" << count;
    for (const Violation& example : examples) {
      if (example.rule == rule) {
        text << " (" << example.detail << ")";
        break;
      }
    }
    text << "; ";
  }
  return text.str();
}

CheckReport check_pieces(const std::vector<Region>& regions,
                         const std::vector<CheckedPiece>& pieces, const CheckOptions& options) {
  return Checker(regions, pieces, options).run();
}

}  // namespace hullcook::stress
