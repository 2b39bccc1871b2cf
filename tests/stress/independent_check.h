// The referee of the stress tests (issue 16): checks a decomposition's or a cook's output against
// the contract without calling the decomposer's measures. From hullcook::core it uses only the
// exact predicates, point location, signed areas, the input validator and convex_hull (a sorting
// hull; the decomposer takes its hulls by Melkman's scan, simple_polygon_hull_indices).
//
// Rules (the ids name them in reports):
//  component.invalid        a component is not a valid region (outer CCW, holes CW, simple,
//                           holes strictly inside and disjoint)
//  component.sliver         a zero-area sliver: its hull narrower than kSliverWidth x the input's
//                           diagonal, or its area below the square of that width
//  hull.degenerate          fewer than 3 vertices, not counter-clockwise, not strictly convex
//  hull.not_convex_hull     (decompositions) the hull is not exactly the convex hull of the
//                           component's outer ring
//  hull.misses_component    a component vertex outside its hull
//  partition.area           the components' areas do not add up to the regions' (pieces lost
//                           or overlapping)
//  partition.outside        a component not inside one region of the input
//  partition.overlap        two components overlap
//  tau.component_to_hull    a point of a component's outer boundary farther than tau from its
//                           hull's boundary
//  tau.hole_to_hull         the same for a point of a hole the component keeps
//  tau.hull_to_component    (decompositions) a point of a hull farther than tau from its component
//  tau.hull_to_outline      (cooks) a point of a hull farther than tau from every region (a hull
//                           the weld grew may reach over its neighbours, never past the outline)
//  tau.unproven             the bound above could be neither proven nor refuted in the budget
//  engine.max_verts         (cooks) a hull with more vertices than max_verts
//  engine.weld              (cooks) two hull vertices closer than the weld
//  engine.collinear         (cooks) a hull vertex within kCollinearFractionOfWeld x weld of its
//                           neighbours' line
//
// Distances are proven, not sampled: a component's boundary inside its convex hull is at most
// the concave function min over the hull's edge lines, maximised exactly along each edge; a hull
// point's distance to the component is bounded over each pocket by the pocket's depth below its
// bridge's line and, where that bound is not enough (and for hulls grown by the engine limits),
// by subdividing the hull (distance_bounds.h).
//
// Tolerance: every comparison allows eps = 1e-9 x the input's diagonal + 8 ulp of its largest
// coordinate (rounding of the coordinates themselves); the subdivision takes triangles smaller
// than eps as proven (so a hull point is within tau + 2 eps); the areas allow 1e-9 x the area
// plus that rounding times the components' perimeters.
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hullcook::stress {

// A piece narrower than this fraction of the input's bounding-box diagonal is a sliver: no input
// of the stress generators or the drawn images has a feature thinner than 1e-6 of its diagonal
// (a wall of 0.01 in a polygon at most 1e4 across), while the slivers that near-collinear
// vertices make are 1e-13 of it or less. An input thinner than that is outside this rule's reach.
inline constexpr double kSliverWidth = 1e-9;

struct EngineRules {
  std::size_t max_verts = 8;  // 0: unlimited
  double weld = 0.005;        // [units] minimum distance between two vertices of a hull
  double collinear_fraction = 0.1;
};

struct CheckOptions {
  double tau = 0.0;  // [units]
  // Decompositions: each hull is exactly the convex hull of its component's outer ring.
  // Cooks: hulls may be grown by the engine limits; they must contain their components.
  bool exact_hulls = true;
  std::optional<EngineRules> engine;        // cooks: the engine's rules for every hull
  std::size_t subdivision_budget = 200000;  // cells per proof of a hull's distance
};

struct CheckedPiece {
  const Region* component;
  const Ring* hull;
};

struct Violation {
  std::string rule;
  std::string detail;
};

struct CheckReport {
  std::map<std::string, std::size_t> counts;  // per rule, how many violations
  std::vector<Violation> examples;            // the first few of each rule
  double eps = 0.0;                           // the tolerance used
  bool ok() const { return counts.empty(); }
  std::string summary() const;  // "rule xN: first detail; ..." or "ok"
};

// Checks pieces as the decomposition (or cook) of regions: a partition of them, each piece within
// tau of its hull in both directions, and the options' rules.
CheckReport check_pieces(const std::vector<Region>& regions,
                         const std::vector<CheckedPiece>& pieces, const CheckOptions& options);

}  // namespace hullcook::stress
