#include "piece_merge.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <tuple>

namespace hullcook {
namespace {

struct Box {
  Vec2 low{std::numeric_limits<double>::infinity()};
  Vec2 high{-std::numeric_limits<double>::infinity()};
  void add(Vec2 p) { low = glm::min(low, p), high = glm::max(high, p); }
  bool holds(Vec2 p) const {
    return low.x <= p.x && p.x <= high.x && low.y <= p.y && p.y <= high.y;
  }
};

Box box_of(const Ring& ring) {
  Box box;
  for (Vec2 p : ring) box.add(p);
  return box;
}

// ring with every vertex of other that lies inside one of its edges inserted there, in order
// along the edge: a T-junction becomes a shared vertex.
Ring with_vertices_of(const Ring& ring, const Ring& other) {
  Box box = box_of(ring);
  Ring candidates;
  for (Vec2 p : other) {
    if (box.holds(p)) candidates.push_back(p);
  }
  Ring out;
  out.reserve(ring.size());
  Ring inside;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    Vec2 a = ring[i], b = ring[(i + 1) % n];
    out.push_back(a);
    inside.clear();
    for (Vec2 p : candidates) {
      if (p != a && p != b && on_segment(a, b, p)) inside.push_back(p);
    }
    std::sort(inside.begin(), inside.end(),
              [&](Vec2 p, Vec2 q) { return glm::dot(p - a, b - a) < glm::dot(q - a, b - a); });
    inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
    out.insert(out.end(), inside.begin(), inside.end());
  }
  return out;
}

bool lexicographic_less(Vec2 p, Vec2 q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); }

// Index j such that b[j] == from and b[j + 1] == to, or -1.
struct EdgeIndex {
  struct Entry {
    Vec2 from, to;
    std::size_t index;
  };
  std::vector<Entry> entries;

  static bool less(const Entry& x, const Entry& y) {
    if (x.from != y.from) return lexicographic_less(x.from, y.from);
    return lexicographic_less(x.to, y.to);
  }

  explicit EdgeIndex(const Ring& ring) {
    for (std::size_t j = 0, n = ring.size(); j < n; ++j) {
      entries.push_back({ring[j], ring[(j + 1) % n], j});
    }
    std::sort(entries.begin(), entries.end(), less);
  }

  long find(Vec2 from, Vec2 to) const {
    Entry key{from, to, 0};
    auto it = std::lower_bound(entries.begin(), entries.end(), key, less);
    if (it == entries.end() || it->from != from || it->to != to) return -1;
    return static_cast<long>(it->index);
  }
};

// Two consecutive edges of the union, meeting at their shared vertex: they must not fold back
// onto each other.
bool folds_back(Vec2 before, Vec2 shared, Vec2 after) {
  return orientation(before, shared, after) == 0 && glm::dot(before - shared, after - shared) > 0;
}

}  // namespace

bool meet_at_two_points(const Ring& a, const Ring& b) { return boundary_points_shared(a, b) == 2; }

int boundary_points_shared(const Ring& a, const Ring& b) {
  return shared_boundary_points(a, b).count;
}

SharedBoundaryPoints shared_boundary_points(const Ring& a, const Ring& b) {
  const Box a_box = box_of(a), b_box = box_of(b);
  auto on_boundary_of = [](const Ring& ring, const Box& box, Vec2 p) {
    if (!box.holds(p)) return false;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      if (on_segment(ring[i], ring[(i + 1) % n], p)) return true;
    }
    return false;
  };
  std::optional<Vec2> first;
  auto second_found = [&](const Ring& ring, const Ring& other, const Box& other_box) {
    for (Vec2 p : ring) {
      if (first && *first == p) continue;
      if (!on_boundary_of(other, other_box, p)) continue;
      if (first) return true;
      first = p;
    }
    return false;
  };
  if (second_found(a, b, b_box) || second_found(b, a, a_box)) return {2, *first};
  if (first) return {1, *first};
  return {};
}

std::optional<Region> merge_components(const Region& a_region, const Region& b_region) {
  if (!meet_at_two_points(a_region.outer, b_region.outer)) return std::nullopt;
  const Ring a = with_vertices_of(a_region.outer, b_region.outer);
  const Ring b = with_vertices_of(b_region.outer, a_region.outer);
  const std::size_t na = a.size(), nb = b.size();
  if (na < 3 || nb < 3) return std::nullopt;

  // Edge i of a (a[i] -> a[i + 1]) is shared when b runs along it the other way.
  EdgeIndex b_edges(b);
  std::vector<long> twin(na);
  std::size_t shared = 0, runs = 0;
  for (std::size_t i = 0; i < na; ++i) {
    twin[i] = b_edges.find(a[(i + 1) % na], a[i]);
    if (twin[i] >= 0) ++shared;
  }
  for (std::size_t i = 0; i < na; ++i) {
    if (twin[i] >= 0 && twin[(i + na - 1) % na] < 0) ++runs;
  }
  if (shared == 0 || shared == na || runs != 1) return std::nullopt;
  std::size_t start = 0;
  while (!(twin[start] >= 0 && twin[(start + na - 1) % na] < 0)) ++start;
  const std::size_t end = (start + shared) % na;  // a[start .. end] is the shared stretch
  // In b the stretch runs from a[end] = b[b_end] to a[start] = b[b_start].
  const std::size_t b_end = static_cast<std::size_t>(twin[(end + na - 1) % na]);
  const std::size_t b_start = (static_cast<std::size_t>(twin[start]) + 1) % nb;
  if ((b_end + shared) % nb != b_start || shared >= nb) return std::nullopt;

  // a's own part from a[end] to a[start], then b's own part strictly between a[start] and a[end].
  Ring a_part, b_part;
  for (std::size_t k = end;; k = (k + 1) % na) {
    a_part.push_back(a[k]);
    if (k == start) break;
  }
  for (std::size_t k = (b_start + 1) % nb; k != b_end; k = (k + 1) % nb) b_part.push_back(b[k]);

  // The two parts are each a piece of a simple ring; the union is simple when they meet only at
  // the stretch's ends.
  Ring merged = a_part;
  merged.insert(merged.end(), b_part.begin(), b_part.end());
  Ring sorted = merged;
  std::sort(sorted.begin(), sorted.end(), lexicographic_less);
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return std::nullopt;
  // b's edges run from a[start] through b_part back to a[end].
  Ring b_path{a[start]};
  b_path.insert(b_path.end(), b_part.begin(), b_part.end());
  b_path.push_back(a[end]);
  Box a_box = box_of(a_part);
  for (std::size_t j = 0; j + 1 < b_path.size(); ++j) {
    Vec2 c = b_path[j], d = b_path[j + 1];
    Box edge_box;
    edge_box.add(c), edge_box.add(d);
    if (edge_box.high.x < a_box.low.x || edge_box.low.x > a_box.high.x ||
        edge_box.high.y < a_box.low.y || edge_box.low.y > a_box.high.y) {
      continue;
    }
    for (std::size_t i = 0; i + 1 < a_part.size(); ++i) {
      Vec2 p = a_part[i], q = a_part[i + 1];
      // Edges that meet at an end of the stretch share only that point unless they fold back.
      bool meets_at_start = j == 0 && i + 2 == a_part.size();  // q == c == a[start]
      bool meets_at_end = j + 2 == b_path.size() && i == 0;    // p == d == a[end]
      if (meets_at_start && folds_back(p, q, d)) return std::nullopt;
      if (meets_at_end && folds_back(c, d, q)) return std::nullopt;
      if (meets_at_start || meets_at_end) continue;
      if (segments_intersect(p, q, c, d)) return std::nullopt;
    }
  }

  remove_degenerate_vertices_in_place(merged);
  if (merged.size() < 3) return std::nullopt;
  Region region{std::move(merged), a_region.holes};
  region.holes.insert(region.holes.end(), b_region.holes.begin(), b_region.holes.end());
  return region;
}

}  // namespace hullcook
