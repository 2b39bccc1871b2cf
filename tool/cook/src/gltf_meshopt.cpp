#include "gltf_meshopt.h"

#include "contract_text.h"
#include "hullcook/cook/meshopt_library.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/format/bundle_layout.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace hullcook {

Quantization Quantization::of(const CookedAsset& asset) {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (const CookedLevel& level : asset.levels) {
    for (const Ring& hull : level.hulls) {
      for (const Vec2& v : hull) {
        min_x = std::min(min_x, v.x), max_x = std::max(max_x, v.x);
        min_y = std::min(min_y, v.y), max_y = std::max(max_y, v.y);
      }
    }
  }
  Quantization grid;
  if (!(min_x <= max_x)) return grid;  // no vertex
  const double tau = asset.levels.empty() ? asset.tau : asset.levels.front().tau;
  const double extent = std::max(max_x - min_x, max_y - min_y);
  grid.step = std::max({std::sqrt(2.0) * 0.01 * tau,
                        std::sqrt(2.0) / (64.0 * asset.pixels_per_unit), extent / 65000.0});
  grid.origin = {0.5 * (min_x + max_x), 0.5 * (min_y + max_y)};
  // About the origin, the int16 range holds 65 534 quanta less the rounding of both ends. (The
  // step's own 65 000 may come back a few ulps over 65 000 when the extent sets it: the test
  // against 65 000 refused hulls 1e6 wide.)
  constexpr double kQuantaAboutTheOrigin = 65532.0;
  if (asset.tile) {
    // As the bundle does (formats/SPEC.md §9): half a pixel over a power of two, with the origin
    // on that grid, so that the cell's borders (at whole or half pixels from the pivot) are grid
    // points, halved steps included, and neighbouring tiles' hulls meet exactly (stop 55's sweep:
    // a full 32 px tile read back 16.0089 units wide of its centre). A cell too large for that
    // step in 16 bits (over 32,765 px) keeps the grid below, as the weld margin assumes no
    // coarser step (formats/SPEC.md §9).
    const double aligned = format::tile_step(asset.pixels_per_unit, grid.step);
    if (aligned > 0.0 && std::isfinite(aligned) && extent / aligned <= kQuantaAboutTheOrigin - 1) {
      grid.step = aligned;
      grid.origin = {std::round(grid.origin.x / aligned) * aligned,
                     std::round(grid.origin.y / aligned) * aligned};
    }
  }
  if (!(grid.step > 0.0) || !std::isfinite(grid.step) ||
      extent / grid.step > kQuantaAboutTheOrigin) {
    throw OutputError("asset " + asset.name + ": its hulls do not fit a 16-bit grid");
  }
  // A hull thinner than the step would reach a reader as a line or a point (zero area, which
  // physics engines refuse or mistake): the step is halved until every hull keeps its area, as
  // long as the asset's span fits 16 bits.
  for (;;) {
    std::size_t flat_level = 0, flat_hull = 0;
    const Ring* flat = nullptr;
    for (std::size_t l = 0; l < asset.levels.size() && !flat; ++l) {
      const std::vector<Ring>& hulls = asset.levels[l].hulls;
      for (std::size_t h = 0; h < hulls.size() && !flat; ++h) {
        if (grid.flattens(hulls[h])) flat = &hulls[h], flat_level = l, flat_hull = h;
      }
    }
    if (!flat) return grid;
    const double finer = 0.5 * grid.step;
    if (extent / finer <= kQuantaAboutTheOrigin) {
      grid.step = finer;
      continue;
    }
    const double least_step = extent / kQuantaAboutTheOrigin;
    throw OutputError(
        "asset " + asset.name + ": hull " + std::to_string(flat_hull) + " of level " +
        std::to_string(flat_level) + ", at " + detail::point((*flat)[0]) + ", " +
        detail::number(convex_thickness(*flat)) +
        " output units thick, would reach a reader as a line or a point on the 16-bit grid of "
        "--meshopt: the asset spans " +
        detail::number(extent) + " units, so 16 bits hold no step finer than " +
        detail::number(least_step) +
        ", and none of the halved steps down to it keeps the hull; write it without --meshopt, "
        "whose 32-bit floats hold it, or cook it with a larger tau, which leaves fewer thin "
        "pieces");
  }
}

std::int16_t Quantization::x(double value) const {
  return static_cast<std::int16_t>(std::lround((value - origin.x) / step));
}
std::int16_t Quantization::y(double value) const {
  return static_cast<std::int16_t>(std::lround((value - origin.y) / step));
}

namespace {

struct GridPoint {
  std::int64_t x, y;
};

// The vertices of hull (as indices) that are left once those whose rounded points do not turn
// left are left out, one at a time: leaving out such a vertex keeps it in the ring (on or inside
// the new edge), so once every vertex turns left the ring holds all of them. Fewer than 3: the
// rounded hull is a line or a point.
std::vector<std::size_t> turning_left(const std::vector<GridPoint>& rounded) {
  auto turns_left = [&](std::size_t a, std::size_t b, std::size_t c) {
    const GridPoint p = rounded[a], q = rounded[b], r = rounded[c];
    return (q.x - p.x) * (r.y - q.y) - (q.y - p.y) * (r.x - q.x) > 0;  // exact: |values| < 2^17
  };
  std::vector<std::size_t> kept(rounded.size());
  for (std::size_t i = 0; i < kept.size(); ++i) kept[i] = i;
  for (bool changed = true; changed && kept.size() >= 3;) {
    changed = false;
    for (std::size_t k = 0; k < kept.size() && kept.size() >= 3;) {
      const std::size_t m = kept.size();
      if (turns_left(kept[(k + m - 1) % m], kept[k], kept[(k + 1) % m])) {
        ++k;
      } else {
        kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
      }
    }
  }
  return kept;
}

}  // namespace

bool Quantization::flattens(const Ring& hull) const {
  // Rounding takes nothing from a hull without area (or clockwise, against the contract).
  if (!(signed_area(hull) > 0.0)) return false;
  std::vector<GridPoint> rounded;
  rounded.reserve(hull.size());
  for (const Vec2& v : hull) rounded.push_back({x(v.x), y(v.y)});
  return turning_left(rounded).size() < 3;
}

Ring Quantization::held(const Ring& hull) const {
  std::vector<GridPoint> rounded;
  rounded.reserve(hull.size());
  for (const Vec2& v : hull) rounded.push_back({x(v.x), y(v.y)});
  const std::vector<std::size_t> kept = turning_left(rounded);
  if (kept.size() < 3 || kept.size() == hull.size()) return hull;
  // Turning left at every vertex, it is convex if it winds once (a sum of exterior angles of 2π,
  // not 4π or more).
  double turning = 0;
  for (std::size_t k = 0, m = kept.size(); k < m; ++k) {
    const GridPoint p = rounded[kept[k]], q = rounded[kept[(k + 1) % m]],
                    r = rounded[kept[(k + 2) % m]];
    const double ax = double(q.x - p.x), ay = double(q.y - p.y);
    const double bx = double(r.x - q.x), by = double(r.y - q.y);
    turning += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  if (!(turning < 3 * M_PI)) return hull;
  Ring out;
  out.reserve(kept.size());
  for (std::size_t i : kept) out.push_back(hull[i]);
  return out;
}

std::string meshopt_compress(std::string_view data, std::size_t stride, MeshoptMode mode) {
  std::string problem;
  const MeshoptLibrary* meshopt = meshopt_library(&problem);
  if (meshopt == nullptr) throw OutputError("cannot compress with meshoptimizer: " + problem);
  const std::size_t count = data.size() / stride;
  std::vector<unsigned char> out;
  std::size_t size = 0;
  if (mode == MeshoptMode::attributes) {
    out.resize(meshopt->encodeVertexBufferBound(count, stride));
    size = meshopt->encodeVertexBuffer(out.data(), out.size(), data.data(), count, stride);
  } else {
    std::vector<unsigned int> indices(count);
    for (std::size_t i = 0; i < count; ++i) {
      if (stride == 2) {
        std::uint16_t value;
        std::memcpy(&value, data.data() + 2 * i, 2);
        indices[i] = value;
      } else {
        std::memcpy(&indices[i], data.data() + 4 * i, 4);
      }
    }
    const unsigned int vertices =
        indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end()) + 1;
    // Version 1 of the index codec, the one EXT_meshopt_compression's decoders read.
    meshopt->encodeIndexVersion(1);
    out.resize(meshopt->encodeIndexBufferBound(count, vertices));
    size = meshopt->encodeIndexBuffer(out.data(), out.size(), indices.data(), count);
  }
  if (size == 0) throw OutputError("meshoptimizer could not compress a bufferView");
  return std::string(reinterpret_cast<const char*>(out.data()), size);
}

}  // namespace hullcook
