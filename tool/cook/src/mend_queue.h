// The edges that HullFitter::mend_local_violations may remove, kept up to date as it removes them
// one at a time. A hull of thousands of vertices closer than the weld (a many-pointed star's tips)
// asked edges_to_mend and sorted every candidate once per removal: minutes.
#pragma once

#include "hullcook/cook/constrain.h"
#include "hullcook/core/polygon.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hullcook {

// What edges_to_mend lists, as a set updated where a removal changes it: a vertex is bad when it
// turns less than the collinear height (kCollinearFractionOfWeld of the weld) or another vertex
// lies closer than the weld, and an edge is wanted when either end is bad. The candidates are the
// wanted edges whose removal has an apex within the bound, in the order mend_local_violations
// tries them: by the apex's error, then by the edge's index.
//
// Vertices carry IDs that increase along the ring: the apex of a removed edge takes the ID of the
// edge's start, and the removal of the edge that closes the ring leaves the apex last, so the
// order of IDs is the order of indices. An edge is known by its start's ID.
class MendQueue {
 public:
  // error_of(apex): how far the apex lies from what the hull must stay within (only compared with
  // bound: an apex farther is no candidate).
  MendQueue(const EngineLimits& limits, double bound, std::function<double(Vec2)> error_of)
      : limits_(limits), bound_(bound), error_of_(std::move(error_of)) {}

  // Starts from hull. False when its coordinates are too large for a grid of cells twice the weld
  // (at least 1e-150), or not finite: then the caller asks edges_to_mend each time instead.
  bool start(const Ring& hull);

  // How many edges are wanted (edges_to_mend(hull).size()).
  std::size_t wanted_count() const { return wanted_count_; }

  struct Candidate {
    double error;
    std::uint32_t id;  // the edge's start
    bool operator<(const Candidate& other) const {
      return error < other.error || (error == other.error && id < other.id);
    }
  };
  // The candidates in the order to try them (stale once the hull has fewer than 4 vertices,
  // when no edge has an apex).
  const std::set<Candidate>& candidates() const { return candidates_; }

  // The index of the edge that starts at the vertex id, and the apex of its removal.
  std::size_t index_of(std::uint32_t id) const;
  Vec2 apex_of(std::uint32_t id) const { return vertex_[id].apex; }

  // The edge at index edge was removed: next is the hull without it (see without_edge).
  void remove_edge(std::size_t edge, const Ring& next);

 private:
  struct Vertex {
    Vec2 point;
    bool bad_turn = false;
    std::uint32_t close = 0;  // vertices closer than the weld
    bool wanted = false;      // the edge that starts here
    bool candidate = false;   // in candidates_, with error
    double error = 0;
    Vec2 apex{0, 0};
  };

  std::uint64_t cell_key(Vec2 p) const;
  // Calls visit(id) for each vertex in the cells round p (every vertex within the weld of p).
  template <typename Visit>
  void for_each_near(Vec2 p, Visit visit) const;
  void insert_in_grid(std::uint32_t id);
  void erase_from_grid(std::uint32_t id);
  bool bad(std::uint32_t id) const { return vertex_[id].bad_turn || vertex_[id].close > 0; }
  // Measures again the turn at index i of hull, the wanted flag and the candidate of edge i.
  void update_turn(const Ring& hull, std::size_t i);
  void update_edge(const Ring& hull, std::size_t i);

  const EngineLimits& limits_;
  double bound_;
  std::function<double(Vec2)> error_of_;
  std::vector<std::uint32_t> ids_;  // by index
  std::vector<Vertex> vertex_;      // by ID
  double cell_ = 0;                 // 2 weld; 0 when no two vertices can be too close
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid_;
  std::set<Candidate> candidates_;
  std::size_t wanted_count_ = 0;
  // remove_edge's scratch, reused: the vertices it touched and the edges to update.
  std::vector<std::uint32_t> touched_;
  std::vector<std::size_t> edges_;
};

}  // namespace hullcook
