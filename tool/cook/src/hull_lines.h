// The edge lines of a convex hull, as the contract check measures a component against them. Inside
// the hull, the distance to its boundary is the least distance to these lines, and the distance to
// one line is affine along a segment: a segment whose two ends lie within τ of one line lies within
// τ of the boundary. Lines are grouped in runs of consecutive edges (and runs of runs) with bounds
// on what their distances can be, so that a query skips the runs that cannot hold its answer: a
// hull of 100,000 vertices took 38 s to check against its own component, every vertex against every
// line.
#pragma once

#include "hullcook/core/polygon.h"
#include "runs.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace hullcook {

class HullLines {
 public:
  // The lines of hull (convex, counter-clockwise), replacing any it held (one object serves every
  // piece of a level).
  void assign(const Ring& hull);

  std::size_t size() const { return from_.size(); }

  // Positive inside (left of the counter-clockwise edge k) [units].
  double distance(std::size_t k, Vec2 p) const {
    return direction_[k].x * (p.y - from_[k].y) - direction_[k].y * (p.x - from_[k].x);
  }

  // The least distance of p to the lines, and the line that gives it (the lowest index of those
  // that do), as a scan of every line finds them. hint: a line to measure first (any index).
  std::pair<double, std::size_t> nearest(Vec2 p, std::size_t hint = 0) const {
    if (use_runs_) return nearest_by_runs(p, hint);
    // Most hulls: a plain loop, inlined where the contract check measures every vertex.
    std::pair<double, std::size_t> best{std::numeric_limits<double>::infinity(), 0};
    for (std::size_t k = 0; k < size(); ++k) best = std::min(best, {distance(k, p), k});
    return best;
  }

  // Whether one line lies within limit of both p and q (the nearest line of a point on two is
  // either).
  bool one_within(Vec2 p, Vec2 q, double limit) const {
    if (use_runs_) return one_within_by_runs(p, q, limit);
    for (std::size_t k = 0; k < size(); ++k) {
      if (distance(k, p) <= limit && distance(k, q) <= limit) return true;
    }
    return false;
  }

  // The largest, over the segment pq, of the least distance to the lines, and where: a concave
  // function of the position along pq, so its slope's sign leads a bisection to the top.
  std::pair<double, Vec2> farthest_on(Vec2 p, Vec2 q) const;

 private:
  // What the lines of a run have: their directions' and their starts' coordinate ranges.
  struct Bounds {
    double direction_x[2], direction_y[2], from_x[2], from_y[2];
  };
  std::pair<double, std::size_t> nearest_by_runs(Vec2 p, std::size_t hint) const;
  bool one_within_by_runs(Vec2 p, Vec2 q, double limit) const;
  // A value no line of the run has a distance from p below, up to rounding (see margin_).
  static double least_distance(const Bounds& bounds, Vec2 p);
  // Calls visit(k) for every line whose distance from each point may be at most the bound that
  // bound() gives at the time, in index order, until visit returns false (with the runs only).
  template <typename Bound, typename Visit>
  void for_each_line_within(Vec2 p, Vec2 q, Bound&& bound, Visit&& visit) const;

  std::vector<Vec2> from_, direction_;
  Runs<Bounds> runs_;
  // Beyond any difference rounding makes between a distance and its run's bound [units].
  double margin_ = 0;
  bool use_runs_ = false;
};

}  // namespace hullcook
