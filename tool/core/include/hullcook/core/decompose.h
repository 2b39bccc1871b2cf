// Lien-Amato approximate convex decomposition (ACD) of polygons with holes: Algorithms 4.1, 4.2,
// 5.1-5.3 and Eq. 5, 8 and 9 of the paper, with the whole decomposition tree kept.
#pragma once

#include "hullcook/core/polygon.h"

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace hullcook {

// Concavity measures (paper §5.1): straight line to the bridge's line, shortest path in the
// pocket to the bridge segment, and the two hybrids.
enum class Measure { sl, sp, h1, h2 };

// "sl", "sp", "h1", "h2" (exactly); nullopt otherwise.
std::optional<Measure> parse_measure(std::string_view name);
const char* measure_name(Measure measure);

struct DecomposeSettings {
  // [input units] concavity tolerance; 0 gives an exact convex decomposition, but for a notch no
  // deeper than the sliver width (a billionth of the region's size, or of a thousandth of its
  // largest coordinate) where every valid cut grazes a vertex or leaves a sliver
  double tau = 0.0;
  Measure measure = Measure::h1;
  double sc = 0.1;  // Eq. 8 weight of the concavity of the cut's far end [1/units]; finite, >= 0
  double sd = 1.0;  // Eq. 8 weight of the cut's length [unitless]; finite, > 0
  // Whether the tree keeps the component of every node it splits, which pieces_at() returns at a
  // τ above tau (levels of detail, piece budgets). Without them the tree holds its leaves and
  // what is being cut, not every depth's copy of the outline: a comb whose cuts peel one tooth at
  // a time kept memory quadratic in its length (16,000 vertices: 0.5 GB; 32,000: 2 GB), and a
  // region of many holes one copy per hole resolved.
  bool keep_coarser_levels = true;
  // Without keep_coarser_levels: the τ values above tau whose pieces the tree keeps all the same,
  // so that pieces_at() can read them (the split nodes that are pieces of none are dropped).
  std::vector<double> kept_levels{};
};

// One piece of a decomposition.
struct Piece {
  Region component;  // [input units] simple outer ring (CCW) with the holes it keeps (CW)
  Ring hull;         // [input units] convex hull of component.outer: CCW, no collinear vertex
  double concavity;  // [input units] under the measure (for holes: Eq. 5)
};

// What made a node concave: its deepest notch on the outer boundary, or the hole resolved next.
struct Witness {
  Vec2 point{0.0, 0.0};  // [input units] the notch, or the hole vertex joined first
  int hole = -1;         // index into component.holes, or -1 for an outer notch
};

// The decomposition tree of one cleaned region. Every node keeps its component, its concavity and
// the witness at which it was split; a node is split when its concavity exceeds the τ the tree
// was built with (and always when it keeps a hole deeper than τ).
class DecompositionTree {
 public:
  struct Node {
    Region component;  // [input units]
    double concavity;  // [input units] decides whether the node splits at a given τ
    Witness witness;   // meaningful when the node has children
    int children[2] = {-1, -1};
    bool is_leaf() const { return children[0] < 0; }
  };

  // The decomposition for any τ' >= built_tau(): leaves of the tree cut where concavity <= τ'.
  // For SL, SP and H1 this equals a fresh decompose() at τ'. For H2 (whose witness depends on τ)
  // every piece still has concavity <= τ'. Pieces come in depth-first order of the tree. A tree
  // built without keep_coarser_levels has the leaves' components and those of the kept_levels'
  // pieces: a τ' at which a dropped node would be a piece throws std::logic_error.
  std::vector<Piece> pieces_at(double tau) const&;
  // The same, moving the pieces' components out of a tree that is not used again (copying them
  // was a tenth of a cook's allocations).
  std::vector<Piece> pieces_at(double tau) &&;

  // The finest level with at most max_pieces pieces (max_pieces 0 is treated as 1).
  std::vector<Piece> pieces_within(std::size_t max_pieces) const;

  // The τ of that level: the smallest of level_taus() with at most max_pieces pieces (0 is
  // treated as 1), or infinity when none has so few. O(nodes × log(levels)).
  double tau_within(std::size_t max_pieces) const;

  // Number of pieces pieces_at(tau) would return, without building them.
  std::size_t piece_count_at(double tau) const;

  // The τ values at which the number of pieces changes, ascending (the levels of detail): the
  // concavities of the split nodes that are >= built_tau().
  std::vector<double> level_taus() const;

  double built_tau() const { return tau_; }
  Measure measure() const { return measure_; }
  // nodes()[0] is the root. Without keep_coarser_levels, a dropped node's component is empty.
  const std::vector<Node>& nodes() const { return nodes_; }

 private:
  friend DecompositionTree decompose(const Region&, const DecomposeSettings&);
  // Calls take(node) for each node that is a piece at tau, in depth-first order.
  template <typename Take>
  void for_each_piece_at(double tau, Take take) const;
  std::vector<Node> nodes_;
  double tau_ = 0.0;
  Measure measure_ = Measure::h1;
};

// Decomposes one cleaned region (see clean_and_validate) until every piece has concavity <= tau,
// or no more than the sliver width for a notch that only sliver cuts resolve (see tau above).
// Deterministic. Throws std::invalid_argument on a negative or NaN tau, or on sc or sd out of
// their ranges (Eq. 8's scores must be numbers to be ordered).
DecompositionTree decompose(const Region& region, const DecomposeSettings& settings);

// Concavity of one cleaned region under a measure (H2 uses tau), as Algorithm 4.1 sees it: the
// maximum over the outer boundary's pockets and the holes (Eq. 5). 0 exactly when convex without
// holes. Exposed for tests and benchmarks.
double measure_concavity(const Region& region, Measure measure, double tau = 0.0);

// Per-vertex concavity of the outer boundary (0 on the convex hull) [input units].
std::vector<double> outer_vertex_concavity(const Ring& outer, Measure measure, double tau = 0.0);

// Eq. 9 of the paper: Σ area(component) / Σ area(hull). 1 for no pieces.
double convexity(const std::vector<Piece>& pieces);

// Every piece's largest concavity (0 for no pieces).
double max_concavity(const std::vector<Piece>& pieces);

}  // namespace hullcook
