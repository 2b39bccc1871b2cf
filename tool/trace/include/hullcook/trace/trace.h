// Silhouette tracing: sprite images to polygons with holes, in pixel space.
//
// Pixel space: pixel (i, j) covers [i, i+1) × [j, j+1), so its centre is (i + 0.5, j + 0.5); x to
// the right, y down. The alpha field is sampled at pixel centres and the image is padded with a
// transparent border, so every outline closes.
//
// Outlines are marching squares on that field: a boundary point lies where the alpha field,
// interpolated linearly between two neighbouring pixel centres, crosses alpha - 0.5 (so a hard
// 0/255 edge lands exactly on the pixel border). Connectivity rule: opaque pixels are
// 8-connected and transparent pixels 4-connected, so two opaque pixels touching at a corner are
// one blob (the saddle cell is always joined on the opaque side). The regions and holes equal
// cv::connectedComponents(mask, 8) and the 4-connected components of the background.
//
// Orientation: in pixel coordinates (y down) every outer ring has a positive shoelace area
// Σ(x_i·y_{i+1} − x_{i+1}·y_i)/2 and every hole a negative one; a y flip reverses both, so a
// caller mapping to y-up re-orients (clean_and_validate() does).
//
// A fully transparent image is not an error: tracing it gives no region and a warning, so a
// sprite sheet with an empty frame still cooks (the asset is then empty).
#pragma once

#include "hullcook/core/polygon.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hullcook {

struct TraceSettings {
  int alpha = 128;  // a pixel is opaque where alpha >= this (0-255; 0 = every pixel)
  // For images without an alpha channel: pixels of exactly this RGB are transparent, all others
  // opaque. With an alpha channel, pixels of this colour become transparent as well.
  std::optional<std::array<std::uint8_t, 3>> color_key;
  double min_blob_area = 4.0;  // [px²] blobs with a smaller traced area are dropped
  double min_hole_area = 4.0;  // [px²] holes with a smaller traced area are filled
  double simplify = 0.5;       // [px] error bound of ring simplification; 0 = none
  // With simplify 0: the rings exactly as traced, collinear vertices kept (else dropped), for a
  // caller that moves vertices before it simplifies them (simplify_regions).
  bool keep_collinear = false;
  std::uint64_t max_pixels = 64ull * 1000 * 1000;  // larger images are refused before decoding
  unsigned threads = 1;  // how many may simplify rings at once; the result is the same for any
};

// An image reduced to its 8-bit alpha channel (after the colour key, if any).
struct AlphaImage {
  int width = 0;                    // [px]
  int height = 0;                   // [px]
  std::vector<std::uint8_t> alpha;  // row-major, width * height values, 0 = transparent
};

// Reads PNG (RGBA, grey + alpha, palette with tRNS, 8 or 16 bits, and without alpha), BMP, WebP
// and TGA (uncompressed or RLE). The dimensions are read from the file's header and checked
// against settings.max_pixels before anything is decoded. Throws InputError naming the file and
// the problem: unreadable, not an image, truncated, corrupt, 0×0, too large, or without alpha
// channel and without settings.color_key.
AlphaImage load_alpha(const std::filesystem::path& path, const TraceSettings& settings);

// Same as load_alpha() on bytes already in memory; name is used in error messages and the
// format is told by magic bytes (TGA, which has none, by a ".tga" name).
AlphaImage decode_alpha(const std::string& bytes, const std::string& name,
                        const TraceSettings& settings);

// An image as 8-bit RGBA, for drawing it (an image without alpha is opaque).
struct RgbaImage {
  int width = 0;                   // [px]
  int height = 0;                  // [px]
  bool has_alpha = false;          // the file has an alpha channel (or PNG/BMP/TGA equivalent)
  std::vector<std::uint8_t> rgba;  // row-major, width * height * 4 values
};

// Reads any image load_alpha() reads, as RGBA. Throws InputError as load_alpha() does (but for
// the missing alpha channel, which is no error here).
RgbaImage load_rgba(const std::filesystem::path& path, std::uint64_t max_pixels);

struct TraceResult {
  int width = 0;   // [px]
  int height = 0;  // [px]
  // [px] y down, one per blob with its holes, oriented as described above. Every ring is simple
  // with at least 3 vertices and no repeated or collinear vertex; no two rings (of any regions)
  // intersect or touch; holes lie inside their outer ring; a blob inside a hole is its own region.
  // Every traced boundary point lies within settings.simplify of the rings.
  // Regions are sorted by their outer ring's first vertex (top to bottom, left to right).
  std::vector<Region> regions;
  std::size_t traced_vertices = 0;  // boundary points of the kept rings before simplification
  double decode_ms = 0.0;           // [ms] reading and decoding the file (0 for trace_alpha)
  double trace_ms = 0.0;            // [ms] marching squares, assembly and simplification
  std::vector<std::string> warnings;
};

// Traces an alpha image. Throws InputError if the image's size and data do not agree.
TraceResult trace_alpha(const AlphaImage& image, const TraceSettings& settings);

// Simplifies regions that trace_alpha gave with settings.simplify 0 and that were moved since
// (a tile's outline points put onto its cell's border: see --tile), as trace_alpha simplifies:
// with error bound eps [px], each ring keeping a subset of its vertices, its orientation and at
// least 3 vertices, the rings simple, disjoint and nested as before, collinear vertices dropped.
// The regions and their holes keep their order; each ring starts at its top-left vertex.
// pinned, when given, names vertices kept whatever eps (but for one straight between its
// neighbours). threads: how many may simplify rings at once; the result is the same for any.
std::vector<Region> simplify_regions(const std::vector<Region>& regions, double eps,
                                     unsigned threads = 1,
                                     const std::function<bool(Vec2)>& pinned = {});

// load_alpha() then trace_alpha(); warnings name the file.
TraceResult trace_image(const std::filesystem::path& path, const TraceSettings& settings);

// True for the image extensions the tracer reads (.png .tga .bmp .webp), case-insensitively.
bool is_image_file(const std::filesystem::path& path);

}  // namespace hullcook
