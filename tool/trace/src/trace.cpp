// Marching squares on the alpha field, ring assembly into regions, and the trace entry points.
#include "hullcook/trace/trace.h"

#include "hullcook/core/error.h"
#include "rings.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace hullcook {
namespace {

using trace_detail::nesting_parents;
using trace_detail::signed_area;
using trace_detail::simplify_rings;

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// Closed rings of the threshold crossing, oriented with the opaque side on the left (positive
// shoelace area for outer rings in y-down pixel coordinates), opaque 8-connected.
//
// Cells have their corners at pixel centres. The cell whose top-left corner is pixel (x, y) has
// corners c0 = (x, y), c1 = (x+1, y), c2 = (x+1, y+1), c3 = (x, y+1), in the positive order, and
// edges e_k from c_k to c_{k+1}. Walking the corners in that order, each edge leaving the opaque
// side is joined to the next edge entering it; in a saddle cell that joins the two opaque
// corners, which is the 8-connected rule.
std::vector<Ring> march(const AlphaImage& image, int threshold) {
  const int width = image.width, height = image.height;
  // The padding is transparent even at threshold 0, where every real pixel is opaque.
  const int padding = threshold == 0 ? -1 : 0;
  const double level = threshold - 0.5;  // strictly between integer alphas: no crossing at a corner
  auto value = [&](int x, int y) -> int {
    if (x < 0 || y < 0 || x >= width || y >= height) return padding;
    return image.alpha[static_cast<std::size_t>(y) * width + x];
  };

  std::vector<Vec2> points;
  std::vector<int> next;
  // Point ids on the horizontal edges of pixel rows y and y+1 (indexed by the left pixel's x+1)
  // and on the vertical edges of the current cell row (indexed by the pixel's x+1).
  std::vector<int> top(width + 2, -1), bottom(width + 2, -1), vertical(width + 3, -1);
  auto crossing = [&](int x0, int y0, int x1, int y1) {
    double v0 = value(x0, y0), v1 = value(x1, y1);
    double t = (level - v0) / (v1 - v0);
    Vec2 a{x0 + 0.5, y0 + 0.5}, b{x1 + 0.5, y1 + 0.5};
    points.push_back(a + t * (b - a));
    next.push_back(-1);
    return static_cast<int>(points.size()) - 1;
  };

  for (int y = -1; y < height; ++y) {
    std::fill(bottom.begin(), bottom.end(), -1);
    std::fill(vertical.begin(), vertical.end(), -1);
    for (int x = -1; x < width; ++x) {
      const std::array<bool, 4> opaque{value(x, y) >= threshold, value(x + 1, y) >= threshold,
                                       value(x + 1, y + 1) >= threshold,
                                       value(x, y + 1) >= threshold};
      if (opaque[0] == opaque[1] && opaque[1] == opaque[2] && opaque[2] == opaque[3]) continue;
      std::array<int*, 4> slots{&top[x + 1], &vertical[x + 2], &bottom[x + 1], &vertical[x + 1]};
      const std::array<std::array<int, 4>, 4> ends{
          {{x, y, x + 1, y}, {x + 1, y, x + 1, y + 1}, {x, y + 1, x + 1, y + 1}, {x, y, x, y + 1}}};
      auto point_on = [&](int k) {
        if (*slots[k] < 0) *slots[k] = crossing(ends[k][0], ends[k][1], ends[k][2], ends[k][3]);
        return *slots[k];
      };
      for (int k = 0; k < 4; ++k) {
        if (!(opaque[k] && !opaque[(k + 1) % 4])) continue;  // e_k leaves the opaque side
        for (int step = 1; step < 4; ++step) {
          int e = (k + step) % 4;
          if (!opaque[e] && opaque[(e + 1) % 4]) {  // e enters the opaque side
            next[point_on(k)] = point_on(e);
            break;
          }
        }
      }
    }
    std::swap(top, bottom);
  }

  std::vector<Ring> rings;
  std::vector<char> visited(points.size(), 0);
  for (std::size_t start = 0; start < points.size(); ++start) {
    if (visited[start]) continue;
    Ring ring;
    for (int p = static_cast<int>(start); !visited[p]; p = next[p]) {
      visited[p] = 1;
      ring.push_back(points[p]);
    }
    rings.push_back(std::move(ring));
  }
  return rings;
}

bool before(const Vec2& a, const Vec2& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }

}  // namespace

TraceResult trace_alpha(const AlphaImage& image, const TraceSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  if (image.width < 0 || image.height < 0 ||
      image.alpha.size() != static_cast<std::size_t>(image.width) * image.height) {
    throw InputError("alpha image: " + std::to_string(image.alpha.size()) + " values for " +
                     std::to_string(image.width) + "x" + std::to_string(image.height) + " pixels");
  }
  TraceResult result;
  result.width = image.width;
  result.height = image.height;
  const int threshold = std::clamp(settings.alpha, 0, 255);

  std::vector<Ring> rings = march(image, threshold);
  if (rings.empty()) {
    result.warnings.push_back("fully transparent (no pixel with alpha >= " +
                              std::to_string(threshold) + "): no region traced");
    result.trace_ms = milliseconds_since(start);
    return result;
  }
  std::vector<int> parents = nesting_parents(rings);

  // Specks and pin holes go with everything inside them (a blob inside a filled hole is solid).
  const int count = static_cast<int>(rings.size());
  std::vector<double> areas(count);
  for (int r = 0; r < count; ++r) areas[r] = signed_area(rings[r]);
  std::vector<int> depth(count, -1);
  auto depth_of = [&](int r) {
    int d = 0;
    for (int p = parents[r]; p >= 0; p = parents[p]) ++d;
    return d;
  };
  for (int r = 0; r < count; ++r) depth[r] = depth_of(r);
  std::vector<int> by_depth(count);
  for (int r = 0; r < count; ++r) by_depth[r] = r;
  std::stable_sort(by_depth.begin(), by_depth.end(),
                   [&](int a, int b) { return depth[a] < depth[b]; });
  std::vector<char> kept(count, 0);
  for (int r : by_depth) {
    if (parents[r] >= 0 && !kept[parents[r]]) continue;
    bool outer = areas[r] > 0;
    double limit = outer ? settings.min_blob_area : settings.min_hole_area;
    if (std::abs(areas[r]) >= limit) kept[r] = 1;
  }

  std::vector<Ring> kept_rings;
  std::vector<int> new_index(count, -1);
  for (int r = 0; r < count; ++r) {
    if (!kept[r]) continue;
    new_index[r] = static_cast<int>(kept_rings.size());
    kept_rings.push_back(std::move(rings[r]));
    result.traced_vertices += kept_rings.back().size();
  }
  std::vector<int> kept_parents;
  for (int r = 0; r < count; ++r) {
    if (kept[r]) kept_parents.push_back(parents[r] >= 0 ? new_index[parents[r]] : -1);
  }
  std::vector<Ring> simplified =
      simplify_rings(kept_rings, kept_parents, std::max(0.0, settings.simplify));

  std::vector<int> region_of(simplified.size(), -1);
  for (std::size_t r = 0; r < simplified.size(); ++r) {
    if (kept_parents[r] >= 0 && signed_area(kept_rings[r]) < 0) continue;
    region_of[r] = static_cast<int>(result.regions.size());
    result.regions.push_back({std::move(simplified[r]), {}});
  }
  for (std::size_t r = 0; r < simplified.size(); ++r) {
    if (region_of[r] >= 0) continue;
    result.regions[region_of[kept_parents[r]]].holes.push_back(std::move(simplified[r]));
  }
  // Deterministic order whatever the container internals: regions and holes by first vertex,
  // each ring starting at its top-left vertex.
  auto rotate_to_first = [](Ring& ring) {
    std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), before), ring.end());
  };
  for (Region& region : result.regions) {
    rotate_to_first(region.outer);
    for (Ring& hole : region.holes) rotate_to_first(hole);
    std::sort(region.holes.begin(), region.holes.end(),
              [](const Ring& a, const Ring& b) { return before(a.front(), b.front()); });
  }
  std::sort(result.regions.begin(), result.regions.end(), [](const Region& a, const Region& b) {
    return before(a.outer.front(), b.outer.front());
  });

  if (result.regions.empty()) {
    result.warnings.push_back("every blob is smaller than --min-blob-area " +
                              std::to_string(settings.min_blob_area) + " px²: no region traced");
  }
  result.trace_ms = milliseconds_since(start);
  return result;
}

TraceResult trace_image(const std::filesystem::path& path, const TraceSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  AlphaImage image = load_alpha(path, settings);
  const double decode_ms = milliseconds_since(start);
  TraceResult result = trace_alpha(image, settings);
  result.decode_ms = decode_ms;
  for (std::string& warning : result.warnings) warning = path.string() + ": " + warning;
  return result;
}

}  // namespace hullcook
