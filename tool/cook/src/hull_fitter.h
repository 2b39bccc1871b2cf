// Growing one hull until the engine accepts it, keeping it within τ.
#pragma once

#include "outline_distance.h"

#include "hullcook/cook/constrain.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace hullcook {

// Height of vertex i above the line through its neighbours; negative for a reflex turn.
double turn_height(const Ring& ring, std::size_t i);

// Removing edge i (hull[i] -> hull[i+1]) extends its neighbouring edges until they meet, so the
// hull only grows. Returns the meeting point, if the neighbours converge (and hull has at least 4
// vertices).
std::optional<Vec2> removed_edge_apex(const Ring& hull, std::size_t i);

// Edges whose removal may mend a local violation of the limits (two vertices closer than the
// weld distance, or a vertex nearly collinear with its neighbours), without duplicates.
std::vector<std::size_t> edges_to_mend(const Ring& hull, const EngineLimits& limits);

// For each vertex of component (the outer ring, then each hole), how far it may lie from the
// boundary of a hull grown from hull: bound, or its distance from hull's boundary if more (a
// growing hull never brings a vertex closer to tau than it was).
std::vector<double> allowed_depths(const Region& component, const Ring& hull, double bound);

// True when every point of hull (the convex hull of component's outer ring) is within bound of
// component, shown by its pockets: component has no hole, and each vertex lies within bound of
// the line of the hull edge over it (a point of a pocket, moving away from that line, meets the
// pocket's chain no deeper than that). Then the far side of component's bound has no bounded
// part, so a polygon holding hull whose boundary is within bound of component is wholly so.
bool pockets_within(const Region& component, const Ring& hull, double bound);

class HullFitter {
 public:
  // What the distances of hull points are bounded in: the component itself, or the whole outline.
  enum class Reach { component, outline };
  // reach: that outline or component (as reach_kind says); bound: how far [output units] a hull
  // point may lie; edges_suffice: whether the new edges alone prove new area within bound (see
  // pockets_within), else cells prove it too; allowed: as from allowed_depths. The references
  // must outlive the fitter.
  HullFitter(const Region& component, const std::vector<double>& allowed,
             const OutlineDistance& reach, Reach reach_kind, bool edges_suffice, double bound,
             const EngineLimits& limits)
      : component_(component),
        allowed_(allowed),
        reach_(reach),
        reach_is_component_(reach_kind == Reach::component),
        edges_suffice_(edges_suffice),
        bound_(bound),
        limits_(limits) {}

  // Grows hull (convex, counter-clockwise, holding the component's vertices exactly as a convex
  // hull of them does, within bound: it is not checked again) until it meets the limits, keeping
  // every point it adds within bound and every point of the component within its allowed depth;
  // nullopt when no such growth is found.
  std::optional<Ring> fit(Ring hull);

  // fit's first step: removes, one at a time, the cheapest edge whose removal mends a weld or
  // collinearity violation, keeping the hull within bound and the component within its allowed
  // depths; nullopt when a violation cannot be mended.
  std::optional<Ring> mend_local_violations(Ring hull) const;

  // For tests: mend with holds_component and growth_within over the whole hull, not only where a
  // removal changes it (the two must agree).
  void check_whole_hull_when_mending(bool whole) { whole_hull_checks_ = whole; }

  // For tests: mend hulls of at least this many vertices with a MendQueue, smaller ones by a
  // full scan after each removal (the two must agree). The default is where the queue pays.
  void queue_mending_from(std::size_t vertices) { queued_from_ = vertices; }

  // For tests: whether reducing the vertex count may infer what a line's scan reaches from the
  // line before it (see reach_from; with or without, the same hulls must come out).
  void infer_reaches(bool infer) { infer_reaches_ = infer; }
  // How many meeting points of two hull lines this fitter has tested (what inferring saves).
  std::uint64_t apex_tests() const { return apex_tests_; }
  // How many component vertices mending has looked at again for a candidate removal: those
  // nearest its three edges and any that may lie outside by rounding, not the whole component.
  std::uint64_t depth_visits() const { return depth_visits_; }

  // True when every point grown adds to known (convex, inside it) is within bound.
  bool growth_within(const Ring& grown, const Ring& known) const;

  // True when every component vertex lies in hull (or on its boundary, or outside it by
  // rounding) no deeper than allowed.
  bool holds_component(const Ring& hull) const;

  // True when every point of every component edge lies no deeper in hull (convex, holding the
  // component) than the deeper of its ends may.
  bool edges_within_depth(const Ring& hull) const;

  // hull with the edges rounding left a component vertex outside of moved out by a few units in
  // the last place; nullopt if that is not enough.
  std::optional<Ring> seal(Ring hull) const;

 private:
  // A component vertex's squared distance to the boundary of the hull being mended, as
  // holds_component measures it; the start of the first hull edge at that distance; whether it
  // is known not to lie outside that hull (exactly on its boundary, or located inside).
  struct VertexDepth {
    double squared;
    Vec2 edge_start;
    bool not_outside;
  };
  // Measures every component vertex in hull; true when every one passes holds_component.
  bool measure_depths(const Ring& hull, std::vector<VertexDepth>& depths) const;
  // The component's vertices and their depths in the hull being mended, found by the start of
  // the edge each was measured against (defined in hull_fitter.cpp).
  class DepthIndex;
  // holds_component(next()), for next() = hull less edge with its apex at `at` (see
  // mend_local_violations) and depths from a hull that passes: measures again only the vertices
  // the removal may move, listing what they become in changed.
  bool holds_component_after(Vec2 at, const std::function<const Ring&()>& next, const Ring& hull,
                             std::size_t edge, const DepthIndex& depths,
                             std::vector<std::pair<std::size_t, VertexDepth>>& changed) const;
  bool too_small(const Ring& hull) const;
  std::optional<Ring> reduce_vertex_count(const Ring& hull);
  // reduce_vertex_count's search, with reaches inferred or not; with, *refuted is set when a
  // polygon's inferred apex failed its check.
  std::optional<Ring> reduce_by_chains(const Ring& hull, bool* refuted);
  bool may_close_within_max_verts(const Ring& hull);
  std::size_t reach_from(const Ring& hull, std::size_t i, std::size_t limit);
  bool apex_within(const Ring& hull, std::size_t i, std::size_t j) const;
  bool clearly_beyond(const Ring& hull, std::size_t i, std::size_t j, Vec2 apex) const;

  const Region& component_;
  const std::vector<double>& allowed_;
  const OutlineDistance& reach_;
  bool reach_is_component_;
  bool edges_suffice_;
  bool whole_hull_checks_ = false;
  std::size_t queued_from_ = 64;
  double bound_;
  EngineLimits limits_;
  // Per edge line of the hull being reduced: how many lines on its scan is known to reach (see
  // reach_from), and whether the line after those is known to be beyond.
  std::vector<std::size_t> reach_known_;
  std::vector<char> beyond_after_known_;
  bool infer_reaches_ = true;
  bool inferring_ = false;  // whether reach_from infers a scan's first lines from the line before
  bool inferred_ = false;   // whether it did
  mutable std::uint64_t apex_tests_ = 0;
  mutable std::uint64_t depth_visits_ = 0;
  std::vector<double> corner_reach_;  // per vertex of the hull being reduced: its distance
  double outside_by_rounding_ = 0;    // how far a component vertex may lie outside that hull
  // reduce_vertex_count's chains: the one being followed, and those that closed.
  std::vector<std::size_t> chain_, closed_;
  std::vector<std::pair<std::size_t, std::size_t>> closed_spans_;  // (first, size) in closed_
};

}  // namespace hullcook
