#include "edge_index.h"

#include "hullcook/core/predicates.h"

#include <algorithm>

namespace hullcook::stress {
namespace {

std::vector<EdgeIndex::Edge> edges_of(const std::vector<Region>& regions) {
  std::vector<EdgeIndex::Edge> edges;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    auto add = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        edges.push_back({ring[i], ring[(i + 1) % ring.size()], r});
      }
    };
    add(regions[r].outer);
    for (const Ring& hole : regions[r].holes) add(hole);
  }
  return edges;
}

std::vector<Bounds> bounds_of_edges(const std::vector<EdgeIndex::Edge>& edges) {
  std::vector<Bounds> bounds;
  bounds.reserve(edges.size());
  for (const EdgeIndex::Edge& edge : edges) bounds.push_back(bounds_of(edge.a, edge.b));
  return bounds;
}

}  // namespace

EdgeIndex::EdgeIndex(const std::vector<Region>& regions)
    : edges_(edges_of(regions)), regions_(regions.size()), grid_(bounds_of_edges(edges_)) {
  for (const Edge& edge : edges_) {
    extent_.add(edge.a);
    extent_.add(edge.b);
  }
}

// The ray from p towards +x crosses a region's boundary an odd number of times when p is inside
// it. An edge counts when it spans p's height half-open (lower end included), so that a ray
// through a vertex counts it once; visit(edge, crossed) returns false to stop at a boundary.
template <typename Visit>
void EdgeIndex::cast(Vec2 p, Visit visit) {
  Bounds ray;
  ray.add(p);
  ray.add({extent_.high.x, p.y});
  for (std::size_t i : grid_.query(ray)) {
    const Edge& edge = edges_[i];
    if (on_segment(edge.a, edge.b, p)) {
      if (!visit(edge, false, true)) return;
      continue;
    }
    const bool a_below = edge.a.y <= p.y, b_below = edge.b.y <= p.y;
    if (a_below == b_below) continue;
    const int side = orientation(edge.a, edge.b, p);  // p left of a->b: +1
    if (a_below ? side > 0 : side < 0) {
      if (!visit(edge, true, false)) return;
    }
  }
}

Location EdgeIndex::locate(std::size_t region, Vec2 p) {
  if (!extent_.contains(p)) return Location::outside;
  bool inside = false, boundary = false;
  cast(p, [&](const Edge& edge, bool crossed, bool on) {
    if (edge.region != region) return true;
    boundary = on;
    inside = inside != crossed;
    return !on;
  });
  if (boundary) return Location::boundary;
  return inside ? Location::inside : Location::outside;
}

bool EdgeIndex::covers(Vec2 p) {
  if (!extent_.contains(p)) return false;
  std::vector<char> inside(regions_, 0);
  bool boundary = false;
  cast(p, [&](const Edge& edge, bool crossed, bool on) {
    boundary = on;
    inside[edge.region] ^= crossed;
    return !on;
  });
  return boundary || std::find(inside.begin(), inside.end(), 1) != inside.end();
}

}  // namespace hullcook::stress
