#include "mend_queue.h"

#include "hull_fitter.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace hullcook {

namespace {

// A cell's index along an axis, within 2^62: an apex may lie farther out than the hull's
// vertices, which start() checked (there it shares an end cell, and distances still decide).
std::int64_t cell_index(double coordinate, double cell) {
  double index = std::floor(coordinate / cell);
  if (!(index >= -0x1p62)) index = -0x1p62;  // NaN too
  if (!(index <= 0x1p62)) index = 0x1p62;
  return static_cast<std::int64_t>(index);
}

// The grid's key of a cell: cells of one key share a list (distances decide).
std::uint64_t key_of(std::int64_t column, std::int64_t row) {
  return static_cast<std::uint64_t>(column) * 0x9E3779B97F4A7C15ull ^
         static_cast<std::uint64_t>(row);
}

}  // namespace

std::uint64_t MendQueue::cell_key(Vec2 p) const {
  return key_of(cell_index(p.x, cell_), cell_index(p.y, cell_));
}

template <typename Visit>
void MendQueue::for_each_near(Vec2 p, Visit visit) const {
  // Cells twice the weld wide: a vertex within the weld of p lies in p's cell or a neighbour.
  const std::int64_t column = cell_index(p.x, cell_), row = cell_index(p.y, cell_);
  std::array<std::uint64_t, 9> keys;
  std::size_t count = 0;
  for (std::int64_t dc = -1; dc <= 1; ++dc) {
    for (std::int64_t dr = -1; dr <= 1; ++dr) {
      const std::uint64_t key = key_of(column + dc, row + dr);
      // Two cells of one key share its list: visit it once.
      if (std::find(keys.begin(), keys.begin() + count, key) != keys.begin() + count) continue;
      keys[count++] = key;
      const auto found = grid_.find(key);
      if (found == grid_.end()) continue;
      for (const std::uint32_t id : found->second) visit(id);
    }
  }
}

void MendQueue::insert_in_grid(std::uint32_t id) {
  grid_[cell_key(vertex_[id].point)].push_back(id);
}

void MendQueue::erase_from_grid(std::uint32_t id) {
  std::vector<std::uint32_t>& cell = grid_[cell_key(vertex_[id].point)];
  const auto at = std::find(cell.begin(), cell.end(), id);
  *at = cell.back();
  cell.pop_back();
}

bool MendQueue::start(const Ring& hull) {
  const std::size_t n = hull.size();
  ids_.resize(n);
  vertex_.assign(n, {});
  grid_.clear();
  candidates_.clear();
  wanted_count_ = 0;
  // At least 1e-150: vertices closer than about 1e-161 square to a length of 0 (below any
  // weld, as edges_to_mend measures them) however many cells of a tinier weld apart.
  cell_ = limits_.weld > 0 ? std::max(2 * limits_.weld_distance(), 1e-150) : 0.0;
  if (cell_ > 0) {
    // Cell indices must fit 64 bits, exactly enough that neighbouring cells differ by one.
    if (!std::isfinite(cell_)) return false;
    for (const Vec2& p : hull) {
      if (!(std::abs(p.x / cell_) < 0x1p52 && std::abs(p.y / cell_) < 0x1p52)) return false;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    ids_[i] = static_cast<std::uint32_t>(i);
    vertex_[i].point = hull[i];
  }
  if (cell_ > 0) {
    for (std::uint32_t id = 0; id < n; ++id) insert_in_grid(id);
    for (std::uint32_t id = 0; id < n; ++id) {
      for_each_near(vertex_[id].point, [&](std::uint32_t other) {
        if (other != id &&
            glm::length(vertex_[id].point - vertex_[other].point) < limits_.weld_distance())
          ++vertex_[id].close;
      });
    }
  }
  for (std::size_t i = 0; i < n; ++i) update_turn(hull, i);
  for (std::size_t i = 0; i < n; ++i) update_edge(hull, i);
  return true;
}

std::size_t MendQueue::index_of(std::uint32_t id) const {
  return static_cast<std::size_t>(std::lower_bound(ids_.begin(), ids_.end(), id) - ids_.begin());
}

void MendQueue::update_turn(const Ring& hull, std::size_t i) {
  // A turn too small to measure (0 or -0 where the exact turn is a left one) breaks the limits
  // whatever the weld, as in edges_to_mend.
  const double height = turn_height(hull, i);
  vertex_[ids_[i]].bad_turn = height < limits_.least_turn() || !(height > 0);
}

void MendQueue::update_edge(const Ring& hull, std::size_t i) {
  const std::size_t n = hull.size();
  Vertex& start = vertex_[ids_[i]];
  const bool wanted = bad(ids_[i]) || bad(ids_[(i + 1) % n]);
  wanted_count_ += static_cast<std::size_t>(wanted) - static_cast<std::size_t>(start.wanted);
  start.wanted = wanted;
  if (start.candidate) candidates_.erase({start.error, ids_[i]});
  start.candidate = false;
  if (!wanted) return;
  const std::optional<Vec2> apex = removed_edge_apex(hull, i);
  if (!apex) return;
  const double error = error_of_(*apex);
  if (!(error <= bound_)) return;
  start.apex = *apex;
  start.error = error;
  start.candidate = true;
  candidates_.insert({error, ids_[i]});
}

void MendQueue::remove_edge(std::size_t edge, const Ring& next) {
  const std::size_t before = ids_.size();
  const std::uint32_t kept = ids_[edge], gone = ids_[(edge + 1) % before];
  // The vertices whose count of close vertices changes.
  std::vector<std::uint32_t>& touched = touched_;
  touched.clear();
  auto part = [&](std::uint32_t id, int change) {
    for_each_near(vertex_[id].point, [&](std::uint32_t other) {
      if (other == id ||
          !(glm::length(vertex_[id].point - vertex_[other].point) < limits_.weld_distance())) {
        return;
      }
      vertex_[other].close = static_cast<std::uint32_t>(vertex_[other].close + change);
      if (change > 0) ++vertex_[id].close;
      touched.push_back(other);
    });
  };
  if (cell_ > 0) {
    erase_from_grid(kept);
    part(kept, -1);
    erase_from_grid(gone);
    part(gone, -1);
  }
  Vertex& removed = vertex_[gone];
  if (removed.candidate) candidates_.erase({removed.error, gone});
  if (removed.wanted) --wanted_count_;
  removed = Vertex{};
  ids_.erase(ids_.begin() + static_cast<std::ptrdiff_t>((edge + 1) % before));
  // The apex takes the place of the edge's start: at the same index, or last for the edge that
  // closed the ring (see without_edge).
  const std::size_t n = next.size(), apex = edge + 1 == before ? n - 1 : edge;
  vertex_[kept].point = next[apex];
  vertex_[kept].close = 0;
  if (cell_ > 0) {
    part(kept, +1);
    insert_in_grid(kept);
  }
  for (std::size_t d = n - 1; d <= n + 1; ++d) update_turn(next, (apex + d) % n);
  // Edges whose ends may have turned bad or good, or whose apex moved: the two round each
  // vertex touched, and those whose four vertices include the apex.
  std::vector<std::size_t>& edges = edges_;
  edges.clear();
  for (std::size_t d = n - 2; d <= n + 1; ++d) edges.push_back((apex + d) % n);
  for (const std::uint32_t id : touched) {
    if (id == gone) continue;
    const std::size_t i = index_of(id);
    edges.push_back((i + n - 1) % n);
    edges.push_back(i);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const std::size_t i : edges) update_edge(next, i);
}

}  // namespace hullcook
