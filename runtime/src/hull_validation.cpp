#include "hull_validation.h"

#include "hullcook/format/bundle_layout.h"

#include <cstddef>
#include <cstring>

namespace hullcook::runtime::detail {
namespace {

using format::HullRecord;
using format::load;
using format::VertexRecord;

// Consecutive hulls are checked together in batches of up to this many vertices, as one flat
// pass over their vertices whose loops have no data-dependent branch (a per-hull loop mispredicts
// its exit on nearly every hull of 3 to 8 vertices) and which the compiler vectorizes. A longer
// hull is checked alone.
constexpr std::size_t kBatchVertices = 512;

struct Edge {
  std::int64_t x, y;
};

std::int64_t cross(Edge a, Edge b) { return a.x * b.y - a.y * b.x; }

// Whether an edge points into the upper half-plane, angle in [0, pi) (see
// format::hull_is_strictly_convex): y > 0, or y == 0 and x > 0.
inline std::uint32_t upper(std::int32_t x, std::int32_t y) {
  return static_cast<std::uint32_t>(2 * y + (x > 0) > 0);
}

// x86-64 CPUs since 2013 multiply 32-bit lanes and hold 8 of them (AVX2), the baseline only 4
// with emulated multiplication: with GCC the batch check is compiled for both and one is picked
// at load time (an ifunc); other compilers build the baseline only.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define HULLCOOK_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define HULLCOOK_VECTOR_CLONES
#endif

// The hulls [first_hull, end_hull), whose vertices are the `count` from vertex `base` (ranges
// already checked: at least 3 vertices each). Exactly format::hull_is_strictly_convex on each:
// with successor[i] the vertex after i in its hull (its first after its last) and
// second[i] the one after that, every turn of every hull is (i, successor[i], second[i]) for one
// i, so one branch-free loop over i, which the compiler vectorizes, computes all of them. Every
// hull's winding number is at least 1 when its turns are all strictly left, so the hulls' sum of
// windings equals their count exactly when each winds once.
HULLCOOK_VECTOR_CLONES
bool batch_is_convex(const unsigned char* vertices, std::uint32_t base, std::uint32_t count,
                     const unsigned char* hull_records, std::uint32_t first_hull,
                     std::uint32_t end_hull) {
  const unsigned char* batch = vertices + 4 * std::size_t{base};
  std::uint32_t word[kBatchVertices], successor[kBatchVertices], second[kBatchVertices];
  std::memcpy(word, batch, 4 * std::size_t{count});
  std::memcpy(successor, batch + 4, 4 * std::size_t{count - 1});
  std::memcpy(second, batch + 8, 4 * std::size_t{count - 2});
  for (std::uint32_t hull = first_hull; hull < end_hull; ++hull) {
    const std::uint32_t a =
        load<std::uint32_t>(hull_records + std::size_t{hull} * sizeof(HullRecord)) - base;
    const std::uint32_t b =
        (hull + 1 < end_hull
             ? load<std::uint32_t>(hull_records + (std::size_t{hull} + 1) * sizeof(HullRecord))
             : base + count) -
        base;
    successor[b - 1] = word[a];
    second[b - 2] = word[a];
    second[b - 1] = word[a + 1];
  }
  auto x_of = [](std::uint32_t w) { return std::int32_t{static_cast<std::int16_t>(w)}; };
  auto y_of = [](std::uint32_t w) { return std::int32_t{static_cast<std::int16_t>(w >> 16)}; };
  // The cross product is computed modulo 2^32, which is exact while every edge component is in
  // [-32768, 32767] (`wide` tells); otherwise the turns are computed again in 64 bits below.
  std::uint32_t not_left = 0, windings = 0, wide = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t w0 = word[i], w1 = successor[i], w2 = second[i];
    const std::int32_t ex = x_of(w1) - x_of(w0), ey = y_of(w1) - y_of(w0);
    const std::int32_t fx = x_of(w2) - x_of(w1), fy = y_of(w2) - y_of(w1);
    wide |= static_cast<std::uint32_t>(ex + 32768) | static_cast<std::uint32_t>(ey + 32768);
    const std::uint32_t turn = static_cast<std::uint32_t>(ex) * static_cast<std::uint32_t>(fy) -
                               static_cast<std::uint32_t>(ey) * static_cast<std::uint32_t>(fx);
    not_left += static_cast<std::int32_t>(turn) <= 0;
    windings += upper(fx, fy) > upper(ex, ey);
  }
  if ((wide >> 16) != 0) {
    not_left = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::uint32_t w0 = word[i], w1 = successor[i], w2 = second[i];
      const Edge e{x_of(w1) - x_of(w0), y_of(w1) - y_of(w0)};
      const Edge f{x_of(w2) - x_of(w1), y_of(w2) - y_of(w1)};
      not_left += cross(e, f) <= 0;
    }
  }
  return not_left == 0 && windings == end_hull - first_hull;
}

}  // namespace

Status validate_hulls(const unsigned char* hull_records, std::uint32_t hull_count,
                      const unsigned char* vertices, std::uint32_t vertex_count) noexcept {
  auto first_vertex = [&](std::uint32_t hull) {
    return load<std::uint32_t>(hull_records + std::size_t{hull} * sizeof(HullRecord));
  };
  if (hull_count > 0 && first_vertex(0) != 0) return Status::malformed;
  std::uint32_t hull = 0;
  while (hull < hull_count) {
    // Gather the hulls that fit in a batch (or one long hull), checking their ranges.
    const std::uint32_t base = first_vertex(hull);
    std::uint32_t end_hull = hull, end = base;
    Status range = Status::ok;
    while (end_hull < hull_count) {
      const std::uint32_t next =
          end_hull + 1 < hull_count ? first_vertex(end_hull + 1) : vertex_count;
      if (next > vertex_count) {
        range = Status::out_of_bounds;
        break;
      }
      if (next < end || next - end < format::kMinHullVertices) {
        range = Status::malformed;
        break;
      }
      if (next - base > kBatchVertices && end_hull > hull) break;
      end = next;
      ++end_hull;
      if (end - base > kBatchVertices) break;  // one long hull
    }
    if (end_hull == hull) return range;
    const bool convex =
        end - base > kBatchVertices
            ? format::hull_is_strictly_convex(vertices + 4 * std::size_t{base}, end - base)
            : batch_is_convex(vertices, base, end - base, hull_records, hull, end_hull);
    if (!convex) return Status::malformed;
    hull = end_hull;  // a range error stops the next gathering at once
  }
  return Status::ok;
}

}  // namespace hullcook::runtime::detail
