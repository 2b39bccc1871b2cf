// Internal: the data the decomposer's stages hand each other (Algorithm 4.1's node, its measure
// and what a child inherits from its parent).
#pragma once

#include "hullcook/core/decompose.h"
#include "length_inline.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace hullcook::detail {

inline constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

inline double distance(Vec2 a, Vec2 b) { return length(b - a); }

// A piece thinner than this fraction of its length, or of the decomposed region's size (see
// SliverFloor), is a sliver (see is_sliver in cut.h): the trace of near-collinear vertices.
inline constexpr double kSliverAreaFraction = 1e-9;

// The width below which a piece is a sliver whatever its length, on this thread (see
// SliverFloor); 0 outside a decomposition.
inline thread_local double sliver_floor_width = 0.0;

// Puts in force, for its lifetime, the sliver width of a decomposition of a region: a billionth
// of its extent (or of a thousandth of its largest coordinate, which bounds the rounding of points
// far from the origin). The cook's contract judges pieces by the same width of the outline, so a
// piece the decomposer lets through is not one the contract refuses (issue 16: a cut 1.2e-7 from
// a vertex along a 13.6 long wall of a 170 wide grid).
class SliverFloor {
 public:
  SliverFloor(const Ring& outer, double max_abs) : saved_(sliver_floor_width) {
    double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x;
    double min_y = min_x, max_y = -min_x;
    for (Vec2 p : outer) {
      min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
    const double scale = std::max({max_x - min_x, max_y - min_y, 1e-3 * max_abs});
    sliver_floor_width = std::isfinite(scale) ? kSliverAreaFraction * scale : 0.0;
  }
  ~SliverFloor() { sliver_floor_width = saved_; }
  SliverFloor(const SliverFloor&) = delete;
  SliverFloor& operator=(const SliverFloor&) = delete;

 private:
  double saved_;
};

// The sliver width of a piece or cut of the given length: the larger of its own and the floor's.
inline double sliver_width(double length) {
  return std::max(kSliverAreaFraction * length, sliver_floor_width);
}

// Whether a notch this deep is rounding rather than shape, to be left where only sliver cuts
// resolve it: no deeper than the sliver width less a thousandth, a margin for the contract, which
// allows a piece that width as slack and measures its notch afresh (rounding differently).
inline bool is_rounding_deep(double depth) { return !(depth > 0.999 * sliver_floor_width); }

// Ring index steps without a division (i < n).
inline std::size_t next_index(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }
inline std::size_t prev_index(std::size_t i, std::size_t n) { return i == 0 ? n - 1 : i - 1; }

// The outer boundary's concavity under a measure.
struct OuterConcavity {
  std::vector<double> vertex;  // per vertex: the value Eq. 8 and the witness use
  // Per vertex, the values that decide splitting (H1's); differs from vertex only under H2,
  // whose witness depends on τ. Eq. 5 uses these so hole depths do not depend on τ.
  std::vector<double> depth;
  double value = 0.0;           // decides splitting (for H2: the H1 value, see decompose.h)
  std::size_t witness = kNone;  // the notch with the largest vertex value
  std::vector<char> on_hull;    // per vertex: 2 a hull vertex, 1 exactly on a hull edge, else 0
};

// A candidate for Eq. 5's closest vertex x. Ties in distance go to the first vertex in the order
// outer ring, holes by index, vertex index: the order in which a plain scan would meet them.
struct NearVertex {
  double distance = std::numeric_limits<double>::infinity();  // infinity: none (not known)
  int ring = 0;                                               // 0 outer, h + 1 hole h
  std::size_t index = 0;
  bool unique = false;  // no other vertex searched lies as near
  bool known() const { return distance != std::numeric_limits<double>::infinity(); }
  bool before(const NearVertex& other) const {
    if (distance != other.distance) return distance < other.distance;
    return ring != other.ring ? ring < other.ring : index < other.index;
  }
  // Takes a candidate if it comes before, keeping track of ties.
  void offer(double candidate_distance, int candidate_ring, std::size_t candidate_index) {
    if (candidate_distance < distance) {
      *this = {candidate_distance, candidate_ring, candidate_index, true};
    } else if (candidate_distance == distance) {
      unique = false;
      if (candidate_ring < ring || (candidate_ring == ring && candidate_index < index)) {
        ring = candidate_ring, index = candidate_index;
      }
    }
  }
};

// Eq. 5's antipodal pair of a hole (p, q) and the vertices of the other rings nearest to each;
// and, once a cycle of closest vertices asked for them, the vertices of ∂P0 nearest to each.
struct HoleEnds {
  std::size_t p = kNone, q = kNone;  // kNone: not known
  NearVertex from_p, from_q;
  NearVertex outer_from_p, outer_from_q;
};

// What a child ring inherits from its parent's hull, per vertex. The parent's hull points that
// the child keeps stay on the child's hull, and a parent pocket kept whole by the child cannot
// hold a vertex of the child's hull: the ray leaving such a vertex outward would cross the pocket
// chain (a point of the child) or the bridge (between two points of the child). So only the runs
// at the child's two ends (cut open pockets) need a fresh look.
// The ring that replaces every kept pocket by its bridge, without the parent's collinear hull
// points, is simple (the child plus its kept pockets) and has the child's hull: Melkman's linear
// hull runs on it.
// A pocket kept whole is the same chain with the same bridge, so it keeps its concavities. A
// pocket cut open at the child's ends whose bridge the child keeps (see child_hint) keeps its
// straight-line ones.
enum HintCode : signed char {
  kFresh = 0,
  kParentHullPoint = 1,  // exactly on a parent hull edge
  kInsideKeptPocket = 2,
  kParentHullVertex = 3,
  kInsideCutPocket = 4,   // in the parent pocket cut open at the child's ends, its bridge kept
  kInsideAddedChain = 5,  // a hole's chain added inside that pocket
};
struct ParentHint {
  std::vector<signed char> code;  // per vertex, a HintCode; empty: nothing inherited
  std::vector<double> value;      // per vertex, the parent's value where inherited; or empty
  // The vertices Melkman's scan visits, ascending: the fresh ones, the parent's hull vertices, and
  // the ends of the inherited range [known_first, known_last] (parent hull points, kept even when
  // collinear so that the reduced ring keeps its shape).
  std::vector<std::size_t> hull_candidates;
  std::size_t known_first = 0, known_last = 0;
  std::size_t start = kNone;  // in hull_candidates: the first parent hull vertex, or kNone
  // Where the child's vertices come from: vertex k < from_parent of its outer ring is the parent's
  // vertex (source_first + k) % n, and its hole c is the parent's hole hole_source[c]. A piece cut
  // along a hole continues its outer ring with that hole's chain, from its vertex chain_first on,
  // less the vertices the seams removed.
  std::size_t source_first = 0, from_parent = 0;
  std::vector<std::size_t> hole_source;
  std::size_t chain_hole = kNone, chain_first = 0;
  // Per hole of the child, what it keeps of its parent's HoleEnds (see inherit_hole_ends).
  std::vector<HoleEnds> hole_ends;

  // Back to nothing inherited, keeping the vectors' storage for the next child's hint.
  void reset() {
    code.clear(), value.clear(), hull_candidates.clear(), hole_source.clear(), hole_ends.clear();
    known_first = known_last = 0, start = kNone;
    source_first = from_parent = 0;
    chain_hole = kNone, chain_first = 0;
  }
};

// Eq. 5 for every hole: antipodal pair from the principal axis, depth through the closest vertex.
struct HoleConcavity {
  std::size_t joined = 0;   // hole vertex joined to the boundary first (p)
  std::size_t far_end = 0;  // its antipode cw(p)
  int closest_ring = 0;     // ring holding the closest vertex x: 0 outer, h+1 hole h
  std::size_t closest = 0;  // its index
  double value = 0.0;
};

// Algorithm 4.1's concave(P) of one node: its outer boundary's and its holes' concavities.
struct Evaluation {
  OuterConcavity outer;
  std::vector<HoleConcavity> holes;
  std::vector<HoleEnds> hole_ends;
  double value = 0.0;
  int deepest_hole = -1;
};

// H2's values depend on τ where a pocket is deeper than it: its children measure afresh.
inline bool inherits_values(const DecomposeSettings& settings) {
  return settings.measure != Measure::h2;
}

}  // namespace hullcook::detail
