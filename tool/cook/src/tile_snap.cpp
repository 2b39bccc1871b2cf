#include "tile_snap.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace hullcook {
namespace {

// Within snap of the border, but for a point a whole number of pixels in, which only a closer
// snap moves: the traced outline of hard-edged art lies on a half-pixel lattice, and a point a
// whole pixel in (at the default snap of 1) is the shape's own, as the underside of a 1 px
// one-way platform or a frame's inner side. Put on the border, it squashed such a tile flat, and
// the tile was then kept as traced (with a warning) and met its neighbours with steps. A corner
// that the tracing cut by half a pixel is put back at any snap of 0.5 and more.
bool near_border(double distance, double snap) {
  return distance < snap || (distance == snap && distance != std::floor(distance));
}

double onto_border(double value, double extent, double snap) {
  value = std::clamp(value, 0.0, extent);
  if (near_border(value, snap)) return 0.0;
  if (near_border(extent - value, snap)) return extent;
  return value;
}

std::vector<Region> moved(const std::vector<Region>& regions, int width, int height, double snap) {
  std::vector<Region> result = regions;
  auto move_ring = [&](Ring& ring) {
    for (Vec2& p : ring) {
      p.x = onto_border(p.x, width, snap);
      p.y = onto_border(p.y, height, snap);
    }
  };
  for (Region& region : result) {
    move_ring(region.outer);
    for (Ring& hole : region.holes) move_ring(hole);
  }
  return result;
}

std::optional<std::vector<Region>> valid(std::vector<Region> regions, const std::string& source) {
  try {
    return clean_and_validate(std::move(regions), source);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace

std::vector<Region> snap_to_cell(const std::vector<Region>& regions, int width, int height,
                                 double snap, const std::string& source,
                                 std::vector<std::string>& warnings) {
  if (regions.empty()) return regions;
  if (auto snapped = valid(moved(regions, width, height, snap), source)) return *snapped;
  warnings.push_back(
      "--tile: snapping the outline to the cell's border would make it invalid "
      "(a part thinner than --snap at the border); kept as traced");
  if (auto clamped = valid(moved(regions, width, height, 0.0), source)) return *clamped;
  return regions;
}

}  // namespace hullcook
