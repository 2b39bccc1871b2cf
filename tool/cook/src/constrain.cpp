#include "hullcook/cook/constrain.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace hullcook {
namespace {

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  Vec2 ab = b - a;
  double length2 = glm::dot(ab, ab);
  double t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + ab * t));
}

double distance_to_ring(Vec2 p, const Ring& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    best = std::min(best, distance_to_segment(p, ring[i], ring[(i + 1) % n]));
  }
  return best;
}

// Crossing-number test; points on the boundary may go either way, which is harmless here
// because their distance to the boundary is zero.
bool inside_ring(Vec2 p, const Ring& ring) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

// Distance from p to the filled component (zero inside it).
double distance_to_component(Vec2 p, const Region& component) {
  double boundary = distance_to_ring(p, component.outer);
  for (const Ring& hole : component.holes) boundary = std::min(boundary, distance_to_ring(p, hole));
  bool inside = inside_ring(p, component.outer);
  for (const Ring& hole : component.holes) inside = inside && !inside_ring(p, hole);
  return inside ? 0.0 : boundary;
}

double signed_area(const Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) twice += cross(ring[i], ring[(i + 1) % n]);
  return twice / 2;
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

// Candidate edges to remove, for every way in which hull breaks the limits.
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
  bool local = std::find(wanted.begin(), wanted.end(), true) != wanted.end();
  if (!local && limits.max_verts != 0 && n > limits.max_verts) wanted.assign(n, true);
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

double distance_to_hull_boundary(Vec2 p, const Ring& hull) { return distance_to_ring(p, hull); }

class HullFitter {
 public:
  HullFitter(const Region& component, double tau, const EngineLimits& limits)
      : component_(component), tau_(tau), limits_(limits) {}

  // Grows hull edge by edge until it meets the limits; nullopt when no growth keeps the bounds.
  std::optional<Ring> fit(Ring hull) {
    std::vector<double> allowed;
    for_each_component_vertex(
        [&](Vec2 v) { allowed.push_back(std::max(tau_, distance_to_hull_boundary(v, hull))); });
    while (true) {
      if (hull.size() < 3 || std::abs(signed_area(hull)) < 0.5 * limits_.weld * limits_.weld) {
        return std::nullopt;
      }
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
        Ring next = without_edge(hull, candidate.edge, candidate.apex);
        if (growth_within_bounds(hull, candidate.edge, candidate.apex) &&
            component_vertices_within(next, allowed)) {
          hull = std::move(next);
          grown = true;
          break;
        }
      }
      if (!grown) return std::nullopt;
    }
  }

 private:
  template <typename Visit>
  void for_each_component_vertex(Visit visit) const {
    for (Vec2 v : component_.outer) visit(v);
    for (const Ring& hole : component_.holes) {
      for (Vec2 v : hole) visit(v);
    }
  }

  // The added triangle's new sides stay within tau of the component (sampled at tau/4).
  bool growth_within_bounds(const Ring& hull, std::size_t edge, Vec2 apex) const {
    Vec2 a = hull[edge], b = hull[(edge + 1) % hull.size()];
    double step = tau_ > 0 ? tau_ / 4 : 1.0;
    for (auto [from, to] : {std::pair{a, apex}, std::pair{apex, b}}) {
      double length = glm::length(to - from);
      int samples = std::clamp(static_cast<int>(std::ceil(length / step)), 1, 256);
      for (int s = 1; s < samples; ++s) {
        Vec2 p = from + (to - from) * (static_cast<double>(s) / samples);
        if (distance_to_component(p, component_) > tau_) return false;
      }
    }
    return true;
  }

  bool component_vertices_within(const Ring& hull, const std::vector<double>& allowed) const {
    std::size_t k = 0;
    bool ok = true;
    for_each_component_vertex([&](Vec2 v) {
      if (ok && distance_to_hull_boundary(v, hull) > allowed[k] * (1 + 1e-12)) ok = false;
      ++k;
    });
    return ok;
  }

  const Region& component_;
  double tau_;
  EngineLimits limits_;
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
