#include "outline_distance.h"

#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

namespace hullcook {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The grid has about one cell per edge, but never more than this many cells a side.
constexpr int kMaxCellsPerSide = 2048;
// growth_within refuses a polygon whose proof needs more cells than this.
constexpr int kCellBudget = 1 << 14;

struct Interval {
  double low = kInfinity, high = -kInfinity;
  bool empty() const { return !(low <= high); }
  void join(Interval other) {
    if (other.empty()) return;
    low = std::min(low, other.low);
    high = std::max(high, other.high);
  }
};

// {t : lower <= offset + slope * t <= upper}.
Interval linear_interval(double offset, double slope, double lower, double upper) {
  if (slope == 0) {
    return offset >= lower && offset <= upper ? Interval{-kInfinity, kInfinity} : Interval{};
  }
  double first = (lower - offset) / slope, second = (upper - offset) / slope;
  return {std::min(first, second), std::max(first, second)};
}

Interval intersect(Interval a, Interval b) {
  return {std::max(a.low, b.low), std::min(a.high, b.high)};
}

// {t : |p + t v - centre| <= radius}.
Interval disc_interval(Vec2 p, Vec2 v, Vec2 centre, double radius) {
  Vec2 offset = p - centre;
  double a = glm::dot(v, v), b = glm::dot(v, offset);
  if (a == 0) {
    return glm::dot(offset, offset) <= radius * radius ? Interval{-kInfinity, kInfinity}
                                                       : Interval{};
  }
  // b² - a (|offset|² - radius²), written as a radius² - (v × offset)²: the first form cancels
  // catastrophically where the line passes through a disc far smaller than |v| (a hull edge
  // along two nearly collinear outline edges, through their shared vertex), and came out
  // negative there: segment_within then found a gap in the capsules at that vertex.
  const double off_line = cross(v, offset);
  double discriminant = a * radius * radius - off_line * off_line;
  if (discriminant < 0) return {};
  double root = std::sqrt(discriminant);
  return {(-b - root) / a, (-b + root) / a};
}

// {t : the distance from p + t v to segment ab is at most radius}: the line meets the capsule
// (two discs and the band between them) in one interval, the union of the three.
Interval capsule_interval(Vec2 p, Vec2 v, Vec2 a, Vec2 b, double radius) {
  Interval covered = disc_interval(p, v, a, radius);
  covered.join(disc_interval(p, v, b, radius));
  Vec2 along = b - a;
  double length = glm::length(along);
  if (length > 0) {
    Vec2 offset = p - a;
    Interval band =
        linear_interval(glm::dot(offset, along), glm::dot(v, along), 0, length * length);
    band = intersect(band, linear_interval(cross(along, offset) / length, cross(along, v) / length,
                                           -radius, radius));
    covered.join(band);
  }
  return covered;
}

// The part of segment p + t v, t in [0, 1], left of convex's edges first .. first + count - 1
// (cyclically; all of them: inside convex).
Interval clip_to_convex(Vec2 p, Vec2 v, const Ring& convex, std::size_t first, std::size_t count) {
  if (convex.size() < 3) return {};
  Interval inside{0, 1};
  for (std::size_t k = 0, n = convex.size(); k < count && !inside.empty(); ++k) {
    const std::size_t i = (first + k) % n;
    Vec2 edge = convex[(i + 1) % n] - convex[i];
    // Left of the edge: cross(edge, p + t v - convex[i]) >= 0.
    inside = intersect(inside,
                       linear_interval(cross(edge, p - convex[i]), cross(edge, v), 0, kInfinity));
  }
  return inside;
}

bool inside_convex(const Ring& convex, Vec2 p) {
  if (convex.size() < 3) return false;
  for (std::size_t i = 0, n = convex.size(); i < n; ++i) {
    if (cross(convex[(i + 1) % n] - convex[i], p - convex[i]) < 0) return false;
  }
  return true;
}

// False when an edge of the convex ring has the whole square strictly on its outer side (the
// square is then disjoint from the ring; the converse may be wrong near corners, which only
// costs more cells).
bool square_meets_convex(const Ring& convex, Vec2 centre, double half) {
  for (std::size_t i = 0, n = convex.size(); i < n; ++i) {
    Vec2 edge = convex[(i + 1) % n] - convex[i];
    bool all_outside = true;
    for (Vec2 corner : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}}) {
      if (cross(edge, centre + corner * half - convex[i]) >= 0) all_outside = false;
    }
    if (all_outside) return false;
  }
  return true;
}

bool square_inside_convex(const Ring& convex, Vec2 centre, double half) {
  for (Vec2 corner : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}}) {
    if (!inside_convex(convex, centre + corner * half)) return false;
  }
  return true;
}

// The part of the convex ring on the outer (right) side of the line through a along edge.
Ring clip_outside(const Ring& ring, Vec2 a, Vec2 edge) {
  Ring out;
  auto side = [&](Vec2 p) { return -cross(edge, p - a); };  // > 0: outside
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    Vec2 p = ring[i], q = ring[(i + 1) % n];
    double sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return out;
}

// True when segment ab meets the closed axis-aligned square (Liang-Barsky).
bool segment_meets_square(Vec2 a, Vec2 b, Vec2 centre, double half) {
  Vec2 v = b - a;
  Interval t{0, 1};
  t = intersect(t, linear_interval(a.x - centre.x, v.x, -half, half));
  t = intersect(t, linear_interval(a.y - centre.y, v.y, -half, half));
  return !t.empty();
}

}  // namespace

OutlineDistance::OutlineDistance(const std::vector<const Region*>& components) {
  auto add_ring = [&](const Ring& ring, auto add) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      if (ring[i] != ring[(i + 1) % n]) add(ring[i], ring[(i + 1) % n]);
    }
  };
  auto add_region = [&](const Region& region, auto add) {
    add_ring(region.outer, add);
    for (const Ring& hole : region.holes) add_ring(hole, add);
  };
  std::size_t edge_count = 0;
  for (const Region* component : components) {
    edge_count += component->outer.size();
    for (const Ring& hole : component->holes) edge_count += hole.size();
  }
  if (components.size() == 1) {
    edges_.reserve(edge_count);
    add_region(*components[0], [&](Vec2 a, Vec2 b) { edges_.push_back({a, b}); });
  } else {
    // A cut is an edge of two components in opposite directions: sort the edges by their
    // undirected key and keep, of each, the surplus of one direction over the other.
    struct Directed {
      Vec2 low, high;
      bool forward;
    };
    std::vector<Directed> directed;
    directed.reserve(edge_count);
    for (const Region* component : components) {
      add_region(*component, [&](Vec2 a, Vec2 b) {
        bool forward = std::tie(a.x, a.y) < std::tie(b.x, b.y);
        directed.push_back({forward ? a : b, forward ? b : a, forward});
      });
    }
    auto key = [](const Directed& e) { return std::tie(e.low.x, e.low.y, e.high.x, e.high.y); };
    std::sort(directed.begin(), directed.end(), [&](const Directed& a, const Directed& b) {
      return key(a) != key(b) ? key(a) < key(b) : a.forward < b.forward;
    });
    for (std::size_t i = 0; i < directed.size();) {
      std::size_t j = i;
      int surplus = 0;
      for (; j < directed.size() && key(directed[j]) == key(directed[i]); ++j) {
        surplus += directed[j].forward ? 1 : -1;
      }
      for (int k = 0; k < std::abs(surplus); ++k) {
        const Directed& e = directed[i];
        edges_.push_back(surplus > 0 ? Edge{e.low, e.high} : Edge{e.high, e.low});
      }
      i = j;
    }
  }
  if (edges_.empty()) return;
  convex_ = components.size() == 1 && components[0]->holes.empty() &&
            is_strictly_convex_ccw(components[0]->outer);

  Vec2 low{kInfinity, kInfinity}, high{-kInfinity, -kInfinity};
  for (const Edge& e : edges_) {
    low = glm::min(low, glm::min(e.a, e.b));
    high = glm::max(high, glm::max(e.a, e.b));
  }
  Vec2 size = high - low;
  double extent = std::max(size.x, size.y);
  if (!(extent > 0)) extent = 1;
  double edges = static_cast<double>(edges_.size());
  cell_ = std::max({std::sqrt(size.x * size.y / edges), extent / kMaxCellsPerSide,
                    std::numeric_limits<double>::min()});
  origin_ = low;
  columns_ = std::min(kMaxCellsPerSide, static_cast<int>(size.x / cell_) + 1);
  rows_ = std::min(kMaxCellsPerSide, static_cast<int>(size.y / cell_) + 1);

  // The edges of each cell and row in edge order.
  cell_edges_.build(static_cast<std::size_t>(columns_) * rows_, [&](auto&& add) {
    for (std::uint32_t k = 0; k < edges_.size(); ++k) {
      const Edge& e = edges_[k];
      for_each_cell_near(e.a, e.b, 0.0, [&](int column, int row) {
        add(static_cast<std::size_t>(row) * columns_ + column, k);
      });
    }
  });
  row_edges_.build(static_cast<std::size_t>(rows_), [&](auto&& add) {
    for (std::uint32_t k = 0; k < edges_.size(); ++k) {
      const Edge& e = edges_[k];
      for (int row = row_of(std::min(e.a.y, e.b.y)), last = row_of(std::max(e.a.y, e.b.y));
           row <= last; ++row) {
        add(static_cast<std::size_t>(row), k);
      }
    }
  });
  visited_.assign(edges_.size(), 0);
}

// Clamped first, truncation is the floor (and a negative value clamps to 0 either way).
int OutlineDistance::column_of(double x) const {
  double column = (x - origin_.x) / cell_;
  return static_cast<int>(std::clamp(column, 0.0, static_cast<double>(columns_ - 1)));
}

int OutlineDistance::row_of(double y) const {
  double row = (y - origin_.y) / cell_;
  return static_cast<int>(std::clamp(row, 0.0, static_cast<double>(rows_ - 1)));
}

template <typename Visit>
void OutlineDistance::for_each_cell_near(Vec2 a, Vec2 b, double radius, Visit visit) const {
  double low_y = std::min(a.y, b.y) - radius, high_y = std::max(a.y, b.y) + radius;
  double top = origin_.y + rows_ * cell_, right = origin_.x + columns_ * cell_;
  if (high_y < origin_.y || low_y > top) return;
  if (std::max(a.x, b.x) + radius < origin_.x || std::min(a.x, b.x) - radius > right) return;
  // Cells are taken a little wide: rounding must not lose a cell the segment touches.
  double pad = radius + 1e-9 * cell_;
  for (int row = row_of(low_y), last = row_of(high_y); row <= last; ++row) {
    // The part of the segment whose y is within radius of this row's band.
    double band_low = std::max(origin_.y + row * cell_ - radius, std::min(a.y, b.y));
    double band_high = std::min(origin_.y + (row + 1) * cell_ + radius, std::max(a.y, b.y));
    if (row == 0) band_low = std::min(a.y, b.y);
    if (row == rows_ - 1) band_high = std::max(a.y, b.y);
    double low_x = std::min(a.x, b.x), high_x = std::max(a.x, b.x);
    if (a.y != b.y && band_low <= band_high) {
      double x0 = a.x + (band_low - a.y) * (b.x - a.x) / (b.y - a.y);
      double x1 = a.x + (band_high - a.y) * (b.x - a.x) / (b.y - a.y);
      low_x = std::max(low_x, std::min(x0, x1));
      high_x = std::min(high_x, std::max(x0, x1));
    }
    for (int column = column_of(low_x - pad), end = column_of(high_x + pad); column <= end;
         ++column) {
      visit(column, row);
    }
  }
}

template <typename Visit>
void OutlineDistance::for_each_edge_near(Vec2 a, Vec2 b, double radius, Visit visit) const {
  if (++query_ == 0) {
    std::fill(visited_.begin(), visited_.end(), 0);
    query_ = 1;
  }
  bool stopped = false;
  for_each_cell_near(a, b, radius, [&](int column, int row) {
    if (stopped) return;
    std::size_t cell = static_cast<std::size_t>(row) * columns_ + column;
    for (const std::uint32_t* k = cell_edges_.begin(cell); k != cell_edges_.end(cell); ++k) {
      const std::uint32_t edge = *k;
      if (visited_[edge] == query_) continue;
      visited_[edge] = query_;
      if constexpr (std::is_same_v<decltype(visit(edge)), bool>) {
        if (!visit(edge)) {
          stopped = true;
          return;
        }
      } else {
        visit(edge);
      }
    }
  });
}

bool OutlineDistance::contains(Vec2 p) const {
  if (edges_.empty() || p.y < origin_.y || p.y > origin_.y + rows_ * cell_) return false;
  const int row = row_of(p.y);
  // A row that many edges span (the spokes of a star cross every row they pass: a 10,000-vertex
  // star's rows held thousands, and its cook took 24 s in this scan) is left for p's cell: the
  // parity of the crossings from the cell's centre, whose side is known, to p.
  if (row_edges_.size(static_cast<std::size_t>(row)) > kRowEdgesWorthACellsCentre &&
      p.x >= origin_.x && p.x <= origin_.x + columns_ * cell_) {
    const int column = column_of(p.x);
    const std::size_t cell = static_cast<std::size_t>(row) * columns_ + column;
    const Vec2 centre = origin_ + Vec2{column + 0.5, row + 0.5} * cell_;
    if (centre_inside_.empty()) centre_inside_.assign(cell_edges_.bucket_count(), kUnknown);
    signed char& known = centre_inside_[cell];
    if (known == kUnknown) known = centre_side(cell, centre);
    if (known != kOnTheOutline) {
      bool inside = known == kInside;
      for (const std::uint32_t* k = cell_edges_.begin(cell); k != cell_edges_.end(cell); ++k) {
        if (crosses(centre, p, edges_[*k].a, edges_[*k].b)) inside = !inside;
      }
      return inside;
    }
  }
  bool inside = false;
  for (const std::uint32_t* k = row_edges_.begin(row); k != row_edges_.end(row); ++k) {
    const Edge& e = edges_[*k];
    if ((e.a.y > p.y) != (e.b.y > p.y) &&
        p.x < e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y)) {
      inside = !inside;
    }
  }
  return inside;
}

// Whether the segment from centre to p crosses edge ab, counted so that the crossings' parity
// is the change of side (exact orientations): ab's ends on either side of the line through
// centre and p (an end on it counts as below: a path through a vertex crosses once or not at
// all, as the outline does), and centre and p on either side of ab's line. centre is on no edge.
bool OutlineDistance::crosses(Vec2 centre, Vec2 p, Vec2 a, Vec2 b) {
  if ((orient2d(centre, p, a) > 0) == (orient2d(centre, p, b) > 0)) return false;
  return (orient2d(a, b, centre) > 0) != (orient2d(a, b, p) > 0);
}

// Inside or outside for a cell's centre by exact orientations (a ray to the right, half-open in
// y as the row scan is), or on the outline when an edge of the cell passes through it.
signed char OutlineDistance::centre_side(std::size_t cell, Vec2 centre) const {
  for (const std::uint32_t* k = cell_edges_.begin(cell); k != cell_edges_.end(cell); ++k) {
    if (on_segment(edges_[*k].a, edges_[*k].b, centre)) return kOnTheOutline;
  }
  const int row = row_of(centre.y);
  bool inside = false;
  for (const std::uint32_t* k = row_edges_.begin(row); k != row_edges_.end(row); ++k) {
    const Edge& e = edges_[*k];
    if ((e.a.y > centre.y) == (e.b.y > centre.y)) continue;
    // The crossing is right of the centre when the centre is left of the edge run upward.
    const bool upward = e.b.y > e.a.y;
    if ((upward ? orient2d(e.a, e.b, centre) : orient2d(e.b, e.a, centre)) > 0) inside = !inside;
  }
  return inside ? kInside : kOutside;
}

double OutlineDistance::distance(Vec2 p, double limit, EdgeSpan* nearest) const {
  ++distance_queries_;
  return measure(p, limit, nearest);
}

double OutlineDistance::measure(Vec2 p, double limit, EdgeSpan* nearest) const {
  if (edges_.empty()) return kInfinity;
  if (contains(p)) return 0.0;
  // Cells further than k rings from p's cell (p clamped into the grid, which only brings it
  // closer to every cell) are at least k cells away.
  Vec2 grid_end = origin_ + Vec2{columns_, rows_} * cell_;
  double outside = glm::length(p - glm::clamp(p, origin_, grid_end));
  if (outside > limit) return outside;
  int column = column_of(p.x), row = row_of(p.y);
  int rings = std::max(columns_, rows_);
  // Within the grid, an edge registered in none of the k rings of cells round p's cell lies
  // beyond their square: k cells plus p's distance to its own cell's side away. That distance,
  // less a margin for the rounding of cell indices (p's and the edges': see for_each_cell_near),
  // lets a point near the outline stop at its own cell (else the ring round it was always
  // scanned: where the outline is dense, as on a disc of thousands of vertices, nine cells of
  // dozens of edges for each apex mending measured). Only the proven nearest edge stops it, so
  // the answer is the full scan's.
  double inner = 0;
  if (outside == 0) {
    const Vec2 corner = origin_ + Vec2{column, row} * cell_;
    const double side =
        std::min({p.x - corner.x, corner.x + cell_ - p.x, p.y - corner.y, corner.y + cell_ - p.y});
    const double margin = 1e-6 * cell_ + 1e-14 * (std::abs(origin_.x) + std::abs(origin_.y) +
                                                  std::abs(p.x) + std::abs(p.y));
    if (side > margin) inner = side - margin;
  }
  double best = kInfinity, best_squared = kInfinity;
  const Edge* best_edge = nullptr;
  for (int k = 0; k <= rings; ++k) {
    auto scan = [&](int c, int r) {
      if (c < 0 || r < 0 || c >= columns_ || r >= rows_) return;
      std::size_t cell = static_cast<std::size_t>(r) * columns_ + c;
      for (const std::uint32_t* k = cell_edges_.begin(cell); k != cell_edges_.end(cell); ++k) {
        const Edge& e = edges_[*k];
        const double squared = point_segment_distance_squared(p, e.a, e.b);
        if (squared < best_squared) best_squared = squared, best_edge = &e;
      }
    };
    if (k == 0) {
      scan(column, row);
    } else {
      for (int c = column - k; c <= column + k; ++c) {
        scan(c, row - k);
        scan(c, row + k);
      }
      for (int r = row - k + 1; r <= row + k - 1; ++r) {
        scan(column - k, r);
        scan(column + k, r);
      }
    }
    best = std::sqrt(best_squared);
    double unseen = std::max(outside, k * cell_);
    if (best <= unseen || unseen > limit || best <= k * cell_ + inner) break;
  }
  if (nearest && best_edge && best <= limit) *nearest = *best_edge;
  return best;
}

bool OutlineDistance::segment_within(Vec2 a, Vec2 b, double tau) const {
  if (edges_.empty()) return false;
  Vec2 v = b - a;
  // Every point of ab lies within |ab| of a: a segment shorter than tau less a's distance is
  // within tau without the edges near it, which are all of them when tau spans the outline (a
  // hull of thousands of vertices mended beside a small star took minutes). The margin keeps the
  // capsules' answer wherever rounding could decide it: of the lengths, and of contains(a),
  // which may call a point within rounding of the boundary inside.
  const double length = glm::length(v);
  const double margin = 1e-9 * tau + 1e-15 * (std::abs(a.x) + std::abs(a.y));
  if (length < tau && measure(a, tau - length, nullptr) + length <= tau - margin) return true;
  std::vector<std::pair<double, double>>& covered = covered_;
  covered.clear();
  for_each_edge_near(a, b, tau, [&](std::uint32_t k) {
    Interval interval = intersect(capsule_interval(a, v, edges_[k].a, edges_[k].b, tau), {0, 1});
    if (!interval.empty()) covered.emplace_back(interval.low, interval.high);
  });
  std::sort(covered.begin(), covered.end());
  // What no capsule covers is further than tau from the boundary: each gap lies wholly inside
  // or wholly outside the outline.
  double reach = 0;
  bool first = true;
  auto gap_inside = [&](double from, double to) { return contains(a + v * (0.5 * (from + to))); };
  for (const auto& [low, high] : covered) {
    if (first ? low > 0 : low > reach) {
      if (!gap_inside(first ? 0.0 : reach, low)) return false;
    }
    reach = first ? high : std::max(reach, high);
    first = false;
  }
  if (first) return gap_inside(0, 1);
  return reach >= 1 || gap_inside(reach, 1);
}

bool OutlineDistance::square_inside(Vec2 centre, double half) const {
  if (!contains(centre)) return false;
  // Stops at the first edge that meets the square: at the apex of a fan of thousands of pieces,
  // a square met nearly all of their edges (a random star of 10,000 vertices at --tau 1%).
  bool crossed = false;
  double wide = half * (1 + 1e-9);
  for_each_edge_near(centre - Vec2{half, 0}, centre + Vec2{half, 0}, half, [&](std::uint32_t k) {
    crossed = segment_meets_square(edges_[k].a, edges_[k].b, centre, wide);
    return !crossed;
  });
  return !crossed;
}

bool OutlineDistance::new_part_within(Vec2 a, Vec2 b, const Ring& known, std::size_t first,
                                      std::size_t count, double tau) const {
  const Vec2 v = b - a;
  const Interval old = clip_to_convex(a, v, known, first, count);
  if (old.empty() || old.high - old.low < 1e-9) return segment_within(a, b, tau);
  // The part inside known is not checked again; the new parts are taken a little long, so that
  // rounding never skips a new point.
  if (old.low > 1e-12 && !segment_within(a, a + v * std::min(old.low + 1e-9, 1.0), tau)) {
    return false;
  }
  return !(old.high < 1 - 1e-12) || segment_within(a + v * std::max(old.high - 1e-9, 0.0), b, tau);
}

bool OutlineDistance::new_edges_within(const Ring& grown, const Ring& known, double tau) const {
  for (std::size_t i = 0, n = grown.size(); i < n; ++i) {
    if (!new_part_within(grown[i], grown[(i + 1) % n], known, 0, known.size(), tau)) return false;
  }
  return true;
}

bool OutlineDistance::growth_within(const Ring& grown, const Ring& known, double tau) const {
  return new_edges_within(grown, known, tau) && cells_beyond_within(grown, grown, known, tau);
}

bool OutlineDistance::apex_growth_within(Vec2 at, const std::function<const Ring&()>& grown,
                                         const Ring& known, std::size_t edge, bool with_cells,
                                         double tau) const {
  const std::size_t m = known.size();
  const Vec2 before = known[(edge + m - 1) % m], after = known[(edge + 2) % m];
  // The two new edges lie on the lines of known's edges beside the removed one, and leave known
  // where those edges end: only the edges round those ends bound the part inside (in exact
  // arithmetic; a far edge within rounding of the line could only cut it shorter, where known's
  // proven boundary lies). Clipping by all of known's edges made mending a long hull quadratic.
  const std::size_t first = m > 8 ? (edge + m - 2) % m : 0, count = m > 8 ? 5 : m;
  if (!new_part_within(before, at, known, first, count, tau) ||
      !new_part_within(at, after, known, first, count, tau)) {
    return false;
  }
  return !with_cells || cells_beyond_within(grown(), Ring{at}, known, tau);
}

bool OutlineDistance::cells_beyond_within(const Ring& grown, const Ring& candidates,
                                          const Ring& known, double tau) const {
  // Only beyond known's edges is the area new: grown on the outer side of each edge's line.
  int budget = kCellBudget;
  if (known.size() < 3) return cells_within(grown, known, tau, budget);
  double scale = 0;
  for (Vec2 p : grown)
    scale = std::max({scale, std::abs(p.x - grown[0].x), std::abs(p.y - grown[0].y)});
  for (std::size_t i = 0, m = known.size(); i < m; ++i) {
    Vec2 a = known[i], edge = known[(i + 1) % m] - a;
    double length = glm::length(edge);
    if (length == 0) continue;
    double beyond = 0;
    for (Vec2 p : candidates) beyond = std::max(beyond, -cross(edge, p - a) / length);
    if (beyond <= 1e-12 * scale) continue;
    if (!cells_within(clip_outside(grown, a, edge), known, tau, budget)) {
      // Out of cells, not beyond τ: where grown passes beyond many of known's edges, their clips
      // overlap and each is searched whole (a hull grown round an ellipse 2 x 0.002 of 48
      // vertices, at τ 0.01: 48 strips as long as the ellipse). The growth is then proven once.
      if (budget != 0) return false;
      int whole_budget = kCellBudget;
      return cells_within(grown, known, tau, whole_budget);
    }
  }
  return true;
}

bool OutlineDistance::cells_within(const Ring& region, const Ring& known, double tau,
                                   int& budget) const {
  if (region.size() < 3) return true;
  Vec2 low = region[0], high = region[0];
  for (Vec2 p : region) low = glm::min(low, p), high = glm::max(high, p);
  double extent = std::max(high.x - low.x, high.y - low.y);
  if (!(extent > 0)) return true;
  double smallest = 1e-10 * (tau > 0 ? tau : extent);
  struct Cell {
    Vec2 centre;
    double half;
  };
  std::vector<Cell> cells{{0.5 * (low + high), 0.5 * extent}};
  while (!cells.empty()) {
    Cell cell = cells.back();
    cells.pop_back();
    if (!square_meets_convex(region, cell.centre, cell.half)) continue;
    if (square_inside_convex(known, cell.centre, cell.half)) continue;
    double radius = cell.half * std::sqrt(2.0);
    double d = distance(cell.centre, tau + radius);
    if (d + radius <= tau) continue;
    if (d == 0 && square_inside(cell.centre, cell.half)) continue;
    if (d > tau && inside_convex(region, cell.centre) && !inside_convex(known, cell.centre)) {
      return false;
    }
    if (cell.half <= smallest) {
      if (d <= tau + radius) continue;
      return false;
    }
    if (--budget == 0) return false;
    double quarter = 0.5 * cell.half;
    for (Vec2 corner : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}}) {
      cells.push_back({cell.centre + corner * quarter, quarter});
    }
  }
  return true;
}

}  // namespace hullcook
