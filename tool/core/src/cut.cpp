#include "cut.h"

#include "hullcook/core/geometry.h"
#include "predicates_inline.h"

#include <algorithm>

namespace hullcook::detail {
namespace {

// The chain of ring from first to last (cyclic), cleaned of the repeated and collinear vertices
// the cut leaves at its seam. The ring is clean, so remove_degenerate_vertices_in_place would
// only ever remove vertices at the seam: this does the same removals without looking at every
// vertex. Returns the ring index of the chain's first kept vertex (the rest follow in order).
std::size_t cut_chain(const Ring& ring, std::size_t first, std::size_t last, Ring& out) {
  const std::size_t n = ring.size();
  if (first <= last) {
    out.assign(ring.begin() + std::ptrdiff_t(first), ring.begin() + std::ptrdiff_t(last) + 1);
  } else {
    out.reserve(last + n - first + 1);
    out.assign(ring.begin() + std::ptrdiff_t(first), ring.end());
    out.insert(out.end(), ring.begin(), ring.begin() + std::ptrdiff_t(last) + 1);
  }
  std::size_t front = 0;  // vertices erased at the front, done by one shift at the end
  auto size = [&] { return out.size() - front; };
  auto at = [&](std::size_t k) { return out[front + k]; };
  bool changed = true;
  while (changed && size() >= 3) {
    changed = false;
    const std::size_t m = size();
    if (at(m - 1) == at(0) || detail::fast_orient2d(at(m - 2), at(m - 1), at(0)) == 0.0) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(at(m - 1), at(0), at(1)) == 0.0) {
      ++front;
      changed = true;
    }
  }
  if (front > 0) out.erase(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(front));
  if (out.size() == 2 && out[0] == out[1]) out.pop_back();
  return (first + front) % n;
}

// Gives each hole of a region but cut_hole (kNone: none) to the piece of the two cut from it that
// holds it, and records where the pieces' holes come from (ParentHint::hole_source). A hole the
// cuts do not touch lies strictly inside the region and off the cuts, so inside exactly one
// piece: its first vertex is located in the smaller ring only, by locate_point's crossing count
// without its test for a point on each edge, for all the holes in one pass.
// A piece cut between two holes (other_cut_hole) keeps the region's outer ring: the holes are
// located in the other piece's ring, the one between the two holes (search_first_only).
void distribute_holes(const Region& region, std::size_t cut_hole, std::pair<Region, Region>& pieces,
                      std::pair<ParentHint, ParentHint>& hints, std::size_t other_cut_hole = kNone,
                      bool search_first_only = false) {
  const bool search_first =
      search_first_only || pieces.first.outer.size() <= pieces.second.outer.size();
  const Ring& ring = search_first ? pieces.first.outer : pieces.second.outer;
  // An edge a-b crosses the horizontal line through p where min(a.y, b.y) <= p.y < max(a.y, b.y):
  // the holes' first vertices by height find the few that an edge crosses.
  std::vector<std::pair<double, std::size_t>> by_height;
  for (std::size_t o = 0; o < region.holes.size(); ++o) {
    if (o != cut_hole && o != other_cut_hole) by_height.emplace_back(region.holes[o][0].y, o);
  }
  std::sort(by_height.begin(), by_height.end());
  std::vector<char> inside(region.holes.size(), 0);
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size() && !by_height.empty(); j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    const double low = std::min(a.y, b.y), high = std::max(a.y, b.y);
    auto point = std::lower_bound(by_height.begin(), by_height.end(), low,
                                  [](const auto& entry, double y) { return entry.first < y; });
    for (; point != by_height.end() && point->first < high; ++point) {
      const double side = detail::fast_orient2d(a, b, region.holes[point->second][0]);
      if ((b.y > a.y) ? side > 0.0 : side < 0.0) inside[point->second] ^= 1;
    }
  }
  for (std::size_t o = 0; o < region.holes.size(); ++o) {
    if (o == cut_hole || o == other_cut_hole) continue;
    const bool in_first = (inside[o] != 0) == search_first;
    (in_first ? pieces.first : pieces.second).holes.push_back(region.holes[o]);
    (in_first ? hints.first : hints.second).hole_source.push_back(o);
  }
}

// The hint (see ParentHint) of a child of size vertices whose vertex k < from_parent is the
// parent's vertex (source_first + k) % parent.on_hull.size(); the rest (a hole's chain) lie inside
// the parent, so off its hull and outside its pockets. The parent's values are inherited unless
// with_values is false.
void child_hint(const OuterConcavity& parent, std::size_t source_first, std::size_t size,
                std::size_t from_parent, bool with_values, ParentHint& hint) {
  hint.reset();
  hint.source_first = source_first, hint.from_parent = from_parent;
  const std::vector<char>& parent_on_hull = parent.on_hull;
  const std::size_t n = parent_on_hull.size();
  if (n == 0) return;
  // The child's vertex k is the parent's vertex source(k).
  auto source = [&](std::size_t k) {
    return source_first + k < n ? source_first + k : source_first + k - n;
  };
  std::size_t known_first = 0;
  while (known_first < from_parent && !parent_on_hull[source(known_first)]) ++known_first;
  if (known_first == from_parent) return;
  std::size_t known_last = from_parent - 1;
  while (!parent_on_hull[source(known_last)]) --known_last;
  // The child's ends (from its last parent hull point round to its first) are fresh, unless both
  // cut ends lie in one parent pocket: then that pocket's bridge is still a hull edge of the child
  // (the child is on the parent's side of it), and the ends lie inside the pocket.
  bool ends_in_one_pocket = known_first < known_last;
  if (ends_in_one_pocket) {
    const std::size_t bridge_end = (source_first + known_first) % n;
    for (std::size_t i = next_index((source_first + known_last) % n, n); i != bridge_end;
         i = next_index(i, n)) {
      if (parent_on_hull[i]) {
        ends_in_one_pocket = false;
        break;
      }
    }
  }
  std::vector<signed char>& code = hint.code;
  std::vector<std::size_t>& candidates = hint.hull_candidates;
  hint.known_first = known_first, hint.known_last = known_last;
  hint.start = kNone;
  candidates.reserve(ends_in_one_pocket ? known_last - known_first + 1 : size);
  code.assign(size, ends_in_one_pocket ? kInsideCutPocket : kFresh);
  if (ends_in_one_pocket) {
    std::fill(code.begin() + std::ptrdiff_t(from_parent), code.end(), kInsideAddedChain);
  } else {
    for (std::size_t k = 0; k < known_first; ++k) candidates.push_back(k);
  }
  constexpr signed char kCodeOfOnHull[3] = {kInsideKeptPocket, kParentHullPoint, kParentHullVertex};
  for (std::size_t k = known_first; k <= known_last; ++k) {
    const char on_hull = parent_on_hull[source(k)];
    code[k] = kCodeOfOnHull[static_cast<std::size_t>(on_hull)];
    if (on_hull == 2 || (on_hull == 1 && (k == known_first || k == known_last))) {
      if (on_hull == 2 && hint.start == kNone) hint.start = candidates.size();
      candidates.push_back(k);
    }
  }
  if (!ends_in_one_pocket) {
    for (std::size_t k = known_last + 1; k < size; ++k) candidates.push_back(k);
  }
  if (with_values) {
    // In two runs: the source wraps round the parent's end at most once. The added chain's
    // vertices (from from_parent on) inherit nothing: zero.
    const std::size_t before_wrap = std::min(from_parent, n - source_first);
    const auto from = parent.vertex.begin() + std::ptrdiff_t(source_first);
    hint.value.reserve(size);
    hint.value.assign(from, from + std::ptrdiff_t(before_wrap));
    hint.value.insert(hint.value.end(), parent.vertex.begin(),
                      parent.vertex.begin() + std::ptrdiff_t(from_parent - before_wrap));
    hint.value.resize(size);
  }
}

// remove_degenerate_vertices_in_place on rings made of chains of clean rings, in two steps:
// append_without_degeneracies for each chain, then close_without_degeneracies. Only the seams
// need its tests: three consecutive vertices of a clean ring are distinct and not collinear, so
// once the last two vertices kept are a chain's, the rest of the chain is kept as it is.
void append_without_degeneracies(const Ring& ring, std::size_t from, std::size_t to, Ring& out) {
  const std::size_t n = ring.size();
  for (std::size_t k = from, step = 0;; k = next_index(k, n), ++step) {
    const std::size_t kept = out.size();
    if (step >= 2 && kept >= 2 && out[kept - 1] == ring[prev_index(k, n)] &&
        out[kept - 2] == ring[prev_index(prev_index(k, n), n)]) {
      const auto begin = ring.begin();
      if (k <= to) {
        out.insert(out.end(), begin + std::ptrdiff_t(k), begin + std::ptrdiff_t(to) + 1);
      } else {
        out.insert(out.end(), begin + std::ptrdiff_t(k), ring.end());
        out.insert(out.end(), begin, begin + std::ptrdiff_t(to) + 1);
      }
      return;
    }
    const Vec2 p = ring[k];
    while (out.size() >= 2 && detail::fast_orient2d(out[out.size() - 2], out.back(), p) == 0.0) {
      out.pop_back();
    }
    if (out.empty() || out.back() != p) out.push_back(p);
    if (k == to) return;
  }
}

void close_without_degeneracies(Ring& out) {
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    if (out.back() == out.front()) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(out[out.size() - 2], out.back(), out.front()) == 0.0) {
      out.pop_back();
      changed = true;
    } else if (detail::fast_orient2d(out.back(), out[0], out[1]) == 0.0) {
      out.erase(out.begin());
      changed = true;
    }
  }
  if (out.size() == 2 && out[0] == out[1]) out.pop_back();
}

// The hint of a piece cut by split_hole: its ring starts with the outer chain from `from` to `to`,
// less the vertices the seams removed, then runs along the hole.
void hole_piece_hint(const Ring& outer, const OuterConcavity& parent, bool with_values,
                     std::size_t from, std::size_t to, const Ring& piece, ParentHint& hint) {
  const std::size_t n = outer.size();
  hint.reset();
  if (piece.empty() || parent.on_hull.size() != n) return;
  std::size_t first = from, chain = (to + n - from) % n + 1;
  while (chain > 0 && outer[first] != piece[0]) first = next_index(first, n), --chain;
  std::size_t from_parent = 0;
  while (from_parent < chain && from_parent < piece.size() &&
         piece[from_parent] == outer[(first + from_parent) % n]) {
    ++from_parent;
  }
  if (from_parent == 0) return;
  child_hint(parent, first, piece.size(), from_parent, with_values, hint);
}

}  // namespace

// Cuts the outer ring along the diagonal i-j; holes go to the piece containing them. Fills the
// children's hull hints from the parent's hull points.
std::pair<Region, Region> split_outer(const Region& region, std::size_t i, std::size_t j,
                                      const OuterConcavity& parent, bool with_values,
                                      std::pair<ParentHint, ParentHint>& hints) {
  const Ring& ring = region.outer;
  std::pair<Region, Region> pieces;
  Region& first = pieces.first;
  Region& second = pieces.second;
  const std::size_t first_source = cut_chain(ring, i, j, first.outer);
  child_hint(parent, first_source, first.outer.size(), first.outer.size(), with_values,
             hints.first);
  const std::size_t second_source = cut_chain(ring, j, i, second.outer);
  child_hint(parent, second_source, second.outer.size(), second.outer.size(), with_values,
             hints.second);
  distribute_holes(region, kNone, pieces, hints);
  return pieces;
}

// Cuts along hole[p]-outer[x] and hole[q]-outer[y] (x != y): two pieces without that hole. Fills
// the pieces' hull hints from the parent's hull points.
std::pair<Region, Region> split_hole(const Region& region, std::size_t h, std::size_t p,
                                     std::size_t x, std::size_t q, std::size_t y,
                                     const OuterConcavity& parent, bool with_values,
                                     std::pair<ParentHint, ParentHint>& hints) {
  const Ring& outer = region.outer;
  const Ring& hole = region.holes[h];
  const std::size_t n = outer.size(), m = hole.size();
  std::pair<Region, Region> pieces;
  Region& first = pieces.first;
  Region& second = pieces.second;
  first.outer.reserve((y + n - x) % n + (p + m - q) % m + 2);
  append_without_degeneracies(outer, x, y, first.outer);
  append_without_degeneracies(hole, q, p, first.outer);
  close_without_degeneracies(first.outer);
  hole_piece_hint(outer, parent, with_values, x, y, first.outer, hints.first);
  second.outer.reserve((x + n - y) % n + (q + m - p) % m + 2);
  append_without_degeneracies(outer, y, x, second.outer);
  append_without_degeneracies(hole, p, q, second.outer);
  close_without_degeneracies(second.outer);
  hole_piece_hint(outer, parent, with_values, y, x, second.outer, hints.second);
  hints.first.chain_hole = hints.second.chain_hole = h;
  hints.first.chain_first = q, hints.second.chain_first = p;
  distribute_holes(region, h, pieces, hints);
  return pieces;
}

// Cuts along hole[p]-other[u] and hole[q]-other[v] between two holes (p != q, u != v): the piece
// between the cuts, and the region with the two holes and that piece merged into one hole. The
// two rings the cuts close are each a chain of either hole in its own (clockwise) order: the
// piece's runs counter-clockwise, the merged hole's clockwise. The outer ring is kept whole, so the
// remainder inherits its measure; nullopt when the rings do not come out as one of each.
std::optional<std::pair<Region, Region>> split_between_holes(
    const Region& region, std::size_t h, std::size_t p, std::size_t q, std::size_t other,
    std::size_t u, std::size_t v, const OuterConcavity& parent, bool with_values,
    std::pair<ParentHint, ParentHint>& hints) {
  const Ring& hole = region.holes[h];
  const Ring& across = region.holes[other];
  Ring between, merged;
  append_without_degeneracies(hole, p, q, between);
  append_without_degeneracies(across, v, u, between);
  close_without_degeneracies(between);
  append_without_degeneracies(hole, q, p, merged);
  append_without_degeneracies(across, u, v, merged);
  close_without_degeneracies(merged);
  if (between.size() < 3 || merged.size() < 3) return std::nullopt;
  // Which of the two is the piece depends on which side of the holes p precedes q.
  if (signed_area(between) < 0.0) std::swap(between, merged);
  if (!(signed_area(between) > 0.0 && signed_area(merged) < 0.0)) return std::nullopt;
  std::pair<Region, Region> pieces;
  hints.first.reset();
  child_hint(parent, 0, region.outer.size(), region.outer.size(), with_values, hints.second);
  pieces.first.outer = std::move(between);
  pieces.second.outer = region.outer;
  distribute_holes(region, h, pieces, hints, other, true);
  pieces.second.holes.push_back(std::move(merged));
  hints.second.hole_source.push_back(kNone);
  return pieces;
}

// What a piece keeps of its parent's HoleEnds (see ParentHint::hole_ends): a hole keeps its
// antipodal pair, and the vertex nearest to an end where the piece keeps that vertex and no other
// vertex was as near. The piece's vertices are some of the parent's, so none is nearer.
void inherit_hole_ends(const Region& parent, const std::vector<HoleEnds>& parent_ends,
                       const Region& piece, ParentHint& hint) {
  if (parent_ends.size() != parent.holes.size() || hint.hole_source.size() != piece.holes.size()) {
    return;
  }
  std::vector<int> ring_in_piece(parent.holes.size() + 1, -1);  // by the parent's ring id
  for (std::size_t c = 0; c < piece.holes.size(); ++c) {
    if (hint.hole_source[c] != kNone)
      ring_in_piece[hint.hole_source[c] + 1] = static_cast<int>(c + 1);
  }
  const std::size_t n = parent.outer.size();
  // On the piece's outer ring at k, if it is there: a piece's vertices are distinct.
  auto on_outer = [&](const NearVertex& nearest, std::size_t k, Vec2 point) -> NearVertex {
    if (k >= piece.outer.size() || piece.outer[k] != point) return {};
    return {nearest.distance, 0, k, true};
  };
  auto in_piece = [&](const NearVertex& nearest) -> NearVertex {
    if (!nearest.unique) return {};
    if (nearest.ring == 0) {
      const std::size_t k = (nearest.index + n - hint.source_first % n) % n;
      return k < hint.from_parent ? on_outer(nearest, k, parent.outer[nearest.index])
                                  : NearVertex{};
    }
    const std::size_t hole = static_cast<std::size_t>(nearest.ring - 1);
    if (hole == hint.chain_hole) {
      const std::size_t m = parent.holes[hole].size();
      const std::size_t k = hint.from_parent + (nearest.index + m - hint.chain_first) % m;
      return on_outer(nearest, k, parent.holes[hole][nearest.index]);
    }
    const int ring = ring_in_piece[static_cast<std::size_t>(nearest.ring)];
    if (ring < 0) return {};
    return {nearest.distance, ring, nearest.index, true};
  };
  // On ∂P0 alone: a piece cut along a hole has the hole's chain on its outer ring too, whose
  // vertices (from from_parent on) must all lie farther.
  auto in_piece_outer = [&](const NearVertex& nearest, Vec2 end) -> NearVertex {
    const NearVertex kept = in_piece(nearest);
    if (!kept.known() || hint.chain_hole == kNone) {
      return kept;
    }
    for (std::size_t k = hint.from_parent; k < piece.outer.size(); ++k) {
      if (!(distance(piece.outer[k], end) > kept.distance)) return {};
    }
    return kept;
  };
  hint.hole_ends.resize(piece.holes.size());
  for (std::size_t c = 0; c < piece.holes.size(); ++c) {
    if (hint.hole_source[c] == kNone) {  // a hole the cuts made: measured afresh
      hint.hole_ends[c] = HoleEnds{};
      continue;
    }
    const HoleEnds& from = parent_ends[hint.hole_source[c]];
    const Ring& hole = piece.holes[c];
    hint.hole_ends[c] = {from.p,
                         from.q,
                         in_piece(from.from_p),
                         in_piece(from.from_q),
                         in_piece_outer(from.outer_from_p, hole[from.p]),
                         in_piece_outer(from.outer_from_q, hole[from.q])};
  }
}

bool is_sliver(const Ring& ring, std::size_t first, std::size_t last) {
  const std::size_t n = ring.size();
  const Vec2 origin = ring[first];
  Vec2 low{0.0, 0.0}, high{0.0, 0.0}, previous{0.0, 0.0};
  double twice_area = 0.0;
  std::size_t count = 1;  // vertices from first to last
  for (std::size_t i = next_index(first, n);; i = next_index(i, n)) {
    ++count;
    const Vec2 p = ring[i] - origin;
    twice_area += previous.x * p.y - previous.y * p.x;
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    previous = p;
    if (i == last) break;
  }
  if (count < 3) return true;
  const Vec2 extent = high - low;
  const double length = std::sqrt(extent.x * extent.x + extent.y * extent.y);
  return !(std::abs(0.5 * twice_area) > sliver_width(length) * length);
}

bool is_sliver(const Ring& ring) { return ring.size() < 3 || is_sliver(ring, 0, ring.size() - 1); }

}  // namespace hullcook::detail
