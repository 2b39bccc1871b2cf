#include "crossing_sweep.h"

#include "hullcook/core/predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <set>

namespace hullcook::detail {
namespace {

// The sweep goes through the points in lexicographic order (x, then y): a sweep line tilted by an
// infinitesimal angle, which meets every segment, vertical ones too, at one point. A segment is
// in the status from its lexicographically first end (left) to its last (right).
bool before(Vec2 p, Vec2 q) { return p.x != q.x ? p.x < q.x : p.y < q.y; }

struct Event {
  Vec2 point;
  std::size_t edge;
  bool insert;
};

// The status: the edges the sweep line meets, from below to above. Only ever asked about the
// edge being inserted against one in the status: where the sweep line through the new edge's left
// end meets the other, below or above that end (and for edges from one point, by their
// directions). Edges in the status do not meet before the sweep line (a meeting ends the sweep),
// so their order is the geometric one.
struct SweepOrder {
  const std::vector<Vec2>* left;
  const std::vector<Vec2>* right;
  const std::size_t* inserting;

  // Whether the sweep line through left[s] meets s below t.
  bool below(std::size_t s, std::size_t t) const {
    const Vec2 a = (*left)[t], b = (*right)[t];
    const double at_start = fast_orient2d(a, b, (*left)[s]);
    if (at_start != 0.0) return at_start < 0.0;
    const double at_end = fast_orient2d(a, b, (*right)[s]);
    if (at_end != 0.0) return at_end < 0.0;
    return s < t;  // collinear: they overlap, which the test of neighbours reports
  }
  bool operator()(std::size_t a, std::size_t b) const {
    if (a == b) return false;
    return a == *inserting ? below(a, b) : !below(b, a);
  }
};

}  // namespace

// Why a meeting cannot go unseen. Let p be the first point, in sweep order, where two edges meet
// that may not. Before p the edges meet only at shared vertices, so the status is ordered. Edges
// whose interiors reach p from the left are, just before p, neighbours in the status (an edge
// between two of them reaches p too), and every two neighbours are tested when they become
// neighbours. Edges that end at p were neighbours of those that pass through p, or of another
// edge ending there. An edge that starts at p is inserted beside the edge through p (at most one,
// or two would have met before p), or beside an edge inserted at p before it, which meets that
// edge at p. Three or more edges with an end at p meet at p, and only two of them are
// consecutive: a pair of them is reported without the status.
std::optional<std::pair<std::size_t, std::size_t>> find_crossing_by_sweep(
    const std::vector<RingEdge>& edges, const std::vector<std::size_t>& ring_sizes) {
  const std::size_t n = edges.size();
  std::vector<Vec2> left(n), right(n);
  std::vector<Event> events;
  events.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool forward = before(edges[i].a, edges[i].b);
    left[i] = forward ? edges[i].a : edges[i].b;
    right[i] = forward ? edges[i].b : edges[i].a;
    events.push_back({left[i], i, true});
    events.push_back({right[i], i, false});
  }
  // At one point, the edges that end there leave before those that start there arrive.
  std::sort(events.begin(), events.end(), [](const Event& e, const Event& f) {
    if (e.point != f.point) return before(e.point, f.point);
    if (e.insert != f.insert) return !e.insert;
    return e.edge < f.edge;
  });
  auto meet = [&](std::size_t i, std::size_t j) {
    if (consecutive(edges[i], edges[j], ring_sizes)) return false;
    return segments_intersect(edges[i].a, edges[i].b, edges[j].a, edges[j].b);
  };
  auto pair = [](std::size_t i, std::size_t j) {
    return std::make_pair(std::min(i, j), std::max(i, j));
  };
  std::size_t inserting = 0;
  std::set<std::size_t, SweepOrder> status(SweepOrder{&left, &right, &inserting});
  std::vector<std::set<std::size_t, SweepOrder>::iterator> where(n);
  for (std::size_t first = 0; first < events.size();) {
    std::size_t last = first + 1;
    while (last < events.size() && events[last].point == events[first].point) ++last;
    if (last - first > 2) {
      for (std::size_t k = first; k < last; ++k) {
        for (std::size_t l = k + 1; l < last; ++l) {
          const std::size_t i = events[k].edge, j = events[l].edge;
          if (i != j && !consecutive(edges[i], edges[j], ring_sizes)) return pair(i, j);
        }
      }
    }
    for (std::size_t k = first; k < last; ++k) {
      const std::size_t edge = events[k].edge;
      if (!events[k].insert) {
        const auto it = where[edge];
        if (it != status.begin() && std::next(it) != status.end()) {
          const std::size_t below = *std::prev(it), above = *std::next(it);
          if (meet(below, above)) return pair(below, above);
        }
        status.erase(it);
        continue;
      }
      inserting = edge;
      const auto it = status.insert(edge).first;
      where[edge] = it;
      if (it != status.begin() && meet(*std::prev(it), edge)) return pair(*std::prev(it), edge);
      if (std::next(it) != status.end() && meet(edge, *std::next(it))) {
        return pair(edge, *std::next(it));
      }
    }
    first = last;
  }
  return std::nullopt;
}

}  // namespace hullcook::detail
