// Marching squares on the alpha field, ring assembly into regions, and the trace entry points.
#include "hullcook/trace/trace.h"

#include "hullcook/core/error.h"
#include "rings.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>

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
//
// Cost: a pass over the pixels that skips eight uniform cells at a time (comparing words of the
// two rows' opaque flags), and the real work only in the cells the outline crosses.
std::vector<Ring> march(const AlphaImage& image, int threshold) {
  const int width = image.width, height = image.height;
  // The padding is transparent even at threshold 0, where every real pixel is opaque.
  const int padding = threshold == 0 ? -1 : 0;
  const double level = threshold - 0.5;  // strictly between integer alphas: no crossing at a corner
  auto value = [&](int x, int y) -> int {
    if (x < 0 || y < 0 || x >= width || y >= height) return padding;
    return image.alpha[static_cast<std::size_t>(y) * width + x];
  };

  // Opaque flags (0 or 1) of pixel rows y and y+1, index x+1, with the transparent padding at both
  // ends and eight spare zero bytes for the word loads.
  const std::size_t stride = static_cast<std::size_t>(width) + 2 + 8;
  const auto level8 = static_cast<std::uint8_t>(threshold);  // threshold is within [0, 255]
  std::vector<std::uint8_t> flags(2 * stride, 0);
  std::uint8_t* upper = flags.data();
  std::uint8_t* lower = flags.data() + stride;
  // Loads row y's flags into out; true when one of them is opaque.
  auto load_flags = [&](int y, std::uint8_t* out) {
    if (y < 0 || y >= height) {
      std::fill(out, out + stride, std::uint8_t{0});
      return false;
    }
    const std::uint8_t* alpha = image.alpha.data() + static_cast<std::size_t>(y) * width;
    // Compared as bytes, sixteen to a vector instruction (as int, four).
    std::uint8_t any = 0;
    for (int x = 0; x < width; ++x) {
      out[x + 1] = alpha[x] >= level8;
      any |= out[x + 1];
    }
    return any != 0;
  };
  auto word = [](const std::uint8_t* p) {
    std::uint64_t w;
    std::memcpy(&w, p, sizeof w);
    return w;
  };

  std::vector<Vec2> points;
  std::vector<int> next;
  // Point ids on the horizontal edges of pixel rows y and y+1 (indexed by the left pixel's x+1)
  // and on the vertical edges of the current cell row (indexed by the pixel's x+1). An id is
  // current only if made since the row that owns the array began (ids only grow), so the
  // arrays are never cleared.
  std::vector<int> top(width + 2, -1), bottom(width + 2, -1), vertical(width + 3, -1);
  int top_first = 0, row_first = 0;  // the first ids made in cell rows y-1 and y
  auto crossing = [&](int x0, int y0, int x1, int y1) {
    double v0 = value(x0, y0), v1 = value(x1, y1);
    double t = (level - v0) / (v1 - v0);
    Vec2 a{x0 + 0.5, y0 + 0.5}, b{x1 + 0.5, y1 + 0.5};
    points.push_back(a + t * (b - a));
    next.push_back(-1);
    return static_cast<int>(points.size()) - 1;
  };

  auto cell = [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>(x + 1);
    const std::array<bool, 4> opaque{upper[i] != 0, upper[i + 1] != 0, lower[i + 1] != 0,
                                     lower[i] != 0};
    std::array<int*, 4> slots{&top[x + 1], &vertical[x + 2], &bottom[x + 1], &vertical[x + 1]};
    const std::array<int, 4> firsts{top_first, row_first, row_first, row_first};
    const std::array<std::array<int, 4>, 4> ends{
        {{x, y, x + 1, y}, {x + 1, y, x + 1, y + 1}, {x, y + 1, x + 1, y + 1}, {x, y, x, y + 1}}};
    auto point_on = [&](int k) {
      if (*slots[k] < firsts[k])
        *slots[k] = crossing(ends[k][0], ends[k][1], ends[k][2], ends[k][3]);
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
  };

  bool upper_any = load_flags(-1, upper);
  for (int y = -1; y < height; ++y) {
    const bool lower_any = load_flags(y + 1, lower);
    row_first = static_cast<int>(points.size());
    // Cells x = -1 .. width-1 are i = x+1 = 0 .. width; eight at a time while uniform, and none
    // between two transparent rows (a sprite's margins, an atlas's gaps).
    for (int i = upper_any || lower_any ? 0 : width + 1; i <= width;) {
      const std::uint64_t a = word(upper + i), a1 = word(upper + i + 1), b = word(lower + i),
                          b1 = word(lower + i + 1);
      if (((a | a1 | b | b1) ^ (a & a1 & b & b1)) == 0) {
        i += 8;
        continue;
      }
      for (const int end = std::min(i + 8, width + 1); i < end; ++i) {
        const int corners = upper[i] + upper[i + 1] + lower[i] + lower[i + 1];
        if (corners != 0 && corners != 4) cell(i - 1, y);
      }
    }
    std::swap(top, bottom);
    std::swap(upper, lower);
    upper_any = lower_any;
    top_first = row_first;
  }

  std::vector<Ring> rings;
  std::vector<char> visited(points.size(), 0);
  for (std::size_t start = 0; start < points.size(); ++start) {
    if (visited[start]) continue;
    std::size_t length = 0;
    for (int p = static_cast<int>(start); !visited[p]; p = next[p]) visited[p] = 2, ++length;
    Ring& ring = rings.emplace_back();
    ring.reserve(length);
    for (int p = static_cast<int>(start); visited[p] == 2; p = next[p]) {
      visited[p] = 1;
      ring.push_back(points[p]);
    }
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
  std::vector<int> parents = nesting_parents(rings, settings.threads);

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
      simplify_rings(kept_rings, kept_parents, std::max(0.0, settings.simplify), settings.threads);

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
