#include "diagonals.h"

#include "hull_fitter.h"

#include "hullcook/cook/contract.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcook {
namespace {

// Whether the segment from ring[i] to ring[j] leaves each end into the interior angle there
// (exact), the ring being simple and counter-clockwise.
bool leaves_into_interior(const Ring& ring, std::size_t i, std::size_t j) {
  const std::size_t n = ring.size();
  auto into_interior = [&](std::size_t at, Vec2 toward) {
    const Vec2 before = ring[(at + n - 1) % n], p = ring[at], after = ring[(at + 1) % n];
    if (orientation(p, after, before) >= 0) {
      return orientation(p, toward, before) > 0 && orientation(toward, p, after) > 0;
    }
    return !(orientation(p, toward, after) >= 0 && orientation(toward, p, before) >= 0);
  };
  return into_interior(i, ring[j]) && into_interior(j, ring[i]);
}

// Whether edge k of a ring of n (from a to b) meets the segment from p = ring[i] to q = ring[j]
// other than at an end it shares with it (exact). An edge whose box misses the segment's cannot
// meet it (exact comparisons).
bool edge_meets(std::size_t k, std::size_t n, Vec2 a, Vec2 b, std::size_t i, std::size_t j, Vec2 p,
                Vec2 q) {
  if (std::max(a.x, b.x) < std::min(p.x, q.x) || std::min(a.x, b.x) > std::max(p.x, q.x) ||
      std::max(a.y, b.y) < std::min(p.y, q.y) || std::min(a.y, b.y) > std::max(p.y, q.y)) {
    return false;
  }
  const std::size_t next = k + 1 == n ? 0 : k + 1;
  if (k == i || k == j || next == i || next == j) return false;
  return segments_intersect(p, q, a, b);
}

}  // namespace

std::optional<std::pair<Ring, Ring>> halve_convex(const Ring& polygon, double slack,
                                                  bool* only_slivers) {
  const std::size_t n = polygon.size();
  if (n < 4) return std::nullopt;
  auto halves_from = [&](std::size_t start) -> std::optional<std::pair<Ring, Ring>> {
    const std::size_t middle = start + n / 2;
    // "Convex" within rounding (see is_convex_without_holes): a notch of 1e-12 of its size lets
    // the diagonal cross the boundary (at --max-verts 3, 1e-6 across: halves that intersect
    // themselves, an internal error).
    if (!is_inner_diagonal(polygon, start % n, middle % n)) return std::nullopt;
    Region first, second;
    for (std::size_t k = start; k <= middle; ++k) first.outer.push_back(polygon[k % n]);
    for (std::size_t k = middle; k <= start + n; ++k) second.outer.push_back(polygon[k % n]);
    if (!(signed_area(first.outer) > 0) || !(signed_area(second.outer) > 0)) return std::nullopt;
    if (is_contract_sliver(first, slack) || is_contract_sliver(second, slack)) {
      *only_slivers = true;
      return std::nullopt;
    }
    return std::pair{std::move(first.outer), std::move(second.outer)};
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (turn_height(polygon, i) > 0) continue;
    if (auto halves = halves_from(i)) return halves;
  }
  for (std::size_t start = 0; start < n; ++start) {
    if (auto halves = halves_from(start)) return halves;
  }
  return std::nullopt;
}

bool is_inner_diagonal(const Ring& ring, std::size_t i, std::size_t j) {
  if (!leaves_into_interior(ring, i, j)) return false;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (edge_meets(k, n, ring[k], ring[k + 1 == n ? 0 : k + 1], i, j, ring[i], ring[j])) {
      return false;
    }
  }
  return true;
}

RunsOfRing::RunsOfRing(const Ring& base) : base_(base) {
  for (std::size_t begin = 0; begin + 1 < base.size(); begin += kEdges) {
    const std::size_t last = std::min(begin + kEdges, base.size() - 1);
    Bounds box{base[begin], base[begin]};
    for (std::size_t v = begin + 1; v <= last; ++v) {
      box.low = glm::min(box.low, base[v]), box.high = glm::max(box.high, base[v]);
    }
    boxes_.push_back(box);
  }
}

bool RunsOfRing::is_inner_diagonal(const Ring& ring, std::size_t first, std::size_t i,
                                   std::size_t j) const {
  if (!leaves_into_interior(ring, i, j)) return false;
  const std::size_t n = ring.size();
  const Vec2 p = ring[i], q = ring[j];
  // The closing edge, then the run's edges (base's first .. first + n - 2), box by box.
  if (edge_meets(n - 1, n, ring[n - 1], ring[0], i, j, p, q)) return false;
  for (std::size_t box = first / kEdges; box * kEdges < first + n - 1; ++box) {
    if (box_misses(boxes_[box], p, q)) continue;
    const std::size_t begin = std::max(first, box * kEdges);
    const std::size_t end = std::min(first + n - 1, (box + 1) * kEdges);
    for (std::size_t e = begin; e < end; ++e) {
      if (edge_meets(e - first, n, base_[e], base_[e + 1], i, j, p, q)) return false;
    }
  }
  return true;
}

// Whether the segment from p to q surely misses the box: their boxes are apart (exact), or every
// corner lies on one side of the segment's line by far more than the rounding of the side's
// computation (a few units in the last place of its terms).
bool RunsOfRing::box_misses(const Bounds& box, Vec2 p, Vec2 q) {
  if (box.high.x < std::min(p.x, q.x) || box.low.x > std::max(p.x, q.x) ||
      box.high.y < std::min(p.y, q.y) || box.low.y > std::max(p.y, q.y)) {
    return true;
  }
  const Vec2 d = q - p;
  const double scale = std::abs(d.x) + std::abs(d.y);
  int above = 0, below = 0;
  for (Vec2 corner :
       {box.low, box.high, Vec2{box.low.x, box.high.y}, Vec2{box.high.x, box.low.y}}) {
    const Vec2 r = corner - p;
    const double side = d.x * r.y - d.y * r.x;
    const double error = 1e-12 * (std::abs(d.x * r.y) + std::abs(d.y * r.x) +
                                  scale * (std::abs(corner.x) + std::abs(corner.y) + std::abs(p.x) +
                                           std::abs(p.y) + std::abs(q.x) + std::abs(q.y)));
    above += side > error;
    below += side < -error;
  }
  return above == 4 || below == 4;
}

std::optional<std::pair<Ring, Ring>> halve_along_diagonal(const Ring& ring, double slack) {
  const std::size_t n = ring.size();
  if (n < 4) return std::nullopt;
  const std::size_t starts = std::min<std::size_t>(n / 2, 32);
  std::optional<std::size_t> best;
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < starts; ++s) {
    const std::size_t i = s * (n / 2) / starts, j = i + n / 2;
    const double length = glm::length(ring[j] - ring[i]);
    if (length < shortest && is_inner_diagonal(ring, i, j)) shortest = length, best = i;
  }
  if (!best) return std::nullopt;
  Region first, second;
  for (std::size_t k = *best; k <= *best + n / 2; ++k) first.outer.push_back(ring[k]);
  for (std::size_t k = *best + n / 2; k <= *best + n; ++k) second.outer.push_back(ring[k % n]);
  if (!(signed_area(first.outer) > 0) || !(signed_area(second.outer) > 0) ||
      is_contract_sliver(first, slack) || is_contract_sliver(second, slack)) {
    return std::nullopt;
  }
  return std::pair{std::move(first.outer), std::move(second.outer)};
}

}  // namespace hullcook
