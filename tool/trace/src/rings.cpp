// Ring nesting and topology-preserving simplification (Douglas-Peucker with an intersection
// check: any simplified edge that crosses or touches another is refined until none does).
#include "rings.h"

#include "hullcook/core/buckets.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/parallel_for.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

namespace hullcook::trace_detail {
namespace {

// Below this many edges, untangling rings costs less than starting a thread.
constexpr std::size_t kEdgesWorthAThread = 1 << 14;
// Nesting splits its bucket grid into bands of rows, but each band's worker walks every edge:
// below this many edges the second walk costs more than the halved writes save (traced
// images of 32,000 to 101,000 vertices nested 0.1 to 0.7 ms slower on two threads than on one,
// blobs_2048's 331,000 vertices 2.8 ms faster).
constexpr std::size_t kNestingEdgesWorthAThread = 1 << 18;
// The rows, rings and cells handed out at a time.
constexpr std::size_t kRowsPerRange = 64;
constexpr std::size_t kRingsPerRange = 256;
constexpr std::size_t kCellsPerRange = 4096;

// Rings handed out at a time to `threads` workers: up to kRingsPerRange, but a quarter of an
// even share when that is fewer, so that a few hundred rings still split (a ring's work varies
// with its length).
std::size_t rings_per_range(std::size_t rings, unsigned threads) {
  return std::clamp<std::size_t>(rings / (4 * std::size_t{std::max(threads, 1u)}), 1,
                                 kRingsPerRange);
}

// Distances below this [px] count as touching. Traced rings are at least ~1/512 px apart (the
// crossing points of different edges), so this only catches real contacts and rounding.
constexpr double kTouch = 1e-9;

double orient(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

// Keeps the index of the largest distance, the first of equals, as comparing the distances
// themselves would: the square root is taken only when the square grows (the square root is
// monotone, so a distance can only be larger when its square is).
class Farthest {
 public:
  void offer(int index, double distance2) {
    if (!(distance2 > best2_) && index_ >= 0) return;
    const double distance = std::sqrt(distance2);
    if (distance > best_) best_ = distance, best2_ = distance2, index_ = index;
  }
  int index() const { return index_; }
  double distance() const { return best_; }
  double distance2() const { return best2_; }

 private:
  int index_ = -1;
  double best_ = -1, best2_ = -1;
};

bool segments_touch(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (std::max(a.x, b.x) + kTouch < std::min(c.x, d.x) ||
      std::max(c.x, d.x) + kTouch < std::min(a.x, b.x) ||
      std::max(a.y, b.y) + kTouch < std::min(c.y, d.y) ||
      std::max(c.y, d.y) + kTouch < std::min(a.y, b.y)) {
    return false;
  }
  double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
  if (((d1 < 0 && d2 > 0) || (d1 > 0 && d2 < 0)) && ((d3 < 0 && d4 > 0) || (d3 > 0 && d4 < 0))) {
    return true;
  }
  return point_segment_distance(a, c, d) < kTouch || point_segment_distance(b, c, d) < kTouch ||
         point_segment_distance(c, a, b) < kTouch || point_segment_distance(d, a, b) < kTouch;
}

// One edge of a simplified ring: from original vertex `from` to original vertex `to` (cyclic).
struct Segment {
  int ring;
  int from;
  int to;
};

// The box of some points: empty until one is added.
struct Box {
  Vec2 low{std::numeric_limits<double>::max()};
  Vec2 high{std::numeric_limits<double>::lowest()};
  void add(Vec2 p) { low = glm::min(low, p), high = glm::max(high, p); }
  bool holds(Vec2 p) const {
    return low.x <= p.x && p.x <= high.x && low.y <= p.y && p.y <= high.y;
  }
};

// The bounding boxes of a ring's blocks of vertices (level 0) and of pairs of the level below,
// up to one box for the ring.
struct BoxTree {
  std::vector<std::vector<Box>> levels;
  void build(const Ring& ring, int block) {
    const int n = static_cast<int>(ring.size());
    levels.assign(1, std::vector<Box>((n + block - 1) / block));
    for (int i = 0; i < n; ++i) levels[0][i / block].add(ring[i]);
    while (levels.back().size() > 1) {
      const std::vector<Box>& below = levels.back();
      std::vector<Box> above((below.size() + 1) / 2);
      for (std::size_t j = 0; j < below.size(); ++j) {
        above[j / 2].add(below[j].low), above[j / 2].add(below[j].high);
      }
      levels.push_back(std::move(above));
    }
  }
};

class Simplifier {
 public:
  // Each ring is first simplified on its own, on up to threads threads (the rings' results do
  // not depend on each other).
  Simplifier(const std::vector<Ring>& rings, double eps, unsigned threads,
             const std::function<bool(Vec2)>& pinned)
      : rings_(rings), eps_(eps), threads_(threads), pinned_(pinned) {
    keep_.resize(rings.size());
    boxes_.resize(rings.size());
    const bool threaded = threads > 1 && rings.size() >= kItemsWorthAThread;
    std::vector<Stack> stacks(threaded ? threads : 1);
    // Rings handed out by ranges: one by one, the threads took turns writing neighbouring
    // rings' vectors.
    if (!threaded) {
      for (std::size_t r = 0; r < rings.size(); ++r) start(static_cast<int>(r), stacks[0]);
    } else {
      parallel_for_ranges(rings.size(), threads, rings_per_range(rings.size(), threads),
                          [&](std::size_t begin, std::size_t end, unsigned worker) {
                            for (std::size_t r = begin; r < end; ++r) {
                              start(static_cast<int>(r), stacks[worker]);
                            }
                          });
    }
  }

  // Refines until no two simplified edges cross or touch. Returns false if it gave up on some
  // rings and restored them whole (then the caller loops again).
  void untangle() {
    for (int round = 0;; ++round) {
      std::vector<Segment> segments = all_segments();
      std::vector<std::pair<int, int>> touching = touching_pairs(segments);
      if (touching.empty()) return;
      std::vector<char> refine(segments.size(), 0);
      for (auto [s, t] : touching) {
        bool s_splits = interior_count(segments[s]) > 0, t_splits = interior_count(segments[t]) > 0;
        if (round >= kMaxRounds || (!s_splits && !t_splits)) {
          restore(segments[s].ring);
          restore(segments[t].ring);
          continue;
        }
        if (s_splits) refine[s] = 1;
        if (t_splits) refine[t] = 1;
      }
      for (std::size_t s = 0; s < segments.size(); ++s) {
        if (refine[s]) split(segments[s]);
      }
    }
  }

  std::vector<Ring> current() const {
    std::vector<Ring> result(rings_.size());
    for (std::size_t r = 0; r < rings_.size(); ++r) {
      result[r].reserve(static_cast<std::size_t>(
          std::count_if(keep_[r].begin(), keep_[r].end(), [](auto keep) { return keep != 0; })));
      for (std::size_t i = 0; i < rings_[r].size(); ++i) {
        if (keep_[r][i]) result[r].push_back(rings_[r][i]);
      }
    }
    return result;
  }

  // Keeps every vertex of the ring; whether any was dropped.
  bool restore(int ring) {
    const bool changed = std::find(keep_[ring].begin(), keep_[ring].end(), 0) != keep_[ring].end();
    std::fill(keep_[ring].begin(), keep_[ring].end(), 1);
    return changed;
  }

 private:
  static constexpr int kMaxRounds = 64;
  // Ranges of at least this many vertices are searched by blocks of kBlock (farthest_in_blocks).
  static constexpr int kBlockedRange = 4096;
  static constexpr int kBlock = 128;
  int size(int ring) const { return static_cast<int>(rings_[ring].size()); }
  int interior_count(const Segment& s) const {
    return (s.to - s.from - 1 + size(s.ring)) % size(s.ring);
  }

  using Stack = std::vector<std::pair<int, int>>;

  void start(int r, Stack& stack) {
    const Ring& ring = rings_[r];
    const int n = size(r);
    if (eps_ > 0 && n >= kBlockedRange) boxes_[r].build(ring, kBlock);
    keep_[r].assign(n, eps_ > 0 ? 0 : 1);
    if (eps_ <= 0 || n <= 3) {
      std::fill(keep_[r].begin(), keep_[r].end(), 1);
      return;
    }
    int a = 0;
    for (int i = 1; i < n; ++i) {
      if (ring[i].x < ring[a].x || (ring[i].x == ring[a].x && ring[i].y < ring[a].y)) a = i;
    }
    Farthest from_a;
    for (int i = 0; i < n; ++i) {
      const Vec2 v = ring[i] - ring[a];
      from_a.offer(i, glm::dot(v, v));
    }
    const int b = from_a.index();
    keep_[r][a] = keep_[r][b] = 1;
    if (!pinned_) {
      douglas_peucker(r, a, b, stack);
      douglas_peucker(r, b, a, stack);
    } else {
      // Pinned vertices are kept; the chains between kept vertices are simplified.
      for (int i = 0; i < n; ++i) {
        if (pinned_(ring[i])) keep_[r][i] = 1;
      }
      for (int i = a, steps = 0; steps < n;) {
        int j = (i + 1) % n;
        ++steps;
        while (!keep_[r][j]) j = (j + 1) % n, ++steps;
        douglas_peucker(r, i, j, stack);
        i = j;
      }
    }
    if (std::count(keep_[r].begin(), keep_[r].end(), 1) < 3) {
      // Never collapse a ring: keep its vertex farthest from the chord.
      int m = farthest_interior({r, a, b});
      int m2 = farthest_interior({r, b, a});
      auto distance = [&](int i) { return point_segment_distance(ring[i], ring[a], ring[b]); };
      keep_[r][(m2 >= 0 && (m < 0 || distance(m2) > distance(m))) ? m2 : m] = 1;
    }
  }

  // The interior vertex of s farthest from its chord (the first of equals), or -1 if s is an
  // original edge.
  int farthest_interior(const Segment& s) const {
    const Ring& ring = rings_[s.ring];
    const int n = size(s.ring);
    const Vec2 a = ring[s.from], b = ring[s.to];
    Farthest farthest;
    const int first = s.from + 1 == n ? 0 : s.from + 1;
    if (interior_count(s) >= kBlockedRange && !boxes_[s.ring].levels.empty()) {
      return farthest_in_blocks(s.ring, first, interior_count(s), a, b);
    }
    for (int i = first; i != s.to; i = i + 1 == n ? 0 : i + 1) {
      farthest.offer(i, point_segment_distance_squared(ring[i], a, b));
    }
    return farthest.index();
  }

  // farthest_interior over count vertices from first on (cyclic), searching a tree of the
  // bounding boxes of blocks of kBlock vertices best bound first and skipping the boxes that
  // cannot hold the farthest: a point's distance from a segment is a convex function, so over a
  // box it is largest at a corner. Scanning a whole range peeled one tooth a level off a comb:
  // quadratic; scanning the blocks' boxes in a row still cost a comb of 4,096 teeth 1 s. The same
  // index as the plain scan: a box is skipped only when its bound lies below the farthest found,
  // and of equal distances the first in the range's order is kept.
  int farthest_in_blocks(int r, int first, int count, Vec2 a, Vec2 b) const {
    const Ring& ring = rings_[r];
    const BoxTree& tree = boxes_[r];
    const int n = size(r);
    // Above every distance of the box's points as computed (their rounding is absolute, at most
    // a few units in the last place of the coordinates).
    auto bound = [&](const Box& box) {
      double largest = 0;
      for (Vec2 corner :
           {box.low, box.high, Vec2{box.low.x, box.high.y}, Vec2{box.high.x, box.low.y}}) {
        largest = std::max(largest, point_segment_distance_squared(corner, a, b));
      }
      const double scale = std::max({std::abs(box.low.x), std::abs(box.low.y), std::abs(box.high.x),
                                     std::abs(box.high.y), std::abs(a.x), std::abs(a.y),
                                     std::abs(b.x), std::abs(b.y)});
      return std::sqrt(largest) * (1 + 1e-12) + 1e-12 * scale + 1e-300;
    };
    // Candidates: a tree node (level, index) or, at level -1, the vertices [begin, end) of a
    // block cut by the range's ends.
    struct Candidate {
      double bound;
      int level, begin, end;
      bool operator<(const Candidate& other) const { return bound < other.bound; }
    };
    thread_local std::vector<Candidate> heap;  // scratch per thread
    heap.clear();
    auto push = [&](double upper, int level, int begin, int end) {
      heap.push_back({upper, level, begin, end});
      std::push_heap(heap.begin(), heap.end());
    };
    auto push_node = [&](int level, int index) {
      push(bound(tree.levels[level][index]), level, index, index + 1);
    };
    // The range as linear pieces [begin, end), each as the part of a block it starts in, the
    // tree's nodes over the whole blocks after, and the part of a block it ends in. A piece that
    // holds no whole block may still cross a block's end (review 52: one that ran to the ring's
    // end from inside the block before its short last block was bounded by the first block's box
    // alone).
    const int pieces[2][2] = {{first, std::min(n, first + count)},
                              {0, std::max(0, first + count - n)}};
    for (const auto& piece : pieces) {
      int at = piece[0];
      const int end = piece[1];
      if (at >= end) continue;
      if (at % kBlock != 0) {
        const int head_end = std::min(end, (at / kBlock + 1) * kBlock);
        push(bound(tree.levels[0][at / kBlock]), -1, at, head_end);
        at = head_end;
      }
      // The ring's last block, short, is whole when the piece runs to the ring's end.
      const int whole_end = end == n ? (n + kBlock - 1) / kBlock : end / kBlock;
      if (at < end && at / kBlock < whole_end) {
        // The canonical nodes of the blocks [at / kBlock, whole_end), bottom up.
        for (int level = 0, low = at / kBlock, high = whole_end; low < high;
             ++level, low >>= 1, high >>= 1) {
          if (low & 1) push_node(level, low++);
          if (high & 1) push_node(level, --high);
        }
        at = std::min(end, whole_end * kBlock);
      }
      if (at < end) push(bound(tree.levels[0][at / kBlock]), -1, at, end);
    }
    // The farthest so far: its distance, and its place in the range's order.
    int best_index = -1, best_place = 0;
    double best = -1;
    while (!heap.empty() && !(heap.front().bound < best)) {
      std::pop_heap(heap.begin(), heap.end());
      const Candidate candidate = heap.back();
      heap.pop_back();
      int scan_begin = candidate.begin, scan_end = candidate.end;
      if (candidate.level > 0) {
        const int child = 2 * candidate.begin;
        push_node(candidate.level - 1, child);
        if (child + 1 < static_cast<int>(tree.levels[candidate.level - 1].size())) {
          push_node(candidate.level - 1, child + 1);
        }
        continue;
      }
      if (candidate.level == 0) {
        scan_begin = candidate.begin * kBlock, scan_end = std::min(n, scan_begin + kBlock);
      }
      for (int i = scan_begin; i < scan_end; ++i) {
        const double distance = std::sqrt(point_segment_distance_squared(ring[i], a, b));
        if (distance < best) continue;
        const int place = i >= first ? i - first : i + n - first;
        if (distance > best || place < best_place)
          best = distance, best_index = i, best_place = place;
      }
    }
    return best_index;
  }

  // stack: scratch, reused.
  void douglas_peucker(int r, int from, int to, Stack& stack) {
    stack.assign(1, {from, to});
    while (!stack.empty()) {
      auto [i, j] = stack.back();
      stack.pop_back();
      int m = farthest_interior({r, i, j});
      if (m < 0) continue;
      if (point_segment_distance(rings_[r][m], rings_[r][i], rings_[r][j]) <= eps_) continue;
      keep_[r][m] = 1;
      stack.emplace_back(i, m);
      stack.emplace_back(m, j);
    }
  }

  // Splits s at its farthest interior vertex; the halves are re-simplified, because the
  // vertices were within eps of the old chord, not necessarily of the new ones.
  void split(const Segment& s) {
    int m = farthest_interior(s);
    if (m < 0 || keep_[s.ring][m]) return;
    keep_[s.ring][m] = 1;
    douglas_peucker(s.ring, s.from, m, peucker_stack_);
    douglas_peucker(s.ring, m, s.to, peucker_stack_);
  }

  std::vector<Segment> all_segments() const {
    std::vector<Segment> segments;
    std::size_t count = 0;
    for (const auto& keep : keep_) {
      count += static_cast<std::size_t>(
          std::count_if(keep.begin(), keep.end(), [](auto k) { return k != 0; }));
    }
    segments.reserve(count);
    std::vector<int> kept;
    for (std::size_t r = 0; r < rings_.size(); ++r) {
      kept.clear();
      for (int i = 0; i < size(static_cast<int>(r)); ++i) {
        if (keep_[r][i]) kept.push_back(i);
      }
      for (std::size_t k = 0; k < kept.size(); ++k) {
        segments.push_back({static_cast<int>(r), kept[k], kept[(k + 1) % kept.size()]});
      }
    }
    return segments;
  }

  bool adjacent(const Segment& s, const Segment& t) const {
    return s.ring == t.ring && (s.to == t.from || t.to == s.from);
  }

  bool touch(const Segment& s, const Segment& t) const {
    Vec2 a = rings_[s.ring][s.from], b = rings_[s.ring][s.to];
    Vec2 c = rings_[t.ring][t.from], d = rings_[t.ring][t.to];
    if (!adjacent(s, t)) return segments_touch(a, b, c, d);
    // Consecutive edges share a vertex; they are bad only if one folds back onto the other.
    if (s.to == t.from && t.to == s.from) return true;  // a two-vertex ring
    if (s.to == t.from) {
      return point_segment_distance(d, a, b) < kTouch || point_segment_distance(a, c, d) < kTouch;
    }
    return point_segment_distance(b, c, d) < kTouch || point_segment_distance(c, a, b) < kTouch;
  }

  // Pairs of segments that cross or touch, found through a uniform grid (each segment is
  // entered in the cells its path crosses, with a small margin, so two segments that meet share
  // a cell whatever the cell size). About one cell per segment, stored as one array of cell
  // lists: the grid's size follows the segments, not the image.
  std::vector<std::pair<int, int>> touching_pairs(const std::vector<Segment>& segments) const {
    std::vector<std::pair<int, int>> result;
    if (segments.empty()) return result;
    Vec2 low{std::numeric_limits<double>::max()}, high{std::numeric_limits<double>::lowest()};
    for (const Ring& ring : rings_) {
      for (Vec2 p : ring) low = glm::min(low, p), high = glm::max(high, p);
    }
    const Vec2 extent = high - low;
    const double cell =
        std::max({4.0, std::sqrt(extent.x * extent.y / static_cast<double>(segments.size())),
                  extent.x / 1024.0, extent.y / 1024.0});
    const int columns = static_cast<int>(extent.x / cell) + 2,
              rows = static_cast<int>(extent.y / cell) + 2;
    auto clamp_column = [&](double x) {
      return std::clamp(static_cast<int>((x - low.x) / cell), 0, columns - 1);
    };
    auto clamp_row = [&](double y) {
      return std::clamp(static_cast<int>((y - low.y) / cell), 0, rows - 1);
    };
    const double margin = 1e-6;
    // Visits the cells that the segment's path crosses.
    auto for_each_cell = [&](const Segment& segment, auto&& visit) {
      Vec2 a = rings_[segment.ring][segment.from];
      Vec2 b = rings_[segment.ring][segment.to];
      if (a.x > b.x) std::swap(a, b);
      for (int column = clamp_column(a.x - margin); column <= clamp_column(b.x + margin);
           ++column) {
        double x0 = std::max(a.x, low.x + column * cell),
               x1 = std::min(b.x, low.x + (column + 1) * cell);
        double y0 = a.y, y1 = b.y;
        if (b.x - a.x > 0) {
          y0 = a.y + (b.y - a.y) * (std::clamp(x0, a.x, b.x) - a.x) / (b.x - a.x);
          y1 = a.y + (b.y - a.y) * (std::clamp(x1, a.x, b.x) - a.x) / (b.x - a.x);
        }
        if (y0 > y1) std::swap(y0, y1);
        for (int row = clamp_row(y0 - margin), last = clamp_row(y1 + margin); row <= last; ++row) {
          visit(static_cast<std::size_t>(row) * columns + column);
        }
      }
    };
    // The grid is built by a part of the segments on each worker (in order), which keeps a
    // cell's order the one-thread order.
    const int bands = band_count(rows, threads_, segments.size() >= kEdgesWorthAThread);
    Buckets<int, int>& grid = grid_;
    grid.build_in_parts(
        static_cast<std::size_t>(columns) * rows, segments.size(), static_cast<unsigned>(bands),
        [&](unsigned, std::size_t begin, std::size_t end, auto&& add) {
          for (std::size_t s = begin; s < end; ++s) {
            for_each_cell(segments[s], [&](std::size_t c) { add(c, static_cast<int>(s)); });
          }
        });
    // The pairs of each range of cells, joined in the cells' order.
    const std::size_t cells = grid.bucket_count();
    return parallel_join<std::pair<int, int>>(
        (cells + kCellsPerRange - 1) / kCellsPerRange, static_cast<unsigned>(bands),
        [&](std::size_t range, unsigned, std::vector<std::pair<int, int>>& out) {
          for (std::size_t c = range * kCellsPerRange,
                           end = std::min(cells, (range + 1) * kCellsPerRange);
               c < end; ++c) {
            for (const int* i = grid.begin(c); i != grid.end(c); ++i) {
              for (const int* j = i + 1; j != grid.end(c); ++j) {
                if (touch(segments[*i], segments[*j])) out.emplace_back(*i, *j);
              }
            }
          }
        },
        2);
  }

  const std::vector<Ring>& rings_;
  double eps_;
  unsigned threads_;
  const std::function<bool(Vec2)>& pinned_;  // vertices kept whatever eps (empty: none)
  std::vector<std::vector<char>> keep_;
  // Per ring of at least kBlockedRange vertices: the tree of its blocks' boxes.
  std::vector<BoxTree> boxes_;
  std::vector<std::pair<int, int>> peucker_stack_;  // douglas_peucker's, reused
  // The grid of touching_pairs(), kept between rounds so that it is allocated once.
  mutable Buckets<int, int> grid_;
};

// Drops vertices on the straight line through their neighbours (within rounding), which does not
// move the outline; a ring keeps at least 3 vertices.
Ring without_collinear(Ring ring) {
  // Most rings have no straight vertex left: those are returned as they are, without a copy.
  auto straight_at = [&](Vec2 previous, std::size_t i) {
    const std::size_t n = ring.size();
    Vec2 in = ring[i] - previous, out = ring[(i + 1) % n] - ring[i];
    return std::abs(cross(in, out)) <= 1e-12 * glm::length(in) * glm::length(out) &&
           glm::dot(in, out) > 0;
  };
  bool any_straight = false;
  for (std::size_t i = 0, n = ring.size(); i < n && n > 3 && !any_straight; ++i) {
    any_straight = straight_at(ring[(i + n - 1) % n], i);
  }
  bool changed = any_straight;
  while (changed && ring.size() > 3) {
    changed = false;
    Ring kept;
    kept.reserve(ring.size());
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      Vec2 previous = kept.empty() ? ring[(i + n - 1) % n] : kept.back();
      if (straight_at(previous, i) && n - (i - kept.size()) > 3) {
        changed = true;
        continue;
      }
      kept.push_back(ring[i]);
    }
    ring = std::move(kept);
  }
  return ring;
}

}  // namespace

double signed_area(const Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) twice += cross(ring[i], ring[(i + 1) % n]);
  return twice / 2;
}

std::vector<int> nesting_parents(const std::vector<Ring>& rings, unsigned threads,
                                 std::vector<char>* misplaced, std::vector<int>* met_first) {
  const int count = static_cast<int>(rings.size());
  std::vector<int> parents(count, -1);
  if (misplaced) misplaced->assign(count, 0);
  if (met_first) met_first->assign(count, -1);
  if (count == 0) return parents;
  double low_y = std::numeric_limits<double>::max(), high_y = std::numeric_limits<double>::lowest();
  std::vector<int> leftmost(count, 0);
  std::size_t edge_count = 0;
  for (int r = 0; r < count; ++r) {
    const Ring& ring = rings[r];
    edge_count += ring.size();
    for (std::size_t i = 0; i < ring.size(); ++i) {
      low_y = std::min(low_y, ring[i].y), high_y = std::max(high_y, ring[i].y);
      const Vec2& best = ring[leftmost[r]];
      if (ring[i].x < best.x || (ring[i].x == best.x && ring[i].y < best.y))
        leftmost[r] = static_cast<int>(i);
    }
  }
  // Edges bucketed by the unit rows their y range overlaps, sorted by their smallest x; the
  // buckets are ranges of one array.
  struct BucketEdge {
    double min_x;
    int ring;
    int index;
  };
  const int rows = static_cast<int>(std::floor(high_y - low_y)) + 1;
  // y - low_y is never negative: truncation is the floor.
  auto row_range = [&](Vec2 a, Vec2 b) {
    return std::pair{static_cast<int>(std::min(a.y, b.y) - low_y),
                     static_cast<int>(std::max(a.y, b.y) - low_y)};
  };
  // The buckets are built by a part of the edges on each worker (in ring order), which keeps
  // a bucket's order the one-thread order.
  const int bands = band_count(rows, threads, edge_count >= kNestingEdgesWorthAThread);
  std::vector<std::size_t> ring_first(count + 1, 0);  // the first edge of each ring
  for (int r = 0; r < count; ++r) ring_first[r + 1] = ring_first[r] + rings[r].size();
  // The largest x extent of an edge in each bucket, per part.
  std::vector<double> part_widest(static_cast<std::size_t>(bands) * rows, 0.0);
  Buckets<BucketEdge, int> edges;
  edges.build_in_parts(
      static_cast<std::size_t>(rows), edge_count, static_cast<unsigned>(bands),
      [&](unsigned part, std::size_t begin, std::size_t end, auto&& add) {
        double* const widest = part_widest.data() + std::size_t{part} * rows;
        int r = static_cast<int>(std::upper_bound(ring_first.begin(), ring_first.end(), begin) -
                                 ring_first.begin()) -
                1;
        std::size_t i = begin - ring_first[r];
        for (std::size_t edge = begin; edge < end; ++edge, ++i) {
          while (i == rings[r].size()) ++r, i = 0;
          const std::size_t n = rings[r].size();
          const Vec2 a = rings[r][i], b = rings[r][i + 1 == n ? 0 : i + 1];
          const auto [first, last] = row_range(a, b);
          for (int row = first; row <= last; ++row) {
            add(static_cast<std::size_t>(row),
                BucketEdge{std::min(a.x, b.x), r, static_cast<int>(i)});
            // Taken on both passes alike: a maximum.
            widest[row] = std::max(widest[row], std::abs(b.x - a.x));
          }
        }
      });
  std::vector<double> widest(part_widest.begin(), part_widest.begin() + rows);
  for (int part = 1; part < bands; ++part) {
    for (int row = 0; row < rows; ++row) {
      widest[row] = std::max(widest[row], part_widest[std::size_t(part) * rows + row]);
    }
  }
  // A row's edges are sorted (for the walk below) only when the row has many queries: with a
  // few, one scan of its edges is cheaper.
  constexpr int kScanQueries = 8;
  auto row_of = [&](int r) { return static_cast<int>(rings[r][leftmost[r]].y - low_y); };
  std::vector<int> queries(rows, 0);
  for (int r = 0; r < count; ++r) ++queries[row_of(r)];
  parallel_for_ranges(
      static_cast<std::size_t>(rows), bands, kRowsPerRange,
      [&](std::size_t first, std::size_t end, unsigned) {
        for (std::size_t row = first; row < end; ++row) {
          if (queries[row] <= kScanQueries) continue;
          // Edges of equal min_x may come in any order: rings do not touch, so
          // no two rings cross a row at the same x, and the walk below stops
          // only past every edge that could still be hit.
          std::sort(edges.begin(row), edges.end(row),
                    [](const BucketEdge& e, const BucketEdge& f) { return e.min_x < f.min_x; });
        }
      });
  std::vector<char> outer(count);
  for (int r = 0; r < count; ++r) outer[r] = signed_area(rings[r]) > 0;
  // The first ring a leftward ray from a ring's leftmost vertex meets bounds the face the ring
  // lies in: it is the parent if its orientation differs (it encloses that face), else a sibling.
  std::vector<int> hits(count, -1), hit_edges(count, -1);
  parallel_for_ranges(
      static_cast<std::size_t>(count), bands,
      rings_per_range(static_cast<std::size_t>(count), static_cast<unsigned>(bands)),
      [&](std::size_t first, std::size_t end, unsigned) {
        for (std::size_t ring = first; ring < end; ++ring) {
          const int r = static_cast<int>(ring);
          Vec2 p = rings[r][leftmost[r]];
          int hit = -1, hit_edge = -1;
          double hit_x = std::numeric_limits<double>::lowest();
          const int row = row_of(r);
          const BucketEdge* const bucket_begin = std::as_const(edges).begin(row);
          const BucketEdge* const bucket_end = std::as_const(edges).end(row);
          auto consider = [&](const BucketEdge& e) {
            if (e.ring == r || !(e.min_x < p.x)) return;
            const Ring& ring = rings[e.ring];
            Vec2 a = ring[e.index], b = ring[(e.index + 1) % ring.size()];
            if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) return;
            double x =
                a.y == b.y ? std::max(a.x, b.x) : a.x + (b.x - a.x) * (p.y - a.y) / (b.y - a.y);
            if (x < p.x && x > hit_x) hit_x = x, hit = e.ring, hit_edge = e.index;
          };
          if (queries[row] <= kScanQueries) {
            for (auto e = bucket_begin; e != bucket_end; ++e) consider(*e);
          } else {
            auto end = std::lower_bound(bucket_begin, bucket_end, p.x,
                                        [](const BucketEdge& e, double x) { return e.min_x < x; });
            // Walking leftwards: an edge starting at min_x crosses at most at min_x + widest.
            for (auto e = end; e != bucket_begin;) {
              --e;
              if (e->min_x + widest[row] <= hit_x) break;
              consider(*e);
            }
          }
          hits[r] = hit, hit_edges[r] = hit_edge;
        }
      });
  // A sibling's parent is known first: the ring hit lies to the left, so it comes first in the
  // order of leftmost vertices.
  std::vector<int> order(count);
  for (int r = 0; r < count; ++r) order[r] = r;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    Vec2 pa = rings[a][leftmost[a]], pb = rings[b][leftmost[b]];
    return pa.x != pb.x ? pa.x < pb.x : (pa.y != pb.y ? pa.y < pb.y : a < b);
  });
  for (int r : order) {
    const int hit = hits[r];
    if (hit < 0) continue;
    parents[r] = outer[r] != outer[hit] ? hit : parents[hit];
  }
  if (misplaced) {
    // The rule above holds for rings nested as traced, where the ring hit first encloses the ring
    // exactly when their orientations differ. Simplified rings may break it (a hole left to the
    // right of an outer boundary that shrank away from it), so the side of the hit edge that
    // faces the ring tells whether the ring hit encloses it; at a vertex, an even-odd count.
    for (int r = 0; r < count; ++r) {
      const int hit = hits[r];
      if (hit < 0) continue;
      const Ring& ring = rings[hit];
      const Vec2 p = rings[r][leftmost[r]];
      const Vec2 a = ring[hit_edges[r]], b = ring[(hit_edges[r] + 1) % ring.size()];
      bool encloses;
      if (std::min(a.y, b.y) < p.y && p.y < std::max(a.y, b.y)) {
        // A counter-clockwise ring encloses what lies left of its edges: east of a downward edge.
        encloses = (b.y < a.y) == static_cast<bool>(outer[hit]);
      } else {
        // The ray meets the ring hit at its vertex v (v.y == p.y; the right end of a horizontal
        // edge). The count below treats a vertex at p.y as below the ray, as a ray just above
        // p.y would: that ray meets no edge of the ring hit between v and p, so where exactly
        // one of v's edges crosses it, that edge is its nearest crossing and tells the side.
        const std::size_t n = ring.size(), i = static_cast<std::size_t>(hit_edges[r]);
        const std::size_t v = a.y == b.y   ? (a.x >= b.x ? i : (i + 1) % n)
                              : a.y == p.y ? i
                                           : (i + 1) % n;
        const Vec2 before = ring[(v + n - 1) % n], at = ring[v], after = ring[(v + 1) % n];
        const bool in_crosses = (before.y > p.y) != (at.y > p.y);
        const bool out_crosses = (at.y > p.y) != (after.y > p.y);
        if (in_crosses != out_crosses) {
          const Vec2 from = in_crosses ? before : at, to = in_crosses ? at : after;
          encloses = (to.y < from.y) == static_cast<bool>(outer[hit]);
        } else {
          // Both of v's edges cross that ray or neither does (v turns in y, or ends a
          // horizontal edge, at p.y): counted. Only edges whose y range holds p.y can cross its
          // row, and each is in the row's bucket once (counting over the whole ring was
          // quadratic where many specks face a long ring at its vertices).
          encloses = false;
          const int row = row_of(r);
          for (const BucketEdge* e = std::as_const(edges).begin(row);
               e != std::as_const(edges).end(row); ++e) {
            if (e->ring != hit) continue;
            const Vec2 c = ring[e->index], d = ring[(e->index + 1) % ring.size()];
            if ((c.y > p.y) != (d.y > p.y) && p.x < c.x + (d.x - c.x) * (p.y - c.y) / (d.y - c.y)) {
              encloses = !encloses;
            }
          }
        }
      }
      (*misplaced)[r] = encloses != (outer[r] != outer[hit]);
    }
  }
  if (met_first) *met_first = std::move(hits);
  return parents;
}

std::vector<Ring> simplify_rings(const std::vector<Ring>& rings, const std::vector<int>& parents,
                                 double eps, unsigned threads,
                                 const std::function<bool(Vec2)>& pinned) {
  Simplifier simplifier(rings, eps, threads, pinned);
  std::vector<Ring> result;
  while (true) {
    simplifier.untangle();
    result = simplifier.current();
    // Disjoint rings can still have changed nesting (a small ring swallowed whole by a
    // neighbour's chord) or a sliver its orientation: restore those rings and check again.
    bool restored = false;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      if ((signed_area(result[r]) > 0) != (signed_area(rings[r]) > 0)) {
        simplifier.restore(static_cast<int>(r));
        restored = true;
      }
    }
    if (!restored) {
      std::vector<char> misplaced;
      std::vector<int> met_first;
      std::vector<int> now = nesting_parents(result, threads, &misplaced, &met_first);
      std::vector<int> wrong;
      for (std::size_t r = 0; r < rings.size(); ++r) {
        if (now[r] == parents[r] && !misplaced[r]) continue;
        wrong.push_back(static_cast<int>(r));
        // Restoring rings already whole changes nothing: only a change loops again.
        restored |= simplifier.restore(static_cast<int>(r));
        if (now[r] >= 0) restored |= simplifier.restore(now[r]);
        if (parents[r] >= 0) restored |= simplifier.restore(parents[r]);
        // The ring met first may be what moved: a hole whose chord swallowed another hole is
        // neither's parent (stop 48's review: --simplify 2 left one hole inside another).
        if (misplaced[r] && met_first[r] >= 0) restored |= simplifier.restore(met_first[r]);
      }
      // Still wrong with all those whole: the ring that moved lies further out (a hole swallowed
      // by another hole, an island of which the leftward ray meets first). It encloses the ring,
      // so its box holds the ring's vertices: every such ring is restored.
      if (!restored && !wrong.empty()) {
        std::vector<Box> boxes(result.size());
        for (std::size_t s = 0; s < result.size(); ++s) {
          for (const Vec2& v : result[s]) boxes[s].add(v);
        }
        for (int r : wrong) {
          const Vec2 p = result[static_cast<std::size_t>(r)][0];
          for (std::size_t s = 0; s < result.size(); ++s) {
            if (boxes[s].holds(p)) restored |= simplifier.restore(static_cast<int>(s));
          }
        }
        // Never seen, but the rings as traced are nested right: the last resort is all of them.
        if (!restored) {
          for (std::size_t s = 0; s < result.size(); ++s) {
            restored |= simplifier.restore(static_cast<int>(s));
          }
        }
      }
    }
    if (!restored) break;
  }
  for (Ring& ring : result) ring = without_collinear(std::move(ring));
  return result;
}

}  // namespace hullcook::trace_detail
