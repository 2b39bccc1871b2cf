#include "hull_lines.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcook {
namespace {

// Below this many lines a query scans them all: the runs would cost more than they skip.
constexpr std::size_t kRunsFrom = 64;

}  // namespace

void HullLines::assign(const Ring& hull) {
  from_.clear(), direction_.clear();
  from_.reserve(hull.size()), direction_.reserve(hull.size());
  bool finite = true;
  double scale = 0;
  for (std::size_t i = 0, n = hull.size(); i < n; ++i) {
    const Vec2 edge = hull[(i + 1) % n] - hull[i];
    from_.push_back(hull[i]);
    direction_.push_back(edge / glm::length(edge));
    finite = finite && std::isfinite(direction_.back().x) && std::isfinite(direction_.back().y) &&
             std::isfinite(hull[i].x) && std::isfinite(hull[i].y);
    scale = std::max({scale, std::abs(hull[i].x), std::abs(hull[i].y)});
  }
  // A distance (two products of a difference of coordinates and a unit direction) is within a few
  // units in the last place of the coordinates of its true value, and so is a run's bound.
  margin_ = 1e-12 * scale;
  use_runs_ = finite && std::isfinite(scale) && size() >= kRunsFrom;
  if (!use_runs_) return;
  auto add = [](Bounds& bounds, Vec2 direction, Vec2 from) {
    bounds.direction_x[0] = std::min(bounds.direction_x[0], direction.x);
    bounds.direction_x[1] = std::max(bounds.direction_x[1], direction.x);
    bounds.direction_y[0] = std::min(bounds.direction_y[0], direction.y);
    bounds.direction_y[1] = std::max(bounds.direction_y[1], direction.y);
    bounds.from_x[0] = std::min(bounds.from_x[0], from.x);
    bounds.from_x[1] = std::max(bounds.from_x[1], from.x);
    bounds.from_y[0] = std::min(bounds.from_y[0], from.y);
    bounds.from_y[1] = std::max(bounds.from_y[1], from.y);
  };
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const Bounds empty{{kInfinity, -kInfinity},
                     {kInfinity, -kInfinity},
                     {kInfinity, -kInfinity},
                     {kInfinity, -kInfinity}};
  runs_.build(size(), empty,
              [&](Bounds& bounds, std::size_t k) { add(bounds, direction_[k], from_[k]); });
}

double HullLines::least_distance(const Bounds& bounds, Vec2 p) {
  // distance = dx (p.y - from.y) - dy (p.x - from.x), bilinear in each pair of ranges: its least
  // value over the box is at a corner.
  const double across[2] = {p.y - bounds.from_y[1], p.y - bounds.from_y[0]};
  const double along[2] = {p.x - bounds.from_x[1], p.x - bounds.from_x[0]};
  double first = std::numeric_limits<double>::infinity();
  double second = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      first = std::min(first, bounds.direction_x[i] * across[j]);
      second = std::max(second, bounds.direction_y[i] * along[j]);
    }
  }
  return first - second;
}

template <typename Bound, typename Visit>
void HullLines::for_each_line_within(Vec2 p, Vec2 q, Bound&& bound, Visit&& visit) const {
  const double margin =
      margin_ + 1e-12 * (std::abs(p.x) + std::abs(p.y) + std::abs(q.x) + std::abs(q.y));
  // Skipped where a run's every line is surely farther than the bound from p or from q (a bound
  // that is not a number skips nothing).
  auto beyond = [&](const Bounds& bounds) {
    const double limit = bound() + margin;
    return least_distance(bounds, p) > limit || least_distance(bounds, q) > limit;
  };
  runs_.for_each(beyond, visit);
}

std::pair<double, std::size_t> HullLines::nearest_by_runs(Vec2 p, std::size_t hint) const {
  std::pair<double, std::size_t> best{std::numeric_limits<double>::infinity(), 0};
  // Measured first, the hint's line bounds the search; the least pair of (distance, index) is the
  // same in any order, and a line skipped is farther than it.
  // (Not a number: no pair compares below it, where the scan never takes one.)
  if (hint < size() && !std::isnan(distance(hint, p))) best = {distance(hint, p), hint};
  for_each_line_within(
      p, p, [&] { return best.first; },
      [&](std::size_t k) {
        best = std::min(best, {distance(k, p), k});
        return true;
      });
  return best;
}

bool HullLines::one_within_by_runs(Vec2 p, Vec2 q, double limit) const {
  bool found = false;
  for_each_line_within(
      p, q, [&] { return limit; },
      [&](std::size_t k) {
        found = distance(k, p) <= limit && distance(k, q) <= limit;
        return !found;
      });
  return found;
}

std::pair<double, Vec2> HullLines::farthest_on(Vec2 p, Vec2 q) const {
  auto at = [&](double t) { return p + (q - p) * t; };
  double low = 0.0, high = 1.0;
  std::size_t hint = 0;
  for (int step = 0; step < 64 && low < high; ++step) {
    const double middle = 0.5 * (low + high);
    hint = nearest(at(middle), hint).second;
    (distance(hint, q) > distance(hint, p) ? low : high) = middle;
  }
  std::pair<double, Vec2> best{-std::numeric_limits<double>::infinity(), p};
  for (double t : {0.0, low, high, 1.0}) {
    const double value = nearest(at(t), hint).first;
    if (value > best.first) best = {value, at(t)};
  }
  return best;
}

}  // namespace hullcook
