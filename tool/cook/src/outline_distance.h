// Distances to an asset's outline for the engine limits: a hull may reach anywhere within τ of
// the outline (the union of the pieces' components), and these queries prove it rather than
// sample it.
#pragma once

#include "hullcook/core/buckets.h"
#include "hullcook/core/polygon.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace hullcook {

class OutlineDistance {
 public:
  // The union of components that partition an outline. An edge two components share (in
  // opposite directions: a cut) lies inside the outline and is left out.
  explicit OutlineDistance(const std::vector<const Region*>& components);

  // True when p is inside the outline. Near the boundary (within rounding) either answer may
  // come back; every caller also measures the distance to the boundary.
  bool contains(Vec2 p) const;

  // Distance from p to the outline: 0 inside. Beyond limit, some value above limit (the search
  // stops there). nearest, when given and p is outside within limit: the boundary edge at that
  // distance (else left as it is).
  struct EdgeSpan {
    Vec2 a, b;
  };
  double distance(Vec2 p, double limit, EdgeSpan* nearest = nullptr) const;
  // True when the outline is one convex polygon (one ring, no hole, turning left at every vertex
  // by exact orientations, winding once). The distance to it is then a convex function: along a
  // segment it is at most the larger of the distances at its ends.
  bool is_convex() const { return convex_; }

  // How many distance() calls this object has answered (what the fitters' shortcuts save).
  std::uint64_t distance_queries() const { return distance_queries_; }

  // True when every point of segment ab is within tau of the outline: the points within tau of
  // each boundary edge form one interval of the segment (a capsule is convex), and what the
  // intervals leave uncovered must be inside the outline.
  bool segment_within(Vec2 a, Vec2 b, double tau) const;

  // True when every point of the boundary of the convex polygon grown that is not in the convex
  // polygon known (known inside grown; empty for none) is within tau of the outline.
  bool new_edges_within(const Ring& grown, const Ring& known, double tau) const;

  // new_edges_within, and every point of grown's area outside known within tau as well, proven
  // by cells: each by the distance at its centre plus its radius (distance is 1-Lipschitz). A
  // hull whose edges pass may still enclose a hole of the outline, or grow past a deep pocket.
  // Cells of about 1e-10 tau are taken when their centre is within tau plus their radius; a
  // polygon that needs more than a few thousand cells is refused.
  bool growth_within(const Ring& grown, const Ring& known, double tau) const;

  // For grown() made from known by moving one vertex out to an apex on the lines of its edges
  // (and dropping its successor: known's edge `edge` removed, its neighbours meeting at `at`):
  // its two edges at that apex as new_edges_within checks them, and with_cells, the area as
  // growth_within proves it. The other edges are known's, and no other vertex lies beyond a line
  // of known. grown() is asked for only with cells.
  bool apex_growth_within(Vec2 at, const std::function<const Ring&()>& grown, const Ring& known,
                          std::size_t edge, bool with_cells, double tau) const;

 private:
  using Edge = EdgeSpan;

  int column_of(double x) const;
  int row_of(double y) const;
  // distance() without counting the query.
  double measure(Vec2 p, double limit, EdgeSpan* nearest) const;
  // Calls visit(column, row) for each cell that may hold a point within radius of segment ab.
  template <typename Visit>
  void for_each_cell_near(Vec2 a, Vec2 b, double radius, Visit visit) const;
  // Calls visit(edge index) once for each edge registered in a cell that may lie within radius
  // of segment ab; a visit that returns bool stops the walk by returning false.
  template <typename Visit>
  void for_each_edge_near(Vec2 a, Vec2 b, double radius, Visit visit) const;
  // new_edges_within for one edge ab of grown, whose part inside known lies left of known's
  // edges first .. first + count - 1 (cyclically).
  bool new_part_within(Vec2 a, Vec2 b, const Ring& known, std::size_t first, std::size_t count,
                       double tau) const;
  // growth_within's proof by cells, for every edge of known that a point of candidates (those of
  // grown that may lie beyond one) lies beyond.
  bool cells_beyond_within(const Ring& grown, const Ring& candidates, const Ring& known,
                           double tau) const;
  // growth_within's proof by cells of the convex region, less known.
  bool cells_within(const Ring& region, const Ring& known, double tau, int& budget) const;
  // True when no boundary edge meets the square and its centre is inside the outline.
  bool square_inside(Vec2 centre, double half) const;
  // contains() by a cell's centre: see there.
  static constexpr std::size_t kRowEdgesWorthACellsCentre = 64;
  static constexpr signed char kUnknown = -1, kOutside = 0, kInside = 1, kOnTheOutline = 2;
  static bool crosses(Vec2 centre, Vec2 p, Vec2 a, Vec2 b);
  signed char centre_side(std::size_t cell, Vec2 centre) const;

  std::vector<Edge> edges_;
  bool convex_ = false;
  Vec2 origin_{0, 0};  // the grid's lower corner
  double cell_ = 1;
  int columns_ = 0, rows_ = 0;
  // Edge indices by cell, and by row of cells (for the ray crossing test).
  Buckets<std::uint32_t, std::uint32_t> cell_edges_, row_edges_;
  mutable std::vector<std::uint32_t> visited_;      // per edge: the query that last saw it
  mutable std::vector<signed char> centre_inside_;  // per cell: its centre's side, once asked
  mutable std::vector<std::pair<double, double>> covered_;  // segment_within's intervals
  mutable std::uint32_t query_ = 0;
  mutable std::uint64_t distance_queries_ = 0;
};

}  // namespace hullcook
