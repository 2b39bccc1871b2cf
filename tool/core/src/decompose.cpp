// Algorithm 4.1 of Lien and Amato (2006), Approx_CD(P, τ): the decomposition tree. The stages
// live one per file, named after the paper:
//   outer_concavity.cpp  §5.1   SL, SP (Algorithm 5.1, pocket_paths.cpp), H1 and H2 concavity
//   hole_concavity.cpp   §5.2   Eq. 5: a hole's antipodal pair and depth
//   concavity.cpp        §4     concave(P) of one node: its outer boundary's and its holes'
//   resolve_notch.cpp    §4, §7 Algorithm 4.2 for a notch of ∂P0: the diagonal by Eq. 8
//   resolve_hole.cpp     §5.2.3 Algorithm 4.2 for a hole: the cuts that open it
//   cut.cpp                     cutting a region along those cuts; what each piece inherits
//   slab_cut.cpp                the cut that always opens a hole, when no diagonal does
//   sight.h                     which segments are diagonals of a region
#include "hullcook/core/decompose.h"

#include "concavity.h"
#include "cut.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"
#include "predicates_inline.h"
#include "resolve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hullcook {

std::optional<Measure> parse_measure(std::string_view name) {
  if (name == "sl") return Measure::sl;
  if (name == "sp") return Measure::sp;
  if (name == "h1") return Measure::h1;
  if (name == "h2") return Measure::h2;
  return std::nullopt;
}

const char* measure_name(Measure measure) {
  switch (measure) {
    case Measure::sl:
      return "sl";
    case Measure::sp:
      return "sp";
    case Measure::h1:
      return "h1";
    case Measure::h2:
      return "h2";
  }
  return "?";
}

namespace {

using namespace detail;

Piece make_piece(Region component, double concavity) {
  const detail::CoordinateBound coordinate_bound(detail::max_abs_coordinate(component.outer));
  thread_local std::vector<std::size_t> indices;
  simple_polygon_hull_indices(component.outer, component.outer.size(), indices);
  Ring hull;
  hull.reserve(indices.size());
  for (std::size_t index : indices) hull.push_back(component.outer[index]);
  return Piece{std::move(component), std::move(hull), concavity};
}

}  // namespace

DecompositionTree decompose(const Region& region, const DecomposeSettings& settings) {
  if (!(settings.tau >= 0.0)) throw std::invalid_argument("decompose: tau must be >= 0");
  if (!(settings.sc >= 0.0 && std::isfinite(settings.sc))) {
    throw std::invalid_argument("decompose: sc must be finite and >= 0");
  }
  if (!(settings.sd > 0.0 && std::isfinite(settings.sd))) {
    throw std::invalid_argument("decompose: sd must be finite and > 0");
  }
  // Every point the decomposition orients is a vertex of the region (or one turned a quarter).
  const double max_abs = detail::max_abs_coordinate(region);
  const detail::CoordinateBound coordinate_bound(max_abs);
  const detail::SliverFloor sliver_floor(region.outer, max_abs);
  DecompositionTree tree;
  tree.tau_ = settings.tau;
  tree.measure_ = settings.measure;
  tree.nodes_.push_back({region, 0.0, {}, {-1, -1}});
  std::vector<int> pending{0};
  // Under every measure but H2 a child inherits the values of the pockets it keeps whole, and
  // measures only new chains: only H2 looks pockets up.
  PocketCache cache;
  PocketCache* const pocket_cache = inherits_values(settings) ? nullptr : &cache;
  std::vector<ParentHint> hints(1);  // per node
  // Per node, the least concavity of its ancestors: a node is a piece at τ when that is above τ
  // (the root has no ancestor) and the node's own concavity is not.
  std::vector<double> ancestors_least{std::numeric_limits<double>::infinity()};
  auto is_piece_of_a_kept_level = [&](int id, double concavity) {
    const double least = ancestors_least[std::size_t(id)];
    return std::any_of(settings.kept_levels.begin(), settings.kept_levels.end(),
                       [&](double tau) { return concavity <= tau && (id == 0 || tau < least); });
  };
  Evaluation e;  // of the node at hand; its storage is reused
  std::vector<ParentHint> spare_hints;
  auto take_spare_hint = [&] {
    if (spare_hints.empty()) return ParentHint();
    ParentHint hint = std::move(spare_hints.back());
    spare_hints.pop_back();
    return hint;
  };
  while (!pending.empty()) {
    const int id = pending.back();
    pending.pop_back();
    // Valid until the children are appended below (nodes_ may then reallocate).
    const Region& component = tree.nodes_[std::size_t(id)].component;
    evaluate(component, settings.measure, settings.tau, e, pocket_cache, &hints[std::size_t(id)]);
    // The node's hint is spent: its storage serves the hints of the next children made.
    spare_hints.push_back(std::move(hints[std::size_t(id)]));
    tree.nodes_[std::size_t(id)].concavity = e.value;
    if (!(e.value > settings.tau)) continue;
    std::pair<ParentHint, ParentHint> child_hints{take_spare_hint(), take_spare_hint()};
    std::optional<std::pair<Region, Region>> parts;
    Witness witness;
    if (e.deepest_hole >= 0 && e.holes[std::size_t(e.deepest_hole)].value > settings.tau) {
      // Fig. 12(b): a hole whose closest vertex lies on another hole waits for that hole.
      std::size_t h = std::size_t(e.deepest_hole);
      for (std::size_t guard = 0; guard < e.holes.size() && e.holes[h].closest_ring != 0; ++guard) {
        h = std::size_t(e.holes[h].closest_ring - 1);
      }
      parts = resolve_hole(component, e, h, settings, child_hints);
      witness = {component.holes[h][e.holes[h].joined], static_cast<int>(h)};
    } else if (e.outer.witness != kNone) {
      parts = resolve_notch(component, e.outer, e.outer.witness, settings, child_hints);
      witness = {component.outer[e.outer.witness], -1};
    }
    if (!parts && witness.hole < 0 && detail::is_rounding_deep(e.outer.value)) {
      // Only slivers resolve the notch, and it is no deeper than they are wide (see
      // resolve_notch): the node stays a piece, within the contract's slack of its hull.
      spare_hints.push_back(std::move(child_hints.first));
      spare_hints.push_back(std::move(child_hints.second));
      continue;
    }
    // A notch of a simple polygon always has a diagonal, and a hole always a slab cut: a node kept
    // whole here would break τ silently (issue 16), so it is an internal error instead.
    if (!parts) {
      throw std::logic_error(
          std::string("decompose: no cut resolves the ") + (witness.hole >= 0 ? "hole" : "notch") +
          " at (" + std::to_string(witness.point.x) + ", " + std::to_string(witness.point.y) +
          ") of a piece of " + std::to_string(component.outer.size()) + " vertices");
    }
    if (!component.holes.empty()) {
      inherit_hole_ends(component, e.hole_ends, parts->first, child_hints.first);
      inherit_hole_ends(component, e.hole_ends, parts->second, child_hints.second);
    }
    const int first = static_cast<int>(tree.nodes_.size());
    tree.nodes_.push_back({std::move(parts->first), 0.0, {}, {-1, -1}});
    tree.nodes_.push_back({std::move(parts->second), 0.0, {}, {-1, -1}});
    hints.push_back(std::move(child_hints.first));
    hints.push_back(std::move(child_hints.second));
    auto& node = tree.nodes_[std::size_t(id)];
    const double least = std::min(ancestors_least[std::size_t(id)], node.concavity);
    ancestors_least.insert(ancestors_least.end(), 2, least);
    if (!settings.keep_coarser_levels && !is_piece_of_a_kept_level(id, node.concavity)) {
      node.component = Region();
    }
    node.witness = witness;
    node.children[0] = first;
    node.children[1] = first + 1;
    pending.push_back(first + 1);
    pending.push_back(first);
  }
  return tree;
}

std::size_t DecompositionTree::piece_count_at(double tau) const {
  std::size_t count = 0;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[std::size_t(stack.back())];
    stack.pop_back();
    if (node.is_leaf() || node.concavity <= tau) {
      ++count;
    } else {
      stack.push_back(node.children[1]);
      stack.push_back(node.children[0]);
    }
  }
  return count;
}

template <typename Take>
void DecompositionTree::for_each_piece_at(double tau, Take take) const {
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    const Node& node = nodes_[std::size_t(id)];
    if (node.is_leaf() || node.concavity <= tau) {
      if (!node.is_leaf() && node.component.outer.empty()) {
        throw std::logic_error("pieces_at: a coarser level than the tree was built to keep");
      }
      take(std::size_t(id));
    } else {
      stack.push_back(node.children[1]);
      stack.push_back(node.children[0]);
    }
  }
}

std::vector<Piece> DecompositionTree::pieces_at(double tau) const& {
  std::vector<Piece> pieces;
  for_each_piece_at(tau, [&](std::size_t id) {
    pieces.push_back(make_piece(nodes_[id].component, nodes_[id].concavity));
  });
  return pieces;
}

std::vector<Piece> DecompositionTree::pieces_at(double tau) && {
  std::vector<Piece> pieces;
  for_each_piece_at(tau, [&](std::size_t id) {
    pieces.push_back(make_piece(std::move(nodes_[id].component), nodes_[id].concavity));
  });
  return pieces;
}

std::vector<double> DecompositionTree::level_taus() const {
  std::vector<double> taus{tau_};
  for (const Node& node : nodes_) {
    if (!node.is_leaf() && node.concavity >= tau_) taus.push_back(node.concavity);
  }
  std::sort(taus.begin(), taus.end());
  taus.erase(std::unique(taus.begin(), taus.end()), taus.end());
  return taus;
}

std::vector<Piece> DecompositionTree::pieces_within(std::size_t max_pieces) const {
  return pieces_at(tau_within(max_pieces));
}

double DecompositionTree::tau_within(std::size_t max_pieces) const {
  const std::size_t budget = std::max<std::size_t>(max_pieces, 1);
  const std::vector<double> taus = level_taus();
  // The piece count does not grow with τ: binary search for the finest level within budget.
  const auto level = std::partition_point(taus.begin(), taus.end(),
                                          [&](double tau) { return piece_count_at(tau) > budget; });
  return level == taus.end() ? std::numeric_limits<double>::infinity() : *level;
}

double convexity(const std::vector<Piece>& pieces) {
  double area = 0.0, hull_area = 0.0;
  for (const Piece& piece : pieces) {
    area += region_area(piece.component);
    hull_area += std::abs(signed_area(piece.hull));
  }
  return hull_area > 0.0 ? area / hull_area : 1.0;
}

double max_concavity(const std::vector<Piece>& pieces) {
  double value = 0.0;
  for (const Piece& piece : pieces) value = std::max(value, piece.concavity);
  return value;
}

}  // namespace hullcook
