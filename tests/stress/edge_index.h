// The edges of a set of regions in a uniform grid: which edges come near a box, and where a point
// lies in one region, by a ray cast through the grid (exact, with the orientation predicate), in
// time proportional to the edges on the ray rather than to the whole boundary.
#pragma once

#include "box_grid.h"

#include "hullcook/core/geometry.h"

#include <cstddef>
#include <vector>

namespace hullcook::stress {

class EdgeIndex {
 public:
  struct Edge {
    Vec2 a, b;
    std::size_t region;
  };

  explicit EdgeIndex(const std::vector<Region>& regions);

  const Edge& edge(std::size_t i) const { return edges_[i]; }
  // Every edge whose box overlaps box.
  std::vector<std::size_t> near(const Bounds& box) { return grid_.query(box); }
  // Where p lies in region r (inside its outer ring and outside its holes), exactly.
  Location locate(std::size_t region, Vec2 p);
  // True when p lies inside or on the boundary of any of the regions.
  bool covers(Vec2 p);

 private:
  // Visits the edges the ray from p towards +x may cross.
  template <typename Visit>
  void cast(Vec2 p, Visit visit);

  std::vector<Edge> edges_;
  std::size_t regions_;
  BoxGrid grid_;
  Bounds extent_;
};

}  // namespace hullcook::stress
