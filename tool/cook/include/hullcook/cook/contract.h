// The output contract (issue 16), checked by the cooker itself on every run before anything is
// written: a violation is a bug in the cooker, reported as an internal error (exit 4) instead of
// being shipped with exit 0.
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/cook/constrain.h"
#include "hullcook/core/decompose.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

// What one level of detail promises.
struct ContractTerms {
  double tau = 0.0;               // [output units] the level's tolerance
  Measure measure = Measure::h1;  // the measure the pieces were cut under
  EngineLimits limits{0, 0.0};    // the hulls' engine limits; {0, 0}: convex hulls, nothing more
};

// The ways one level's pieces (components and final hulls, in output units) break the contract
// for an asset whose cleaned outline is `outline`; empty when they keep it. Each names the piece
// (1-based, in order) and the figures, e.g. "piece 3: hull vertex (12.5, 4) lies 4.03 beyond the
// outline (τ 4)". The contract:
//  - partition: every component is a valid region (a simple counter-clockwise outer ring with
//    clockwise holes inside it) and no sliver (thinner than 1e-9 of its length); their areas add
//    up to the outline's (relative 1e-9, the areas summed exactly but for a final rounding: a
//    long thin piece's area is a small difference of large products); the boundaries of each
//    region's pieces (by CookedPiece::region) cancel that region's edge for edge (an edge left
//    over is a gap or an overlap);
//  - every component within τ of its hull: its concavity measured afresh (measure_concavity, not
//    the decomposition's bookkeeping), and geometrically every point of its boundary inside the
//    hull and within τ of the hull's boundary;
//  - every hull: at least 3 vertices, convex and counter-clockwise (exact predicates), within the
//    limits (hull_meets_limits) unless they are {0, 0};
//  - every hull point within τ of the outline (vertices and edges, rigorously).
// Lengths are compared with a slack for rounding only: 1e-9 of the outline's extent, or of a
// thousandth of its largest coordinate when that is more (an outline far from the origin).
// threads: how many may check pieces at once; the result is the same for any count.
std::vector<std::string> find_contract_violations(const std::vector<CookedPiece>& pieces,
                                                  const std::vector<Region>& outline,
                                                  const ContractTerms& terms, unsigned threads = 1);

// Throws InputError "SOURCE: region R is too thin to cut into pieces within the output's contract
// (area A over a length of L)" when a region of outline is itself a sliver as the contract judges
// pieces checked against outline: no decomposition of it could keep the contract, so it is bad
// input, not an internal error (issue 19's fuzzing: a 1.6 wide spike 1e9 long); or "(hole H
// comes within D of the outer boundary at (x, y): a wall up to W thick there is thinner than the
// output's contract resolves)" / "(the outer boundary comes within D of itself at (x, y): a spike
// or neck up to W wide there ...)" when two rings,
// or one ring's two sides, come within twice the sliver width of an edge: at the contract's
// resolution they touch. Regions are numbered from first_region_number. threads: how many may
// check regions at once; the error thrown (the first region's) is the same for any count.
void refuse_sliver_regions(const std::vector<Region>& outline, const std::string& source,
                           std::size_t first_region_number = 1, unsigned threads = 1);

// The slack for rounding that the contract compares lengths with: 1e-9 of the extent of the
// rings' points, or of a thousandth of their largest coordinate when that is more. The rings are
// an outline's outer rings, or all of its pieces' (which span the same box).
double contract_slack(const std::vector<const Ring*>& rings);

// Whether the contract calls region a sliver at that slack: its area no more than its length (the
// diagonal of its outer ring's bounding box) times the larger of 1e-9 of that length and slack.
bool is_contract_sliver(const Region& region, double slack);

// "SOURCE: a piece of A square units near (x, y) is a sliver (thinner than the rounding of its
// coordinates) that no cut avoided": the start of the refusal of a piece the decomposer could
// only cut as a sliver, which each caller ends with what it tried and what the user can change.
std::string sliver_piece_refusal(const Region& piece, std::string_view source);

// Throws InputError (sliver_piece_refusal's, "at tau = T; raise --tau, or move the input nearer
// the origin") for the first of the pieces of outline that the contract calls a sliver: the
// decomposer cuts one only where no other cut resolves a notch deeper than the slivers are wide,
// which at that τ is bad input (the cook merges such a piece into a neighbour where τ allows).
void refuse_sliver_pieces(const std::vector<CookedPiece>& pieces,
                          const std::vector<Region>& outline, double tau, std::string_view source);

// Why hull is no convex counter-clockwise polygon, as the contract judges every hull ("its hull
// is clockwise", "its hull is not convex at its vertex (x, y)", ...); nullopt when it is one. A
// reader of hulls that another run wrote (link's fragments) checks them with it.
std::optional<std::string> hull_shape_defect(const Ring& hull);

// Throws ContractError "SOURCE: internal error: the output breaks its contract: FIRST (and N
// more)" when there are violations.
void enforce_contract(const std::string& source, const std::vector<std::string>& violations);

}  // namespace hullcook
