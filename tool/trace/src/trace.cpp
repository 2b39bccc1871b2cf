// Marching squares on the alpha field, ring assembly into regions, and the trace entry points.
#include "hullcook/trace/trace.h"

#include "hullcook/core/error.h"
#include "hullcook/core/parallel_for.h"
#include "rings.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace hullcook {
namespace {

using trace_detail::nesting_parents;
using trace_detail::signed_area;
using trace_detail::simplify_rings;

// Below this many pixels, marching costs less than starting a thread.
constexpr std::size_t kPixelsWorthAThread = 1 << 18;

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// One band of cell rows' crossing points, numbered from 0 in the order the whole march would
// make them. The points on the band's top pixel row belong to the band above (its last row made
// them): they are referred to as -(x + 2), by the left pixel's x.
constexpr int kUnlinked = std::numeric_limits<int>::max();  // a point whose next is not known yet

struct MarchedBand {
  std::vector<Vec2> points;
  std::vector<int> next;  // per point: the next point of its ring (a band's own or one above)
  std::vector<std::pair<int, int>> next_of_above;  // (a point above, the next point)
  std::vector<int> bottom;  // the points on the pixel row below the band, by x + 1
};

// The links of a marching-squares cell by its case (corner k opaque: bit k), in the order the
// edges leaving the opaque side come (ascending k); an unused entry has leaving = 4.
struct CellLink {
  unsigned leaving = 4, entering = 4;
};
constexpr std::array<std::array<CellLink, 2>, 16> cell_links() {
  std::array<std::array<CellLink, 2>, 16> links{};
  for (unsigned corners = 0; corners < 16; ++corners) {
    auto opaque = [&](unsigned k) { return (corners >> (k % 4) & 1u) != 0; };
    unsigned count = 0;
    for (unsigned k = 0; k < 4; ++k) {
      if (!(opaque(k) && !opaque(k + 1))) continue;
      for (unsigned step = 1; step < 4; ++step) {
        const unsigned e = (k + step) % 4;
        if (!opaque(e) && opaque(e + 1)) {
          links[corners][count].leaving = k;
          links[corners][count].entering = e;
          ++count;
          break;
        }
      }
    }
  }
  return links;
}
constexpr std::array<std::array<CellLink, 2>, 16> kCellLinks = cell_links();

// Marches cell rows [first_row, end_row) (cell row y has pixel rows y and y + 1 at its corners).
MarchedBand march_band(const AlphaImage& image, int threshold, int first_row, int end_row) {
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

  MarchedBand band;
  std::vector<Vec2>& points = band.points;
  std::vector<int>& next = band.next;
  // Point ids on the horizontal edges of pixel rows y and y+1 (indexed by the left pixel's x+1)
  // and on the vertical edges of the current cell row (indexed by the pixel's x+1). An id is
  // current only if made since the row that owns the array began (ids only grow), so the
  // arrays are never cleared. The band's top row's points are the band above's: all current.
  std::vector<int> top(width + 2, -1), bottom(width + 2, -1), vertical(width + 3, -1);
  int top_first = 0, row_first = 0;  // the first ids made in cell rows y-1 and y
  if (first_row > -1) {
    for (int i = 0; i < width + 2; ++i) top[i] = -(i + 1);
    top_first = std::numeric_limits<int>::min();
  }
  auto crossing = [&](int x0, int y0, int x1, int y1) {
    double v0 = value(x0, y0), v1 = value(x1, y1);
    double t = (level - v0) / (v1 - v0);
    Vec2 a{x0 + 0.5, y0 + 0.5}, b{x1 + 0.5, y1 + 0.5};
    points.push_back(a + t * (b - a));
    next.push_back(kUnlinked);
    return static_cast<int>(points.size()) - 1;
  };

  // A cell's corners c0..c3 (see march) as bits 0..3 of its case. Each edge e_k leaving the
  // opaque side (c_k opaque, c_k+1 not) is joined to the first edge after it entering that side.
  auto cell = [&](int x, int y, unsigned corners) {
    auto point_on = [&](unsigned k) {
      switch (k) {
        case 0:
          if (top[x + 1] < top_first) top[x + 1] = crossing(x, y, x + 1, y);
          return top[x + 1];
        case 1:
          if (vertical[x + 2] < row_first) vertical[x + 2] = crossing(x + 1, y, x + 1, y + 1);
          return vertical[x + 2];
        case 2:
          if (bottom[x + 1] < row_first) bottom[x + 1] = crossing(x, y + 1, x + 1, y + 1);
          return bottom[x + 1];
        default:
          if (vertical[x + 1] < row_first) vertical[x + 1] = crossing(x, y, x, y + 1);
          return vertical[x + 1];
      }
    };
    for (const CellLink& link : kCellLinks[corners]) {
      if (link.leaving > 3) break;
      // The entering edge's point is made first (the order the points are numbered in).
      const int to = point_on(link.entering);
      const int from = point_on(link.leaving);
      if (from >= 0) {
        next[from] = to;
      } else {
        band.next_of_above.emplace_back(from, to);
      }
    }
  };

  bool upper_any = load_flags(first_row, upper);
  for (int y = first_row; y < end_row; ++y) {
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
        const unsigned corners = unsigned(upper[i]) | unsigned(upper[i + 1]) << 1 |
                                 unsigned(lower[i + 1]) << 2 | unsigned(lower[i]) << 3;
        if (corners != 0 && corners != 15) cell(i - 1, y, corners);
      }
    }
    std::swap(top, bottom);
    std::swap(upper, lower);
    upper_any = lower_any;
    top_first = row_first;
  }
  band.bottom = std::move(top);  // swapped in after the last row
  return band;
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
// two rows' opaque flags), and the real work only in the cells the outline crosses. A large
// image is marched in bands of rows on up to `threads` threads, whose points are then numbered
// on as one march would number them: the rings are the same whatever the count.
std::vector<Ring> march(const AlphaImage& image, int threshold, unsigned threads) {
  const int rows = image.height + 1;  // cell rows -1 .. height-1
  const int band_total = band_count(
      rows, threads, static_cast<std::size_t>(image.width) * image.height >= kPixelsWorthAThread);
  std::vector<MarchedBand> bands(band_total);
  parallel_for_bands(rows, band_total, [&](std::size_t b, int first, int end) {
    bands[b] = march_band(image, threshold, first - 1, end - 1);
  });

  // Points are numbered on across the bands, as one march numbers them. Each band's points stay
  // in the band (copying them into one array cost as much as marching on two threads): a
  // global id is found in its band by the offsets.
  std::vector<std::size_t> offsets(band_total + 1, 0);
  for (int b = 0; b < band_total; ++b) offsets[b + 1] = offsets[b] + bands[b].points.size();
  const std::size_t total = offsets.back();
  std::vector<int> next;
  if (band_total == 1) {
    next = std::move(bands[0].next);
  } else {
    next.resize(total);
    parallel_for(bands.size(), band_total, [&](std::size_t b, unsigned) {
      const int own = static_cast<int>(offsets[b]);
      const int above = b > 0 ? static_cast<int>(offsets[b - 1]) : 0;
      const std::vector<int>& bottom_above = b > 0 ? bands[b - 1].bottom : bands[b].bottom;
      int* out = next.data() + own;
      // A point above is one of the band above's bottom row.
      for (int id : bands[b].next) {
        *out++ = id == kUnlinked ? kUnlinked : id >= 0 ? own + id : above + bottom_above[-id - 1];
      }
    });
    // A band's last points are linked by the band below.
    for (int b = 1; b < band_total; ++b) {
      const int own = static_cast<int>(offsets[b]), above = static_cast<int>(offsets[b - 1]);
      auto global = [&](int id) {
        return id >= 0 ? own + id : above + bands[b - 1].bottom[-id - 1];
      };
      for (auto [from, to] : bands[b].next_of_above) next[global(from)] = global(to);
    }
  }
  auto point_at = [&](std::size_t id) {
    const std::size_t b =
        std::upper_bound(offsets.begin(), offsets.end(), id) - offsets.begin() - 1;
    return bands[b].points[id - offsets[b]];
  };

  // A ring is numbered by its first point, as one walk over the points in order would find it.
  // Each band walks the rings that lie in it on its own thread; a ring that crosses into another
  // band is marked and walked whole afterwards.
  constexpr char kUnseen = 0, kWalking = 2, kCrossing = 3, kTaken = 1;
  std::vector<char> state(total, kUnseen);
  std::vector<std::vector<std::pair<std::size_t, Ring>>> found(band_total);
  // Where each band's walks of crossing rings began: a crossing ring's first point is one.
  std::vector<std::vector<std::size_t>> crossing_starts(band_total);
  auto take = [&](std::size_t start, auto&& point_of) {
    std::size_t length = 0;
    for (std::size_t p = start; state[p] == kWalking; p = static_cast<std::size_t>(next[p])) {
      state[p] = kTaken, ++length;
    }
    Ring ring;
    ring.reserve(length);
    for (std::size_t p = start, k = 0; k < length; p = static_cast<std::size_t>(next[p]), ++k) {
      ring.push_back(point_of(p));
    }
    return ring;
  };
  parallel_for(bands.size(), band_total, [&](std::size_t b, unsigned) {
    const std::size_t own = offsets[b], end = offsets[b + 1];
    const std::vector<Vec2>& points = bands[b].points;
    for (std::size_t start = own; start < end; ++start) {
      if (state[start] != kUnseen) continue;
      std::size_t p = start;
      while (p >= own && p < end && state[p] == kUnseen) {
        state[p] = kWalking;
        p = static_cast<std::size_t>(next[p]);
      }
      if (p == start) {
        found[b].emplace_back(start, take(start, [&](std::size_t q) { return points[q - own]; }));
      } else {
        crossing_starts[b].push_back(start);
        for (p = start; p >= own && p < end && state[p] == kWalking;) {
          state[p] = kCrossing;
          p = static_cast<std::size_t>(next[p]);
        }
      }
    }
  });
  std::vector<std::pair<std::size_t, Ring>> crossing;
  for (const std::vector<std::size_t>& starts : crossing_starts) {
    for (std::size_t start : starts) {
      if (state[start] != kCrossing) continue;
      for (std::size_t p = start; state[p] == kCrossing; p = static_cast<std::size_t>(next[p])) {
        state[p] = kWalking;
      }
      crossing.emplace_back(start, take(start, point_at));
    }
  }
  std::size_t ring_count = crossing.size();
  for (const auto& band_rings : found) ring_count += band_rings.size();
  std::vector<std::pair<std::size_t, Ring>> numbered;
  numbered.reserve(ring_count);
  for (auto& band_rings : found)
    std::move(band_rings.begin(), band_rings.end(), std::back_inserter(numbered));
  std::move(crossing.begin(), crossing.end(), std::back_inserter(numbered));
  std::inplace_merge(numbered.begin(), numbered.begin() + (ring_count - crossing.size()),
                     numbered.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Ring> rings;
  rings.reserve(ring_count);
  for (auto& [first, ring] : numbered) rings.push_back(std::move(ring));
  return rings;
}

bool before(const Vec2& a, const Vec2& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }

}  // namespace

std::vector<Region> simplify_regions(const std::vector<Region>& regions, double eps,
                                     unsigned threads, const std::function<bool(Vec2)>& pinned) {
  std::vector<Ring> rings;
  for (const Region& region : regions) {
    rings.push_back(region.outer);
    rings.insert(rings.end(), region.holes.begin(), region.holes.end());
  }
  std::vector<Ring> simplified =
      simplify_rings(rings, nesting_parents(rings, threads), std::max(0.0, eps), threads, pinned);
  std::vector<Region> out(regions.size());
  std::size_t next = 0;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    out[r].outer = std::move(simplified[next++]);
    for (std::size_t h = 0; h < regions[r].holes.size(); ++h) {
      out[r].holes.push_back(std::move(simplified[next++]));
    }
    std::rotate(out[r].outer.begin(),
                std::min_element(out[r].outer.begin(), out[r].outer.end(), before),
                out[r].outer.end());
    for (Ring& hole : out[r].holes) {
      std::rotate(hole.begin(), std::min_element(hole.begin(), hole.end(), before), hole.end());
    }
  }
  return out;
}

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

  std::vector<Ring> rings = march(image, threshold, settings.threads);
  if (rings.empty()) {
    // With a colour key, the alpha traced is 0 at the key and the image's own elsewhere. An
    // image of faint pixels is not transparent: its most opaque pixel says what --alpha traces it.
    const int most =
        image.alpha.empty() ? 0 : *std::max_element(image.alpha.begin(), image.alpha.end());
    result.warnings.push_back(
        settings.color_key
            ? "fully transparent (every pixel is the colour key, or has alpha below " +
                  std::to_string(threshold) + "): no region traced"
        : most == 0
            ? "fully transparent (no pixel with alpha >= " + std::to_string(threshold) +
                  "): no region traced"
            : "no pixel reaches --alpha " + std::to_string(threshold) +
                  " (the most opaque has alpha " + std::to_string(most) + "): no region traced");
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
      settings.keep_collinear && !(settings.simplify > 0)
          ? kept_rings
          : simplify_rings(kept_rings, kept_parents, std::max(0.0, settings.simplify),
                           settings.threads);

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
    // The largest blob's area tells what --min-blob-area would keep it: a lone pixel traces to
    // half a px² (stop 53's sweep: --min-blob-area 1 still dropped a sheet of single pixels).
    double largest = 0.0;
    for (int r = 0; r < count; ++r) largest = std::max(largest, areas[r]);
    char area[32], blob[32];
    std::snprintf(area, sizeof area, "%g", settings.min_blob_area);
    std::snprintf(blob, sizeof blob, "%g", largest);
    result.warnings.push_back(std::string("every blob is smaller than --min-blob-area ") + area +
                              " px² (the largest is " + blob + " px²): no region traced");
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
