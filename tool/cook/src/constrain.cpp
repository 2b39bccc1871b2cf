#include "hullcook/cook/constrain.h"

#include "hullcook/core/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace hullcook {
namespace {

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

double distance_to_ring(Vec2 p, const Ring& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    best = std::min(best, point_segment_distance(p, ring[i], ring[(i + 1) % n]));
  }
  return best;
}

// Distance from p to the filled component (zero inside it or on its boundary).
double distance_to_component(Vec2 p, const Region& component) {
  if (locate_point(component, p) != Location::outside) return 0.0;
  double boundary = distance_to_ring(p, component.outer);
  for (const Ring& hole : component.holes) boundary = std::min(boundary, distance_to_ring(p, hole));
  return boundary;
}

// Height of vertex i above the line through its neighbours; negative for a reflex turn.
double turn_height(const Ring& ring, std::size_t i) {
  std::size_t n = ring.size();
  Vec2 previous = ring[(i + n - 1) % n];
  Vec2 next = ring[(i + 1) % n];
  Vec2 base = next - previous;
  double length = glm::length(base);
  if (length == 0) return 0;
  return cross(base, ring[i] - previous) * -1.0 / length;
}

struct Violations {
  std::vector<std::size_t> edges;  // edges whose removal may help, without duplicates
  bool any = false;
};

// Edges whose removal may mend a local violation: two vertices closer than the weld distance, or
// a vertex (nearly) collinear with its neighbours.
Violations find_violations(const Ring& hull, const EngineLimits& limits) {
  Violations found;
  std::size_t n = hull.size();
  std::vector<bool> wanted(n, false);
  auto want = [&](std::size_t edge) { wanted[edge % n] = true; };
  double collinear = kCollinearFractionOfWeld * limits.weld;
  for (std::size_t i = 0; i < n; ++i) {
    if (turn_height(hull, i) < collinear) {
      want(i + n - 1);
      want(i);
    }
    for (std::size_t j = i + 1; j < n; ++j) {
      if (glm::length(hull[i] - hull[j]) < limits.weld) {
        want(i + n - 1);
        want(i);
        want(j + n - 1);
        want(j);
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (wanted[i]) found.edges.push_back(i);
  }
  found.any = !found.edges.empty();
  return found;
}

// Removing edge i (hull[i] -> hull[i+1]) extends its neighbouring edges until they meet, so the
// hull only grows. Returns the meeting point, if the neighbours converge.
std::optional<Vec2> removed_edge_apex(const Ring& hull, std::size_t i) {
  std::size_t n = hull.size();
  if (n < 4) return std::nullopt;
  Vec2 a = hull[i], b = hull[(i + 1) % n];
  Vec2 before = a - hull[(i + n - 1) % n];
  Vec2 after = hull[(i + 2) % n] - b;
  double denominator = cross(before, after);
  if (!(denominator > 0)) return std::nullopt;
  double t = cross(b - a, after) / denominator;
  if (!(t >= 0) || !std::isfinite(t)) return std::nullopt;
  return a + before * t;
}

Ring without_edge(const Ring& hull, std::size_t i, Vec2 apex) {
  std::size_t n = hull.size();
  Ring grown;
  grown.reserve(n - 1);
  for (std::size_t k = 0; k < n; ++k) {
    if (k == i) {
      grown.push_back(apex);
    } else if (k != (i + 1) % n) {
      grown.push_back(hull[k]);
    }
  }
  return grown;
}

class HullFitter {
 public:
  HullFitter(const Region& component, double tau, const EngineLimits& limits)
      : component_(component), tau_(tau), limits_(limits) {}

  // Grows hull until it meets the limits; nullopt when no growth keeps the bounds.
  std::optional<Ring> fit(Ring hull) {
    allowed_.clear();
    for_each_component_vertex(
        [&](Vec2 v) { allowed_.push_back(std::max(tau_, distance_to_ring(v, hull))); });
    // Reducing the vertex count creates new apexes, which may need welding again.
    for (int round = 0; round < 4; ++round) {
      std::optional<Ring> mended = mend_local_violations(std::move(hull));
      if (!mended) return std::nullopt;
      hull = std::move(*mended);
      if (limits_.max_verts == 0 || hull.size() <= limits_.max_verts) return hull;
      std::optional<Ring> reduced = reduce_vertex_count(hull);
      if (!reduced) return std::nullopt;
      hull = std::move(*reduced);
    }
    return std::nullopt;
  }

 private:
  bool too_small(const Ring& hull) const {
    return hull.size() < 3 || std::abs(signed_area(hull)) < 0.5 * limits_.weld * limits_.weld;
  }

  // Removes, one at a time, the cheapest edge that mends a weld or collinearity violation.
  std::optional<Ring> mend_local_violations(Ring hull) const {
    while (true) {
      if (too_small(hull)) return std::nullopt;
      Violations violations = find_violations(hull, limits_);
      if (!violations.any) return hull;
      struct Candidate {
        double error;
        std::size_t edge;
        Vec2 apex;
      };
      std::vector<Candidate> candidates;
      for (std::size_t edge : violations.edges) {
        std::optional<Vec2> apex = removed_edge_apex(hull, edge);
        if (!apex) continue;
        double error = distance_to_component(*apex, component_);
        if (error <= tau_) candidates.push_back({error, edge, *apex});
      }
      std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.error != b.error ? a.error < b.error : a.edge < b.edge;
      });
      bool grown = false;
      for (const Candidate& candidate : candidates) {
        std::size_t n = hull.size();
        Ring next = without_edge(hull, candidate.edge, candidate.apex);
        if (segment_within_tau(hull[candidate.edge], candidate.apex) &&
            segment_within_tau(candidate.apex, hull[(candidate.edge + 1) % n]) &&
            component_vertices_within(next)) {
          hull = std::move(next);
          grown = true;
          break;
        }
      }
      if (!grown) return std::nullopt;
    }
  }

  // Keeps as few of the hull's edge lines as possible (at most max_verts) so that the polygon
  // they bound stays within tau of the component. From every starting edge, each kept line is
  // followed by the farthest line whose meeting point with it is still within tau: greedy
  // farthest reach is optimal along a chain, and trying every start closes the cycle.
  std::optional<Ring> reduce_vertex_count(const Ring& hull) {
    std::size_t m = hull.size();
    apex_cache_.assign(m * m, ApexState::unknown);
    apex_points_.assign(m * m, Vec2{0, 0});
    std::optional<Ring> best;
    for (std::size_t start = 0; start < m; ++start) {
      std::vector<std::size_t> kept{start};
      std::size_t current = start;
      bool closed = false;
      while (kept.size() <= limits_.max_verts) {
        std::size_t farthest = current + 1;
        for (std::size_t j = current + 2; j <= start + m; ++j) {
          if (!apex_within_tau(hull, current % m, j % m)) break;
          farthest = j;
        }
        if (farthest == start + m) {
          closed = true;
          break;
        }
        kept.push_back(farthest);
        current = farthest;
      }
      if (!closed || kept.size() > limits_.max_verts || kept.size() < 3) continue;
      if (best && best->size() <= kept.size()) continue;
      Ring polygon;
      for (std::size_t k = 0; k < kept.size(); ++k) {
        std::size_t i = kept[k] % m, j = kept[(k + 1) % kept.size()] % m;
        polygon.push_back((i + 1) % m == j ? hull[j] : apex_points_[i * m + j]);
      }
      if (component_vertices_within(polygon)) best = std::move(polygon);
    }
    return best;
  }

  enum class ApexState : unsigned char { unknown, within, beyond };

  // Whether the lines of edges i and j (j after i, counter-clockwise, not adjacent) meet at a
  // point such that the region added between them stays within tau of the component.
  bool apex_within_tau(const Ring& hull, std::size_t i, std::size_t j) {
    std::size_t m = hull.size();
    ApexState& state = apex_cache_[i * m + j];
    if (state == ApexState::unknown) {
      state = ApexState::beyond;
      Vec2 a = hull[i], b = hull[(i + 1) % m], c = hull[j], d = hull[(j + 1) % m];
      Vec2 first = b - a, second = d - c;
      double denominator = cross(first, second);
      if (denominator > 0) {
        double t = cross(c - a, second) / denominator;
        Vec2 apex = a + first * t;
        bool ahead = t >= 1 && glm::dot(apex - c, second) <= 0 && std::isfinite(t);
        if (ahead && distance_to_component(apex, component_) <= tau_ &&
            segment_within_tau(b, apex) && segment_within_tau(apex, c)) {
          state = ApexState::within;
          apex_points_[i * m + j] = apex;
        }
      }
    }
    return state == ApexState::within;
  }

  template <typename Visit>
  void for_each_component_vertex(Visit visit) const {
    for (Vec2 v : component_.outer) visit(v);
    for (const Ring& hole : component_.holes) {
      for (Vec2 v : hole) visit(v);
    }
  }

  // Every point of the segment stays within tau of the component (sampled at tau/4; the ends
  // are checked by the caller or are old hull vertices).
  bool segment_within_tau(Vec2 from, Vec2 to) const {
    double step = tau_ > 0 ? tau_ / 4 : 1.0;
    double length = glm::length(to - from);
    int samples = std::clamp(static_cast<int>(std::ceil(length / step)), 1, 64);
    for (int s = 1; s < samples; ++s) {
      Vec2 p = from + (to - from) * (static_cast<double>(s) / samples);
      if (distance_to_component(p, component_) > tau_) return false;
    }
    return true;
  }

  bool component_vertices_within(const Ring& hull) const {
    std::size_t k = 0;
    bool ok = true;
    for_each_component_vertex([&](Vec2 v) {
      if (ok && distance_to_ring(v, hull) > allowed_[k] * (1 + 1e-12)) ok = false;
      ++k;
    });
    return ok;
  }

  const Region& component_;
  double tau_;
  EngineLimits limits_;
  std::vector<double> allowed_;  // per component vertex: max(tau, distance before)
  std::vector<ApexState> apex_cache_;
  std::vector<Vec2> apex_points_;
};

bool is_convex_without_holes(const CookedPiece& piece) {
  if (!piece.component.holes.empty()) return false;
  double component_area = std::abs(signed_area(piece.component.outer));
  double hull_area = std::abs(signed_area(piece.hull));
  return hull_area - component_area <= 1e-12 * std::max(1.0, hull_area);
}

// Splits a convex polygon along the diagonal between vertex 0 and the middle vertex.
std::pair<Ring, Ring> halve_convex(const Ring& polygon) {
  std::size_t middle = polygon.size() / 2;
  Ring first(polygon.begin(), polygon.begin() + static_cast<std::ptrdiff_t>(middle) + 1);
  Ring second(polygon.begin() + static_cast<std::ptrdiff_t>(middle), polygon.end());
  second.push_back(polygon.front());
  return {first, second};
}

class Constrainer {
 public:
  Constrainer(double tau, const EngineLimits& limits, const SplitComponent& split,
              std::vector<std::string>& warnings)
      : tau_(tau), limits_(limits), split_(split), warnings_(warnings) {}

  void add(CookedPiece piece, int depth, std::vector<CookedPiece>& out) {
    HullFitter fitter(piece.component, tau_, limits_);
    if (std::optional<Ring> hull = fitter.fit(piece.hull)) {
      piece.hull = std::move(*hull);
      out.push_back(std::move(piece));
      return;
    }
    // Finer decompositions leave more room for growth; at τ = 0 the pieces are convex.
    static constexpr double kSplitFractions[] = {0.5, 0.125, 0.0};
    for (; depth < 3; ++depth) {
      std::vector<CookedPiece> parts = split_(piece.component, tau_ * kSplitFractions[depth]);
      if (parts.size() > 1) {
        for (CookedPiece& part : parts) add(std::move(part), depth + 1, out);
        return;
      }
    }
    if (is_convex_without_holes(piece) && piece.hull.size() > 3) {
      auto [first, second] = halve_convex(piece.hull);
      for (const Ring& half : {first, second}) {
        CookedPiece part{Region{half, {}}, half, 0.0};
        add(std::move(part), 3, out);
      }
      return;
    }
    std::ostringstream message;
    message << "a piece of area " << std::abs(signed_area(piece.hull)) << " near ("
            << piece.hull.front().x << ", " << piece.hull.front().y
            << ") is too small for the engine (weld " << limits_.weld
            << "); it is left out of the hulls";
    warnings_.push_back(message.str());
  }

 private:
  double tau_;
  EngineLimits limits_;
  const SplitComponent& split_;
  std::vector<std::string>& warnings_;
};

}  // namespace

bool hull_meets_limits(const Ring& hull, const EngineLimits& limits) {
  if (hull.size() < 3 || signed_area(hull) <= 0) return false;
  if (limits.max_verts != 0 && hull.size() > limits.max_verts) return false;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    if (turn_height(hull, i) <= 0) return false;
  }
  return !find_violations(hull, limits).any;
}

std::vector<CookedPiece> apply_engine_limits(std::vector<CookedPiece> pieces, double tau,
                                             const EngineLimits& limits,
                                             const SplitComponent& split,
                                             std::vector<std::string>& warnings) {
  std::vector<CookedPiece> out;
  out.reserve(pieces.size());
  Constrainer constrainer(tau, limits, split, warnings);
  for (CookedPiece& piece : pieces) constrainer.add(std::move(piece), 0, out);
  return out;
}

}  // namespace hullcook
